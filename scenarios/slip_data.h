#pragma once
// Converts recorded data — the project's HDF5 datasets and CSV recordings of real
// TacTips — into the PinFrames and ground truth the detectors consume.

#include <string>
#include <vector>

#include "detectors/detector.h"

namespace tactip {

/// Parses a run selection such as "0-19", "3", "0,2,5-7" (sorted, de-duplicated);
/// throws InputError on malformed text.
std::vector<int> ParseRunList(const std::string& text);

/// Reads runs of an HDF5 dataset as labelled frame sequences. `runs` empty = all runs.
/// The labelled window starts at the run's retraction; the onset frame is the first
/// frame at or after `gross_slip_onset_s`. That frame's velocity spans the onset (part
/// static, part slip), so unless `score_onset_frame` is set it is a transition frame and
/// the slip frames start at the next one. Throws InputError for a missing/corrupt file
/// or a run that is not in the dataset.
std::vector<LabeledRun> LoadDatasetRuns(const std::string& path, const std::vector<int>& runs,
                                        bool score_onset_frame = false);

/// Reads pin frames from the project's HDF5 datasets or from a real-TacTip CSV
/// recording (by extension: .h5/.hdf5 or .csv). CSV input is one run (index 0) with no
/// ground truth. Throws InputError naming the file and problem.
std::vector<LabeledRun> LoadFrames(const std::string& path, const std::vector<int>& runs);

}  // namespace tactip
