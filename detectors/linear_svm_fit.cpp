#include "detectors/linear_svm_fit.h"

#include <linear.h>

#include <memory>
#include <stdexcept>

#include "detectors/library_fit.h"
#include "sim/base/errors.h"
#include "sim/base/number_text.h"

namespace tactip {

/// Frees a liblinear model.
struct HingeModelFree {
  void operator()(::model* m) const { ::free_and_destroy_model(&m); }
};
using HingeModelPtr = std::unique_ptr<::model, HingeModelFree>;

namespace {

/// Bias feature appended to every row.
constexpr double kHingeBias = 1.0;
/// The primal solver's stopping tolerance (liblinear's default for it).
constexpr double kHingeEps = 0.01;

struct HingeRows : NodeRows<feature_node> {
  explicit HingeRows(const Eigen::MatrixXf& x) : NodeRows<feature_node>(x, kHingeBias) {}
};

/// One L2-regularised squared-hinge-loss SVM on `rows`, by liblinear's primal trust-region
/// Newton solver: deterministic (its dual solvers draw from rand(), which the folds' threads share).
HingeModelPtr TrainOne(HingeRows& rows, std::vector<double>& y, int dim, double c) {
  ::problem prob{};
  prob.l = static_cast<int>(y.size());
  prob.n = dim + 1;
  prob.y = y.data();
  prob.x = rows.rows.data();
  prob.bias = kHingeBias;
  ::parameter param{};
  param.solver_type = L2R_L2LOSS_SVC;
  param.eps = kHingeEps;
  param.C = c;
  param.p = 0.1;
  if (const char* err = ::check_parameter(&prob, &param)) {
    throw InputError(std::string("liblinear rejected the parameters: ") + err);
  }
  return HingeModelPtr(::train(&prob, &param));
}

/// The fit as libsvm's text of a linear C-SVC: f(x) = w.x - rho, label[0] where f > 0.
std::string AsLibsvmText(const ::model* m, int dim) {
  if (m->nr_class != 2) throw std::logic_error("linear SVM: the training set has one class only");
  std::string text = "svm_type c_svc\nkernel_type linear\nnr_class 2\ntotal_sv 1\n";
  text += "rho " + RoundTripText(-m->w[dim] * kHingeBias) + "\n";
  text += "label " + std::to_string(m->label[0]) + " " + std::to_string(m->label[1]) + "\n";
  text += "nr_sv 1 0\nSV\n1";
  for (int j = 0; j < dim; ++j) text += " " + std::to_string(j + 1) + ":" + RoundTripText(m->w[j]);
  return text + "\n";
}

}  // namespace

LinearSvmFit FitLinearSvm(const TrainingSet& ts, const std::vector<CvCandidate>& grid, int folds,
                          const std::function<void(const std::string&)>& progress) {
  ::set_print_string_function([](const char*) {});
  const int dim = static_cast<int>(ts.x.cols());
  const auto train = [dim](HingeRows& rows, std::vector<double>& y, const CvCandidate& candidate) {
    return TrainOne(rows, y, dim, candidate.c);
  };
  const auto predict = [](const ::model* m, const feature_node* row) { return ::predict(m, row); };
  LinearSvmFit fit;
  fit.report = GroupedGridSearch(ts, folds, grid, FitAndPredictEachCandidate<HingeRows>(train, predict), progress);
  auto [standardizer, text] = RefitOnEveryRow<HingeRows>(ts, {fit.report.best_c, 0.0}, train,
                                                         [dim](const ::model* m) { return AsLibsvmText(m, dim); });
  fit.standardizer = std::move(standardizer);
  fit.libsvm_text = std::move(text);
  return fit;
}

}  // namespace tactip
