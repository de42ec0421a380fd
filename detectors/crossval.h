#pragma once
// Grouped cross-validation of the trained detectors (SVM, logistic regression): folds by
// run, F1, feature standardisation, the hyperparameter search and the checks of its inputs.

#include <functional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include <Eigen/Core>

#include "detectors/detector.h"

namespace tactip {

/// Assigns every row to one of k folds by its group (run): the distinct groups, sorted
/// ascending, go round-robin to folds 0, 1, ..., k-1, so all frames of one run share a fold.
/// Deterministic. Returns the fold of each row. Throws InputError unless k >= 1.
/// With fewer distinct groups than k, the folds past the number of groups stay empty.
std::vector<int> GroupFolds(const std::vector<int>& group, int k);

/// F1 of the positive class (label 1): 2 tp / (2 tp + fp + fn); 0 when nothing is positive
/// in either vector (undefined). Throws InputError if the sizes differ.
double F1Score(const std::vector<int>& truth, const std::vector<int>& pred);

/// Per-feature affine scaling to zero mean and unit variance, fitted on training rows.
struct Standardizer {
  Eigen::VectorXf mean;     ///< per-feature mean of the fitted rows
  Eigen::VectorXf inv_std;  ///< 1 / population standard deviation; 1 for constant columns

  /// Fits on the rows of `x` (statistics in double). A column whose values are all equal
  /// (or whose 1/std overflows a float) gets inv_std = 1. Throws InputError if `x`
  /// has no rows.
  static Standardizer Fit(const Eigen::MatrixXf& x);
  /// x <- (x - mean) * inv_std, in place, no allocation. Throws InputError on a
  /// dimension mismatch.
  void Apply(Eigen::VectorXf& x) const;
  /// Applies the scaling to every row of `x` in place (same arithmetic as Apply).
  void ApplyRows(Eigen::MatrixXf& x) const;
  /// Feature dimension.
  int dim() const { return static_cast<int>(mean.size()); }
};

/// Outcome of a grouped cross-validated hyperparameter search.
struct CvReport {
  double best_c = 0.0;       ///< chosen C
  double best_gamma = 0.0;   ///< chosen RBF gamma (absolute, not scaled by 1/dim); 0 without one
  double best_f1 = 0.0;      ///< pooled out-of-fold F1 of the chosen candidate; NaN if CV was skipped
  /// (C, gamma, pooled out-of-fold F1) of every candidate, in search order.
  std::vector<std::tuple<double, double, double>> grid;
  int folds = 0;             ///< folds actually used (min(cv_folds, number of runs)); 0 if skipped
  int n_rows = 0;            ///< training rows
  int n_slip = 0;            ///< slip rows among them (the classes are imbalanced: slip is the minority)
};

/// One hyperparameter candidate of the search (gamma = 0 for models without one).
struct CvCandidate {
  double c = 1.0;      ///< regularisation C
  double gamma = 0.0;  ///< RBF gamma (absolute)
};

/// Fits a model on standardised training rows for every candidate and returns, per candidate,
/// the 0/1 predictions of the standardised test rows. Called concurrently for different folds,
/// so it must be thread-safe (libsvm / liblinear training is).
using CvFitPredict = std::function<std::vector<std::vector<int>>(
    const Eigen::MatrixXf& x_train, const std::vector<int>& y_train, const Eigen::MatrixXf& x_test,
    const std::vector<CvCandidate>& grid)>;

/// Grouped k-fold CV over `grid`: folds from GroupFolds(ts.group, min(k, runs)); on each fold
/// a Standardizer is fitted on the training rows only and applied to both sides; `fit` predicts
/// the held-out rows. A candidate's score is the F1 of the pooled out-of-fold predictions of
/// all rows; the best is the first candidate (grid order) with the highest score. When a fold's
/// training rows hold one class only, its test rows are predicted as that class. Folds run in
/// parallel (at most min(folds, hardware threads)); the result does not depend on the thread
/// count. With a single candidate and fewer than 2 runs CV is skipped (best_f1 = NaN). Throws
/// InputError if k < 2 or the training set has fewer than 2 runs while the grid has
/// several candidates, and propagates errors of `fit`. `progress`, if set, hears of each fold
/// as it finishes and of the chosen candidate (from any thread, one call at a time).
CvReport GroupedGridSearch(const TrainingSet& ts, int k, const std::vector<CvCandidate>& grid,
                           const CvFitPredict& fit, const std::function<void(const std::string&)>& progress = {});

/// Checks a training set before fitting: consistent sizes, labels in {0, 1}, at least one
/// feature column, finite features, and both classes present; throws InputError
/// ("training set has no slip frames: ...") otherwise.
void CheckTrainingSet(const TrainingSet& ts);

/// Checks a list of hyperparameter values (`what` names it, e.g. "c_grid"): non-empty,
/// finite and > 0; throws InputError naming the list and the bad value.
void CheckPositiveGrid(const std::vector<double>& values, std::string_view what);

}  // namespace tactip
