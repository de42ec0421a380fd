// Logistic-regression slip detector: grouped-CV training with liblinear, streaming decisions
// through liblinear's predict_values, and a text model that embeds liblinear's own format.

#include "detectors/logreg.h"

#include <linear.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <utility>

#include "detectors/library_fit.h"
#include "detectors/model_text.h"
#include "detectors/text_io.h"
#include "sim/base/files.h"
#include "sim/base/number_text.h"
#include "sim/base/temp_file.h"

namespace tactip {

/// Frees a liblinear model. Outside the anonymous namespace: the detector's Impl holds one.
struct LinearModelFree {
  void operator()(::model* m) const { ::free_and_destroy_model(&m); }
};
using LinearModelPtr = std::unique_ptr<::model, LinearModelFree>;

namespace {

/// Bias feature appended to every row (liblinear's "-B 1").
constexpr double kBias = 1.0;

/// Routes liblinear's progress printing into a no-op (the hook is liblinear's own global).
void SilenceLiblinear() { ::set_print_string_function([](const char*) {}); }

/// Dense rows as liblinear nodes, with the bias node.
struct LinearRows : NodeRows<feature_node> {
  explicit LinearRows(const Eigen::MatrixXf& x) : NodeRows<feature_node>(x, kBias) {}
};

/// Trains one L2R_LR model (the returned model owns its weights).
LinearModelPtr TrainOne(LinearRows& rows, std::vector<double>& y, int dim, double c) {
  ::problem prob{};
  prob.l = static_cast<int>(y.size());
  prob.n = dim + 1;
  prob.y = y.data();
  prob.x = rows.rows.data();
  prob.bias = kBias;
  ::parameter param{};
  param.solver_type = L2R_LR;
  param.eps = 0.01;
  param.C = c;
  param.nr_weight = 0;
  param.weight_label = nullptr;
  param.weight = nullptr;
  param.p = 0.1;
  param.init_sol = nullptr;
  if (const char* err = ::check_parameter(&prob, &param)) {
    throw InputError(std::string("liblinear rejected the parameters: ") + err);
  }
  return LinearModelPtr(::train(&prob, &param));
}

/// liblinear's text for `m` (liblinear 2.3 writes models only to files).
std::string ModelText(const ::model* m) {
  const TempFile tmp;
  if (::save_model(tmp.path().c_str(), m) != 0) {
    throw InputError("cannot write the liblinear model to '" + tmp.path() + "'");
  }
  return ReadText(tmp.path());
}

/// Checks that `text` is exactly what liblinear writes for a two-class (0/1) L2R_LR model
/// with a bias term over `dim` features, so load_model never sees malformed input.
void ValidateLiblinearText(const std::string& text, const std::string& path, int line_offset, int dim) {
  ModelTextReader r(text, path, line_offset);
  r.ExpectExact("solver_type L2R_LR");
  r.ExpectExact("nr_class 2");
  const std::vector<std::string> label = r.ExpectKey("label", 2);
  if (!((label[0] == "0" && label[1] == "1") || (label[0] == "1" && label[1] == "0"))) {
    r.Fail("labels must be 0 and 1");
  }
  const int nr_feature = r.ParseInt(r.ExpectKey("nr_feature", 1)[0], "nr_feature");
  if (nr_feature != dim) r.Fail("nr_feature " + std::to_string(nr_feature) + " differs from dim " + std::to_string(dim));
  const double bias = r.ParseDouble(r.ExpectKey("bias", 1)[0], "bias");
  if (bias != kBias) r.Fail("bias must be " + RoundTripText(kBias));
  r.ExpectExact("w");
  for (int i = 0; i <= dim; ++i) {
    const std::string line = r.ReadLine("weight " + std::to_string(i + 1) + " of " + std::to_string(dim + 1));
    // One number per line (liblinear leaves a trailing space).
    const size_t b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t");
    const std::string token = b == std::string::npos ? "" : line.substr(b, e - b + 1);
    r.ParseDouble(token, "weight");
  }
  r.ExpectEndOfFile("weight");
}

}  // namespace

/// Everything a trained logistic-regression detector holds; per-frame buffers are sized once.
struct LogRegDetector::Impl {
  FeatureSet features = FeatureSet::kDrDtheta;
  double c = 1.0;
  int dim = 0;
  Standardizer standardizer;
  std::string liblinear_text;  ///< the model as liblinear writes it (saved verbatim)
  LinearModelPtr model;        ///< loaded from liblinear_text
  CvReport cv;

