#pragma once
// The threshold gross-slip detector: slip when the magnitude of the mean pin velocity
// reaches a trained threshold (the simplest hardware method).

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "detectors/detector.h"

namespace tactip {

/// Slip when v = |mean_i (dx_i, dy_i)| >= T (pixels per frame); score = v.
class ThresholdDetector : public Detector {
 public:
  /// Uses threshold `threshold_px` (px/frame); throws InputError unless finite and >= 0.
  explicit ThresholdDetector(double threshold_px);

  /// Chooses T maximising F1 over the frames BuildTrainingSet would select (same rules,
  /// same seeded downsampling); ties go to the smaller T. Throws InputError on bad
  /// options or when the selection holds no slip frame.
  static std::unique_ptr<ThresholdDetector> Train(const std::vector<LabeledRun>& runs, const TrainOptions& opts);
  /// Reads a model written by Save; throws InputError("model 'PATH': ...") if corrupt.
  static std::unique_ptr<ThresholdDetector> Load(const std::string& path);

  /// "threshold".
  std::string name() const override { return "threshold"; }
  /// Forgets the previous frame.
  void Reset() override;
  /// Decision for the next frame (the first frame after Reset is never a slip).
  Decision Update(const PinFrame& frame) override;
  /// Writes "tactip-detector threshold 1" and "threshold_px T" atomically.
  void Save(const std::string& path) const override;

  /// The threshold T in px/frame.
  double threshold_px() const { return threshold_px_; }

 private:
  double threshold_px_;
  VelocityFeatures features_{FeatureSet::kDr};
  Eigen::VectorXf scratch_;
};

}  // namespace tactip
