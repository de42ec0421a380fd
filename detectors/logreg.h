#pragma once
// Logistic-regression gross-slip detector (hardware method): L2-regularised logistic
// regression on standardised pin-velocity features, trained with liblinear.

#include <memory>
#include <string>

#include "detectors/crossval.h"
#include "detectors/detector.h"

namespace tactip {

/// L2-regularised logistic regression (liblinear L2R_LR, bias term 1, eps 0.01) over
/// VelocityFeatures. Training: grouped k-fold CV over C maximising the pooled out-of-fold F1,
/// then a refit on all rows. Unweighted classes (slip is the minority; F1 selects C).
/// Deterministic.
class LogRegDetector final : public Detector {
 public:
  /// Trains on `ts` (rows from BuildTrainingSet with opts.features); C from opts.c_grid by
  /// GroupedGridSearch with opts.cv_folds. Throws InputError on an unusable set
  /// ("training set has no slip frames: ...") or bad options.
  static std::unique_ptr<LogRegDetector> Train(const TrainingSet& ts, const TrainOptions& opts);
  /// Reads a model written by Save; throws InputError naming `path` if it is
  /// missing, unreadable or corrupt.
  static std::unique_ptr<LogRegDetector> Load(const std::string& path);
  /// Parses the text of a model file (as Load does after reading it); `path` names it in errors.
  static std::unique_ptr<LogRegDetector> FromText(const std::string& text, const std::string& path);

  /// Frees the liblinear model.
  ~LogRegDetector() override;
  /// Not copyable: owns the liblinear model.
  LogRegDetector(const LogRegDetector&) = delete;
  LogRegDetector& operator=(const LogRegDetector&) = delete;

  /// "logreg".
  std::string name() const override { return "logreg"; }
  /// Forgets the previous frame.
  void Reset() override;
  /// Features -> standardise -> liblinear decision value f. slip = predicted label is 1;
  /// score = f oriented so that > 0 means slip (the log-odds of slip). The first frame after
  /// Reset is never a slip. Allocates nothing. Throws InputError if the frame's pin
  /// count does not fit dim().
  Decision Update(const PinFrame& frame) override;
  /// Writes "tactip-detector logreg 1", the parameters, the standardizer and the liblinear
  /// model text, atomically; throws InputError if it cannot.
  void Save(const std::string& path) const override;

  /// Feature variant the model was trained on.
  FeatureSet features() const;
  /// Regularisation C.
  double c() const;
  /// Feature dimension.
  int dim() const;
  /// Standardisation applied before the classifier.
  const Standardizer& standardizer() const;
  /// The hyperparameter search of Train (gamma entries are 0); for a loaded model only best_c
  /// is set (best_f1 = NaN, empty grid).
  const CvReport& cv_report() const;

 private:
  struct Impl;
  explicit LogRegDetector(std::unique_ptr<Impl> impl);
  /// Validates and loads the embedded model text (`path`, `line_offset` locate it in errors).
  static std::unique_ptr<Impl> MakeImpl(FeatureSet features, double c, Standardizer standardizer,
                                              std::string liblinear_text, const std::string& path,
                                              int line_offset);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tactip