  // Streaming state and scratch.
  VelocityFeatures feat;
  Eigen::VectorXf x;
  std::vector<feature_node> nodes;  ///< dim values, the bias node, the terminator
};

// Builds the detector state from liblinear model text: strict validation, then load_model
// through a temporary file.
std::unique_ptr<LogRegDetector::Impl> LogRegDetector::MakeImpl(FeatureSet features, double c,
                                                               Standardizer standardizer, std::string liblinear_text,
                                                               const std::string& path, int line_offset) {
  const int dim = standardizer.dim();
  ValidateLiblinearText(liblinear_text, path, line_offset, dim);
  auto m = std::make_unique<LogRegDetector::Impl>();
  m->features = features;
  m->c = c;
  m->dim = dim;
  m->standardizer = std::move(standardizer);
  m->liblinear_text = std::move(liblinear_text);
  m->feat = VelocityFeatures(features);

  // Let liblinear read its model from a temporary file.
  {
    const TempFile tmp;
    tmp.Write(m->liblinear_text, "model '" + path + "'");
    SilenceLiblinear();
    m->model.reset(::load_model(tmp.path().c_str()));
  }
  if (!m->model) throw InputError("model '" + path + "': liblinear could not read the embedded model");

  // Per-frame node buffer with fixed indices.
  m->x.resize(dim);
  m->nodes.resize(static_cast<size_t>(dim) + 2);
  for (int j = 0; j < dim; ++j) m->nodes[static_cast<size_t>(j)] = feature_node{j + 1, 0.0};
  m->nodes[static_cast<size_t>(dim)] = feature_node{dim + 1, kBias};
  m->nodes[static_cast<size_t>(dim) + 1] = feature_node{-1, 0.0};
  return m;
}

LogRegDetector::LogRegDetector(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LogRegDetector::~LogRegDetector() = default;

void LogRegDetector::Reset() { impl_->feat.Reset(); }
FeatureSet LogRegDetector::features() const { return impl_->features; }
double LogRegDetector::c() const { return impl_->c; }
int LogRegDetector::dim() const { return impl_->dim; }
const Standardizer& LogRegDetector::standardizer() const { return impl_->standardizer; }
const CvReport& LogRegDetector::cv_report() const { return impl_->cv; }

Decision LogRegDetector::Update(const PinFrame& frame) {
  Impl& m = *impl_;
  Decision d;
  // Features (none for the first frame), checked against the model's dimension.
  if (!m.feat.Update(frame, m.x)) return d;
  if (m.x.size() != m.dim) {
    throw InputError("frame at t = " + std::to_string(frame.time_s) + " s gives " +
                     std::to_string(m.x.size()) + " features; the logreg model expects " +
                     std::to_string(m.dim));
  }
  // Standardise into the node buffer and let liblinear decide.
  m.standardizer.Apply(m.x);
  for (int j = 0; j < m.dim; ++j) m.nodes[static_cast<size_t>(j)].value = static_cast<double>(m.x[j]);
  double f = 0.0;
  const double label = ::predict_values(m.model.get(), m.nodes.data(), &f);
  d.slip = label == 1.0;
  d.score = m.model->label[0] == 1 ? f : -f;
  return d;
}

void LogRegDetector::Save(const std::string& path) const {
  const Impl& m = *impl_;
  std::string text = "tactip-detector logreg 1\n";
  text += "features " + ToString(m.features) + "\n";
  text += "C " + RoundTripText(m.c) + "\n";
  text += "dim " + std::to_string(m.dim) + "\n";
  AppendStandardizer(m.standardizer, text);
  text += "liblinear-model\n";
  text += m.liblinear_text;
  WriteFileAtomic(path, text);
}

std::unique_ptr<LogRegDetector> LogRegDetector::Load(const std::string& path) {
  return FromText(ReadText(path), path);
}

std::unique_ptr<LogRegDetector> LogRegDetector::FromText(const std::string& text, const std::string& path) {
  ModelTextReader r(text, path);
  // Header: kind and version.
  const std::vector<std::string> head = r.ExpectKey("tactip-detector", 2);
  if (head[0] != "logreg") r.Fail("detector kind '" + head[0] + "' is not logreg");
  if (head[1] != "1") r.Fail("unsupported model version '" + head[1] + "' (this build reads 1)");
  // Parameters.
  const FeatureSet features = r.ReadFeatures();
  const double c = r.ReadC();
  const int dim = r.ReadDim();
  Standardizer standardizer = r.ReadStandardizer(dim);
  // The embedded liblinear model.
  r.ExpectExact("liblinear-model");
  auto impl = MakeImpl(features, c, std::move(standardizer), r.Rest(), path, r.line_number());
  impl->cv.best_c = c;
  impl->cv.best_f1 = std::numeric_limits<double>::quiet_NaN();
  return std::unique_ptr<LogRegDetector>(new LogRegDetector(std::move(impl)));
}

std::unique_ptr<LogRegDetector> LogRegDetector::Train(const TrainingSet& ts, const TrainOptions& opts) {
  // Check the data and the search grid.
  CheckTrainingSet(ts);
  CheckPositiveGrid(opts.c_grid, "c_grid");
  const int dim = static_cast<int>(ts.x.cols());
  std::vector<CvCandidate> grid;
  for (double c : opts.c_grid) grid.push_back({c, 0.0});
  SilenceLiblinear();

  // Grouped CV: one liblinear problem per fold, one model per candidate; then the refit on
  // every row with the best C, round-tripped through liblinear's text.
  const auto train = [dim](LinearRows& rows, std::vector<double>& y, const CvCandidate& candidate) {
    return TrainOne(rows, y, dim, candidate.c);
  };
  const auto predict = [](const ::model* m, const feature_node* row) { return ::predict(m, row); };
  const CvReport report =
      GroupedGridSearch(ts, opts.cv_folds, grid, FitAndPredictEachCandidate<LinearRows>(train, predict), opts.progress);
  auto [standardizer, text] =
      RefitOnEveryRow<LinearRows>(ts, {report.best_c, 0.0}, train, [](const ::model* m) { return ModelText(m); });
  auto impl = MakeImpl(opts.features, report.best_c, std::move(standardizer), std::move(text), "(trained logreg)", 0);
  impl->cv = report;
  return std::unique_ptr<LogRegDetector>(new LogRegDetector(std::move(impl)));
}

}  // namespace tactip
