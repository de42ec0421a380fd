// SVM slip detectors: grouped-CV training (the Gaussian kernel with libsvm, the linear one with
// liblinear: detectors/linear_svm_fit.h), an allocation-free dense decision
// function for streaming, and a text model that embeds libsvm's own model format.

#include "detectors/svm.h"

#include <svm.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "detectors/library_fit.h"
#include "detectors/linear_svm_fit.h"
#include "detectors/model_text.h"
#include "detectors/text_io.h"
#include "sim/base/files.h"
#include "sim/base/number_text.h"
#include "sim/base/temp_file.h"

namespace tactip {

/// Frees a libsvm model (whether from svm_train or svm_load_model). Outside the
/// anonymous namespace: the detector's Impl holds one.
struct SvmModelFree {
  void operator()(svm_model* m) const { svm_free_and_destroy_model(&m); }
};
using SvmModelPtr = std::unique_ptr<svm_model, SvmModelFree>;

namespace {

/// libsvm reads and writes model files through process-wide state (a static line buffer,
/// and setlocale around the text): one model file at a time in the whole process.
std::mutex& LibsvmFileMutex() {
  static std::mutex m;
  return m;
}

/// Routes libsvm's progress printing into a no-op (the hook is libsvm's own global).
void SilenceLibsvm() { svm_set_print_string_function([](const char*) {}); }

/// "svm-linear" / "svm-rbf".
const char* KindName(SvmDetector::Kernel k) { return k == SvmDetector::Kernel::kRbf ? "svm-rbf" : "svm-linear"; }

/// Dense rows as libsvm nodes (no bias node).
using SvmRows = NodeRows<svm_node>;

/// C-SVC parameters: no class weights, no probability model, shrinking on.
svm_parameter MakeParameter(SvmDetector::Kernel kernel, double c, double gamma) {
  svm_parameter p{};
  p.svm_type = C_SVC;
  p.kernel_type = kernel == SvmDetector::Kernel::kRbf ? RBF : LINEAR;
  p.degree = 3;
  p.gamma = kernel == SvmDetector::Kernel::kRbf ? gamma : 0.0;
  p.coef0 = 0.0;
  p.cache_size = 200.0;
  p.eps = 1e-3;
  p.C = c;
  p.nr_weight = 0;
  p.weight_label = nullptr;
  p.weight = nullptr;
  p.nu = 0.5;
  p.p = 0.1;
  p.shrinking = 1;
  p.probability = 0;
  return p;
}

/// Trains one C-SVC on `rows` (which must outlive the returned model).
SvmModelPtr TrainOne(SvmRows& rows, std::vector<double>& y, const svm_parameter& param) {
  svm_problem prob{};
  prob.l = static_cast<int>(y.size());
  prob.y = y.data();
  prob.x = rows.rows.data();
  if (const char* err = svm_check_parameter(&prob, &param)) {
    throw InputError(std::string("libsvm rejected the parameters: ") + err);
  }
  return SvmModelPtr(svm_train(&prob, &param));
}

/// libsvm's text for `model` (libsvm 3.24 writes models only to files).
std::string ModelText(const svm_model* model) {
  const TempFile tmp;
  {
    const std::lock_guard lock(LibsvmFileMutex());
    if (svm_save_model(tmp.path().c_str(), model) != 0) {
      throw InputError("cannot write the libsvm model to '" + tmp.path() + "'");
    }
  }
  return ReadText(tmp.path());
}

/// Parses one "coef idx:val idx:val ..." SV line strictly (indices increasing in 1..dim).
bool ParseSvLine(const std::string& line, int dim, std::string& problem) {
  const char* p = line.data();
  const char* end = p + line.size();
  auto skip_space = [&] {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
  };
  // Coefficient.
  skip_space();
  double coef = 0.0;
  auto res = std::from_chars(p, end, coef);
  if (res.ec != std::errc() || !std::isfinite(coef) || (res.ptr < end && *res.ptr != ' ' && *res.ptr != '\t')) {
    problem = "support vector line does not start with a coefficient";
    return false;
  }
  p = res.ptr;
  // index:value pairs.
  int last = 0;
  for (skip_space(); p < end; skip_space()) {
    int idx = 0;
    res = std::from_chars(p, end, idx);
    if (res.ec != std::errc() || res.ptr >= end || *res.ptr != ':') {
      problem = "support vector entry is not 'index:value'";
      return false;
    }
    if (idx <= last || idx > dim) {
      problem = "support vector index " + std::to_string(idx) + " out of order or outside 1.." + std::to_string(dim);
      return false;
    }
    last = idx;
    double v = 0.0;
    res = std::from_chars(res.ptr + 1, end, v);
    if (res.ec != std::errc() || !std::isfinite(v) || (res.ptr < end && *res.ptr != ' ' && *res.ptr != '\t')) {
      problem = "support vector value is not a finite number";
      return false;
    }
    p = res.ptr;
  }
  return true;
}

/// Checks that `text` is exactly what libsvm writes for a two-class (0/1) C-SVC with the
/// given kernel, gamma and dimension, so svm_load_model never sees malformed input.
void ValidateLibsvmText(const std::string& text, const std::string& path, int line_offset, SvmDetector::Kernel kernel,
                        double gamma, int dim) {
  ModelTextReader r(text, path, line_offset);
  r.ExpectExact("svm_type c_svc");
  r.ExpectExact(kernel == SvmDetector::Kernel::kRbf ? "kernel_type rbf" : "kernel_type linear");
  if (kernel == SvmDetector::Kernel::kRbf) {
    const double g = r.ParseDouble(r.ExpectKey("gamma", 1)[0], "libsvm gamma");
    if (g != gamma) r.Fail("libsvm gamma " + RoundTripText(g) + " differs from gamma " + RoundTripText(gamma));
  }
  r.ExpectExact("nr_class 2");
  const int total = r.ParseInt(r.ExpectKey("total_sv", 1)[0], "total_sv");
  if (total < 1) r.Fail("total_sv must be >= 1");
  r.ParseDouble(r.ExpectKey("rho", 1)[0], "rho");
  const std::vector<std::string> label = r.ExpectKey("label", 2);
  if (!((label[0] == "0" && label[1] == "1") || (label[0] == "1" && label[1] == "0"))) {
    r.Fail("labels must be 0 and 1");
  }
  const std::vector<std::string> nsv = r.ExpectKey("nr_sv", 2);
  const int n0 = r.ParseInt(nsv[0], "nr_sv"), n1 = r.ParseInt(nsv[1], "nr_sv");
  // n1 == total - n0 rather than n0 + n1 == total: the sum of two ints can overflow.
  if (n0 < 0 || n1 < 0 || n0 > total || n1 != total - n0) {
    r.Fail("nr_sv " + nsv[0] + " " + nsv[1] + " does not add up to total_sv " + std::to_string(total));
  }
  r.ExpectExact("SV");
  std::string problem;
  for (int i = 0; i < total; ++i) {
    const std::string line = r.ReadLine("support vector " + std::to_string(i + 1) + " of " + std::to_string(total));
    if (!ParseSvLine(line, dim, problem)) r.Fail(problem);
  }
  r.ExpectEndOfFile("support vector");
}

}  // namespace

/// Everything a trained SVM detector holds; per-frame buffers are sized once.
struct SvmDetector::Impl {
  Kernel kernel = Kernel::kRbf;
  FeatureSet features = FeatureSet::kDrDtheta;
  double c = 1.0;
  double gamma = 0.0;
  int dim = 0;
  Standardizer standardizer;
  std::string libsvm_text;  ///< the model as libsvm writes it (saved verbatim)
  SvmModelPtr model;        ///< loaded from libsvm_text (owns its support vectors)
  CvReport cv;

