#pragma once
// What the tracker reports for each pin beyond the camera's projection: position noise and
// missed detections. Two models (`sensor.noise_model`):
//   independent  Gaussian per pin and coordinate, white in time (sensor.pixel_noise_px).
//   structured   the structure of a real TacTip's static noise (docs/model.md#pin-noise):
//                one similarity transform of the whole pattern per frame (translation,
//                rotation and scale about the principal point), each a first-order
//                autoregressive process in time (correlation time sensor.common_time_s);
//                a per-pin field correlated between neighbours (a Gaussian kernel over the
//                pattern, white in time); and the independent part of the first model.
// Seeded and deterministic. The independent part and the dropouts draw from the same stream
// in both models, in the same order; the structured parts from a second stream.

#include <cstdint>
#include <vector>

#include "sensors/camera.h"
#include "sim/base/random.h"

namespace tactip {

/// Adds noise and dropouts to one frame of projected pin positions, in place. Not
/// thread-safe; one per camera and run.
class DetectionNoise {
 public:
  DetectionNoise(const CameraConfig& cfg, std::uint64_t seed);
  /// `px` (N x 2, row-major, the noise-free positions on entry) is replaced by what the
  /// tracker reports; `valid` (N) set. `prev_px` holds the previous reported positions
  /// (empty on the first frame): a missed pin keeps them. The structured model builds its
  /// neighbour kernel from the first frame's positions (the only allocation).
  void Apply(std::vector<float>& px, std::vector<std::uint8_t>& valid, const std::vector<float>& prev_px);

  /// The pattern's mean nearest-neighbour distance in the first frame, px (0 before it, or
  /// under the independent model).
  double pitch_px() const { return pitch_px_; }

 private:
  /// One common-mode coordinate: stationary std and state.
  struct Ar1 {
    double std = 0.0;
    double x = 0.0;
  };
  void BuildKernel(const std::vector<float>& px);
  void StepCommon();
  void AddStructured(std::vector<float>& px);

  CameraConfig cfg_;
  Rng rng_;         // independent part and dropouts (the independent model's stream)
  Rng structured_;  // common mode and neighbour field
  bool structured_model_;
  double a_ = 0.0;  // autoregressive coefficient per frame of the common mode
  bool started_ = false;
  Ar1 shift_u_, shift_v_, turn_, scale_;
  double pitch_px_ = 0.0;
  // The neighbour field's kernel, rows by pin: weights_[offsets_[i] .. offsets_[i+1]) on
  // pins neighbours_[...]; every row has unit sum of squares.
  std::vector<int> offsets_, neighbours_;
  std::vector<double> weights_;
  std::vector<double> white_;  // 2 N white values of the neighbour field, per frame
};

/// The pattern's mean nearest-neighbour distance of positions `px` (N x 2, row-major), px;
/// 0 for fewer than two pins.
double MeanNearestNeighbourPx(const std::vector<float>& px);

}  // namespace tactip
