#pragma once
// Hardware-style slip labels: the onset a camera tracking a marker on the object would give
// (the `marker_camera.` section). On the hardware, slip was labelled from a marker on the
// object followed by a second camera; its frames are slower than the tactile camera's, not
// synchronised with them, quantised to its pixels and jittered, and the onset is the first
// of its frames where the marker has moved beyond a displacement threshold. The simulator's
// exact onset (gross_slip_onset_s) is the first frame in which every contacting pin slides;
// this one (marker_onset_s) is stored beside it, so a detector can be trained and scored with
// either (docs/dataset-format.md, docs/detectors-and-benchmark.md).

#include <cstdint>
#include <vector>

#include "sim/config.h"

namespace tactip {

/// The marker camera (the `marker_camera.` section). Every default is chosen (the sources
/// name the camera, a JeVois module, but not its mode, view or threshold).
struct MarkerCameraConfig {
  double frame_rate_hz = 30.0;   ///< marker frames per second
  double mm_per_px = 0.3;        ///< size of one of its pixels at the marker
  double jitter_px = 0.2;        ///< std of the tracked marker position per frame, px
  double threshold_mm = 1.0;     ///< displacement from the held position that labels slip
  double reference_s = 0.5;      ///< span of held frames averaged into the reference position

  template <class V>
  void Visit(V& v) {
    v("frame_rate_hz", frame_rate_hz, "Hz",
      "Frame rate of the camera that tracks a marker on the object (hardware-style labels, marker_onset_s). 30 Hz: "
      "a JeVois module at 640x480 (chosen; the hardware's mode is not recorded). Its frames start at a random "
      "phase per run, not synchronised with the tactile camera's.",
      Bounds::Closed(1.0, 1000.0));
    v("mm_per_px", mm_per_px, "mm",
      "Size of one marker-camera pixel at the marker: the tracked height is rounded to it (0.3 mm: 640 px across "
      "~190 mm of the rig; chosen).",
      Bounds::Closed(0.001, 10.0));
    v("jitter_px", jitter_px, "px",
      "Std of the tracked marker position per marker frame, before the rounding to pixels (0.2 px; chosen).",
      Bounds::Closed(0.0, 20.0));
    v("threshold_mm", threshold_mm, "mm",
      "Hardware-style onset: the first marker frame after the hold whose position differs from the held "
      "reference by at least this (1 mm; chosen, the hardware's value is not recorded).",
      Bounds::Closed(0.001, 100.0));
    v("reference_s", reference_s, "s",
      "The reference position: the mean over the marker frames of this span before the hold ends (the "
      "retraction's start), within the hold (a shorter hold: all of it).",
      Bounds::Closed(0.0, 100.0));
  }
  void ValidateRules() const {}
};

/// The hold of a run: the object held still from `start_s` (the lift's end) to `end_s`
/// (the retraction's start).
struct HoldSpan {
  double start_s = 0.0, end_s = 0.0;
};

/// The hardware-style onset (s) of a run whose object moved along `height_m` at the tactile
/// frame times `time_s` (linearly interpolated between them), held over `hold`: the marker
/// frames at a seeded random phase, jittered and rounded to pixels, referenced to the mean of
/// those in the last `reference_s` of the hold (or the first at or after its end), and the
/// first frame at or after the hold's end that differs by `threshold_mm` or more. NaN when no
/// frame does or the run has fewer than two frames.
double MarkerOnset(const std::vector<double>& time_s, const std::vector<double>& height_m, const HoldSpan& hold,
                   const MarkerCameraConfig& cfg, std::uint64_t seed);

}  // namespace tactip
