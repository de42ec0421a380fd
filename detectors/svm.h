#pragma once
// Support-vector-machine gross-slip detectors (hardware method): C-SVC with a linear or a
// Gaussian (RBF) kernel on standardised pin-velocity features, trained with libsvm.

#include <memory>
#include <string>

#include "detectors/crossval.h"
#include "detectors/detector.h"

namespace tactip {

/// C-SVC slip classifier over VelocityFeatures. Training: grouped k-fold CV over C (and
/// gamma for RBF) maximising the pooled out-of-fold F1, then a refit on all rows. The classes
/// are unweighted, as on the hardware, although slip is the minority class (with n_slip = 4
/// and static_fraction = 0.4 typically 5-20 % of the rows); F1 as the selection criterion is
/// what accounts for the imbalance. Deterministic: no probability model, no shuffling.
class SvmDetector final : public Detector {
 public:
  /// Kernel of the SVM.
  enum class Kernel {
    kLinear,  ///< K(u, v) = u . v
    kRbf,     ///< K(u, v) = exp(-gamma |u - v|^2)
  };

  /// Trains on `ts` (rows from BuildTrainingSet with opts.features). Candidates: C in
  /// opts.c_grid and, for RBF, gamma = g / dim for g in opts.gamma_scale_grid (dim = feature
  /// dimension), searched by GroupedGridSearch with opts.cv_folds. Throws InputError
  /// on an unusable set ("training set has no slip frames: ...") or bad options.
  static std::unique_ptr<SvmDetector> Train(const TrainingSet& ts, Kernel kernel, const TrainOptions& opts);
  /// Reads a model written by Save; throws InputError naming `path` if it is
  /// missing, unreadable or corrupt.
  static std::unique_ptr<SvmDetector> Load(const std::string& path);
  /// Parses the text of a model file (as Load does after reading it); `path` names it in errors.
  static std::unique_ptr<SvmDetector> FromText(const std::string& text, const std::string& path);

  /// Frees the libsvm model.
  ~SvmDetector() override;
  /// Not copyable: owns the libsvm model.
  SvmDetector(const SvmDetector&) = delete;
  SvmDetector& operator=(const SvmDetector&) = delete;

  /// "svm-linear" or "svm-rbf".
  std::string name() const override;
  /// Forgets the previous frame.
  void Reset() override;
  /// Features -> standardise -> decision value f. slip = libsvm's predicted label is 1;
  /// score = f oriented so that > 0 means slip. The first frame after Reset is never a slip.
  /// Allocates nothing. Throws InputError if the frame's pin count does not fit dim().
  Decision Update(const PinFrame& frame) override;
  /// Writes "tactip-detector svm-rbf 1" (or svm-linear), the parameters, the standardizer
  /// and the libsvm model text, atomically; throws InputError if it cannot.
  void Save(const std::string& path) const override;

  /// Kernel of the model.
  Kernel kernel() const;
  /// Feature variant the model was trained on.
  FeatureSet features() const;
  /// Regularisation C.
  double c() const;
  /// RBF gamma (absolute); 0 for the linear kernel.
  double gamma() const;
  /// Feature dimension.
  int dim() const;
  /// Number of support vectors.
  int n_support_vectors() const;
  /// Standardisation applied before the SVM.
  const Standardizer& standardizer() const;
  /// The hyperparameter search of Train; for a loaded model only best_c / best_gamma are set
  /// (best_f1 = NaN, empty grid).
  const CvReport& cv_report() const;

 private:
  struct Impl;
  explicit SvmDetector(std::unique_ptr<Impl> impl);
  /// Validates and loads the embedded model text (`path`, `line_offset` locate it in errors).
  static std::unique_ptr<Impl> MakeImpl(Kernel kernel, FeatureSet features, double c, double gamma,
                                              Standardizer standardizer, std::string libsvm_text,
                                              const std::string& path, int line_offset);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tactip