  // Dense copy of libsvm's decision function f(x) = sum_i coef_i K(sv_i, x) - rho.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> sv;  ///< nSV x dim
  Eigen::VectorXd coef;   ///< nSV
  Eigen::VectorXd w;      ///< linear kernel: sum_i coef_i sv_i
  double rho = 0.0;
  int first_label = 0;    ///< libsvm's label[0]: f > 0 predicts it

  // Streaming state and scratch.
  VelocityFeatures feat;
  Eigen::VectorXf x;
  Eigen::VectorXd xd;
  Eigen::VectorXd k;

  /// Decision value f for a standardised feature vector in xd.
  double DecisionValue() {
    if (kernel == Kernel::kLinear) return w.dot(xd) - rho;
    for (Eigen::Index i = 0; i < sv.rows(); ++i) k[i] = (sv.row(i).transpose() - xd).squaredNorm();
    k.array() = (k.array() * -gamma).exp();
    return coef.dot(k) - rho;
  }
};

// Builds the detector state from libsvm model text: strict validation, svm_load_model through
// a temporary file, then the dense decision function, checked against svm_predict_values.
std::unique_ptr<SvmDetector::Impl> SvmDetector::MakeImpl(Kernel kernel, FeatureSet features, double c, double gamma,
                                                         Standardizer standardizer, std::string libsvm_text,
                                                         const std::string& path, int line_offset) {
  const int dim = standardizer.dim();
  ValidateLibsvmText(libsvm_text, path, line_offset, kernel, gamma, dim);
  auto m = std::make_unique<SvmDetector::Impl>();
  m->kernel = kernel;
  m->features = features;
  m->c = c;
  m->gamma = kernel == Kernel::kRbf ? gamma : 0.0;
  m->dim = dim;
  m->standardizer = std::move(standardizer);
  m->libsvm_text = std::move(libsvm_text);
  m->feat = VelocityFeatures(features);

  // Let libsvm read its model from a temporary file.
  {
    const TempFile tmp;
    tmp.Write(m->libsvm_text, "model '" + path + "'");
    SilenceLibsvm();
    const std::lock_guard lock(LibsvmFileMutex());
    m->model.reset(svm_load_model(tmp.path().c_str()));
  }
  if (!m->model) throw InputError("model '" + path + "': libsvm could not read the embedded model");
  const svm_model& sm = *m->model;

  // Dense copies of the support vectors, coefficients and offset.
  const int l = sm.l;
  m->sv.setZero(l, dim);
  m->coef.resize(l);
  for (int i = 0; i < l; ++i) {
    for (const svm_node* p = sm.SV[i]; p->index != -1; ++p) m->sv(i, p->index - 1) = p->value;
    m->coef[i] = sm.sv_coef[0][i];
  }
  m->rho = sm.rho[0];
  m->first_label = sm.label[0];
  m->w = m->sv.transpose() * m->coef;
  m->x.resize(dim);
  m->xd.resize(dim);
  m->k.resize(l);

  // The dense function must agree with libsvm's own on a few support vectors.
  const double scale = kernel == Kernel::kRbf ? 1.0 : m->sv.rowwise().squaredNorm().maxCoeff();
  const double tol = 1e-9 * (1.0 + std::abs(m->rho) + m->coef.cwiseAbs().sum() * scale);
  std::vector<svm_node> nodes(static_cast<size_t>(dim) + 1);
  for (int i : {0, l / 2, l - 1}) {
    for (int j = 0; j < dim; ++j) nodes[static_cast<size_t>(j)] = svm_node{j + 1, m->sv(i, j)};
    nodes[static_cast<size_t>(dim)] = svm_node{-1, 0.0};
    double ref = 0.0;
    svm_predict_values(m->model.get(), nodes.data(), &ref);
    m->xd = m->sv.row(i).transpose();
    const double mine = m->DecisionValue();
    if (!(std::abs(mine - ref) <= tol)) {
      throw std::logic_error("model '" + path + "': dense SVM decision " + RoundTripText(mine) +
                             " disagrees with libsvm's " + RoundTripText(ref));
    }
  }
  return m;
}

SvmDetector::SvmDetector(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SvmDetector::~SvmDetector() = default;

std::string SvmDetector::name() const { return KindName(impl_->kernel); }
void SvmDetector::Reset() { impl_->feat.Reset(); }
SvmDetector::Kernel SvmDetector::kernel() const { return impl_->kernel; }
FeatureSet SvmDetector::features() const { return impl_->features; }
double SvmDetector::c() const { return impl_->c; }
double SvmDetector::gamma() const { return impl_->gamma; }
int SvmDetector::dim() const { return impl_->dim; }
int SvmDetector::n_support_vectors() const { return impl_->model->l; }
const Standardizer& SvmDetector::standardizer() const { return impl_->standardizer; }
const CvReport& SvmDetector::cv_report() const { return impl_->cv; }

Decision SvmDetector::Update(const PinFrame& frame) {
  Impl& m = *impl_;
  Decision d;
  // Features (none for the first frame), checked against the model's dimension.
  if (!m.feat.Update(frame, m.x)) return d;
  if (m.x.size() != m.dim) {
    throw InputError("frame at t = " + std::to_string(frame.time_s) + " s gives " +
                     std::to_string(m.x.size()) + " features; the " + name() + " model expects " +
                     std::to_string(m.dim));
  }
  // Standardise and evaluate; libsvm predicts label[0] when f > 0.
  m.standardizer.Apply(m.x);
  m.xd = m.x.cast<double>();
  const double f = m.DecisionValue();
  const int label = f > 0.0 ? m.first_label : 1 - m.first_label;
  d.slip = label == 1;
  d.score = m.first_label == 1 ? f : -f;
  return d;
}

void SvmDetector::Save(const std::string& path) const {
  const Impl& m = *impl_;
  std::string text = std::string("tactip-detector ") + KindName(m.kernel) + " 1\n";
  text += "features " + ToString(m.features) + "\n";
  text += "C " + RoundTripText(m.c) + "\n";
  text += "gamma " + RoundTripText(m.gamma) + "\n";
  text += "dim " + std::to_string(m.dim) + "\n";
  AppendStandardizer(m.standardizer, text);
  text += "libsvm-model\n";
  text += m.libsvm_text;
  WriteFileAtomic(path, text);
}

std::unique_ptr<SvmDetector> SvmDetector::Load(const std::string& path) { return FromText(ReadText(path), path); }

std::unique_ptr<SvmDetector> SvmDetector::FromText(const std::string& text, const std::string& path) {
  ModelTextReader r(text, path);
  // Header: kind and version.
  const std::vector<std::string> head = r.ExpectKey("tactip-detector", 2);
  Kernel kernel = Kernel::kRbf;
  if (head[0] == "svm-rbf") {
    kernel = Kernel::kRbf;
  } else if (head[0] == "svm-linear") {
    kernel = Kernel::kLinear;
  } else {
    r.Fail("detector kind '" + head[0] + "' is not svm-rbf or svm-linear");
  }
  if (head[1] != "1") r.Fail("unsupported model version '" + head[1] + "' (this build reads 1)");
  // Parameters.
  const FeatureSet features = r.ReadFeatures();
  const double c = r.ReadC();
  const double gamma = r.ParseDouble(r.ExpectKey("gamma", 1)[0], "gamma");
  if (kernel == Kernel::kRbf ? !(gamma > 0.0) : gamma < 0.0) r.Fail("gamma out of range");
  const int dim = r.ReadDim();
  Standardizer standardizer = r.ReadStandardizer(dim);
  // The embedded libsvm model.
  r.ExpectExact("libsvm-model");
  auto impl = MakeImpl(kernel, features, c, gamma, std::move(standardizer), r.Rest(), path, r.line_number());
  impl->cv.best_c = c;
  impl->cv.best_gamma = impl->gamma;
  impl->cv.best_f1 = std::numeric_limits<double>::quiet_NaN();
  return std::unique_ptr<SvmDetector>(new SvmDetector(std::move(impl)));
}

std::unique_ptr<SvmDetector> SvmDetector::Train(const TrainingSet& ts, Kernel kernel, const TrainOptions& opts) {
  // Check the data and the search grid.
  CheckTrainingSet(ts);
  CheckPositiveGrid(opts.c_grid, "c_grid");
  const int dim = static_cast<int>(ts.x.cols());
  std::vector<CvCandidate> grid;
  if (kernel == Kernel::kRbf) {
    CheckPositiveGrid(opts.gamma_scale_grid, "gamma_scale_grid");
    for (double c : opts.c_grid) {
      for (double g : opts.gamma_scale_grid) grid.push_back({c, g / dim});
    }
  } else {
    for (double c : opts.c_grid) grid.push_back({c, 0.0});
    // The linear kernel: liblinear's hinge-loss solver, written as a libsvm linear model.
    LinearSvmFit fit = FitLinearSvm(ts, grid, opts.cv_folds, opts.progress);
    auto impl = MakeImpl(kernel, opts.features, fit.report.best_c, 0.0, std::move(fit.standardizer),
                         std::move(fit.libsvm_text), "(trained svm-linear)", 0);
    impl->cv = fit.report;
    return std::unique_ptr<SvmDetector>(new SvmDetector(std::move(impl)));
  }
  SilenceLibsvm();

  // Grouped CV: one libsvm problem per fold, one model per candidate; then the refit on every
  // row with the best parameters, round-tripped through libsvm's text.
  const auto train = [kernel](SvmRows& rows, std::vector<double>& y, const CvCandidate& candidate) {
    return TrainOne(rows, y, MakeParameter(kernel, candidate.c, candidate.gamma));
  };
  const auto predict = [](const svm_model* m, const svm_node* row) { return svm_predict(m, row); };
  const CvReport report =
      GroupedGridSearch(ts, opts.cv_folds, grid, FitAndPredictEachCandidate<SvmRows>(train, predict), opts.progress);
  auto [standardizer, text] = RefitOnEveryRow<SvmRows>(ts, {report.best_c, report.best_gamma}, train,
                                                       [](const svm_model* m) { return ModelText(m); });
  auto impl = MakeImpl(kernel, opts.features, report.best_c, report.best_gamma, std::move(standardizer),
                       std::move(text), "(trained " + std::string(KindName(kernel)) + ")", 0);
  impl->cv = report;
  return std::unique_ptr<SvmDetector>(new SvmDetector(std::move(impl)));
}

}  // namespace tactip
