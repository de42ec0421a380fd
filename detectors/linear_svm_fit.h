#pragma once
// The linear SVM's training: liblinear's primal trust-region Newton solver on the
// L2-regularised squared hinge loss (the L2-loss linear SVM, the bias a feature of value 1;
// deterministic), because libsvm's kernel solver does not converge on noisy frames (it reaches
// its cap of 10^7 iterations). The fit is written as
// a libsvm linear model with one support vector, w with coefficient 1, and rho = -b, so the
// detector's model file, loading and streaming are those of every other SVM.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "detectors/crossval.h"

namespace tactip {

/// The grouped cross-validation over `grid` (C only) on `folds` folds, and the refit on every
/// row with the best C.
struct LinearSvmFit {
  CvReport report;
  Standardizer standardizer;
  std::string libsvm_text;  ///< the refit as libsvm writes a two-class linear C-SVC
};

LinearSvmFit FitLinearSvm(const TrainingSet& ts, const std::vector<CvCandidate>& grid, int folds,
                          const std::function<void(const std::string&)>& progress);

}  // namespace tactip
