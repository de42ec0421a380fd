#pragma once
// How far one run is from the reference run with the same seed: onsets, pin trajectories
// before the onset, and the per-pin labels.

#include "sensors/dataset.h"

namespace tactip {

/// Differences of one run from its reference (same scenario, seed and run index).
struct RunDifference {
  double onset_error_s = 0.0;      ///< |gross onset - reference's| (inf when only one slipped)
  double incipient_error_s = 0.0;  ///< |incipient onset - reference's| (0 when neither has one; inf when one)
  double traj_rms_px = 0.0;        ///< RMS pin image distance over the frames both are held, before both onsets
  double label_disagreement = 0.0; ///< share of pin-frames, over pins in contact in either, whose contact or slip label differs
  int frames_compared = 0;
};

/// Compares `run` with `ref` frame by frame (both sampled at the same camera rate), as
/// their first sensors recorded them. Throws std::invalid_argument when their pin counts
/// differ.
RunDifference CompareRuns(const RunRecord& run, const RunRecord& ref);

}  // namespace tactip
