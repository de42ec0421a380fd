#pragma once
// Offline evaluation of a streaming detector on labelled runs: confusion counts, F1,
// detection delay, false positives per minute and per-frame run time.

#include <limits>
#include <string>
#include <vector>

#include "detectors/detector.h"

namespace tactip {

/// Binary confusion counts (positive = slip).
struct Confusion {
  long tp = 0;  ///< slip frames declared slip
  long fp = 0;  ///< static frames declared slip
  long tn = 0;  ///< static frames declared static
  long fn = 0;  ///< slip frames declared static

  /// tp / (tp + fp); 0 when undefined.
  double Precision() const;
  /// tp / (tp + fn); 0 when undefined.
  double Recall() const;
  /// 2 tp / (2 tp + fp + fn); 0 when undefined.
  double F1() const;
  /// (tp + tn) / total; 0 when undefined.
  double Accuracy() const;
  /// tp + fp + tn + fn.
  long Total() const { return tp + fp + tn + fn; }
  /// Adds another set of counts.
  Confusion& operator+=(const Confusion& o);
};

/// Evaluation of one run.
struct RunEvaluation {
  int run = 0;               ///< LabeledRun::run
  Confusion confusion;       ///< over the scored frames of this run
  int onset_frame = -1;      ///< ground-truth onset (-1: no slip in the run)
  int detection_frame = -1;  ///< first frame >= onset declared slip (-1: none)
  /// detection_frame - onset_frame; NaN if not detected at/after onset.
  double delay_frames = std::numeric_limits<double>::quiet_NaN();
  int static_frames = 0;          ///< scored static frames
  int false_positive_frames = 0;  ///< scored static frames declared slip
};

/// Evaluation of a detector over a set of runs.
struct Evaluation {
  std::string detector;             ///< Detector::name()
  Confusion confusion;              ///< summed over all runs
  std::vector<RunEvaluation> runs;  ///< one per run, in input order
  double delay_frames_mean = 0.0;   ///< over runs detected at/after onset; NaN if none
  double delay_ms_mean = 0.0;       ///< same, in ms (each run at its own frame rate); NaN if none
  double fp_per_min = 0.0;          ///< false positives per minute of scored static data; NaN if none
  double us_per_frame_mean = 0.0;   ///< mean wall time of Detector::Update, microseconds
  double us_per_frame_p99 = 0.0;    ///< 99th percentile (nearest rank) of the same
  int frames_scored = 0;            ///< frames counted in the confusion
  double detected_fraction = 0.0;   ///< runs with an onset that were detected; NaN if no run has one
};

/// Streams every frame of every run through `det` (Reset before each run, each Update
/// timed with std::chrono::steady_clock) and scores frames first_frame <= k < onset as
/// static (all frames >= first_frame when the run has no onset) and onset <= k <
/// onset + n_slip as slip; later frames are streamed but not scored. The detection
/// frame is the first frame >= onset declared slip, searched to the end of the run.
/// Throws InputError if n_slip < 1 or a frame rate is not > 0 (and passes on
/// the detector's errors).
Evaluation Evaluate(Detector& det, const std::vector<LabeledRun>& runs, int n_slip);

/// One line: "TP 10 FP 2 TN 100 FN 1 | precision 0.8333 recall 0.9091 F1 0.8696 accuracy 0.9735".
std::string FormatConfusion(const Confusion& c);

}  // namespace tactip
