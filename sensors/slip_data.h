#pragma once
// Converts recorded data — the project's HDF5 datasets and CSV recordings of real
// TacTips — into the PinFrames and ground truth the detectors consume.

#include <string>
#include <vector>

#include "detectors/detector.h"
#include "sensors/dataset.h"

namespace tactip {

/// Parses a run selection such as "0-19", "3", "0,2,5-7" (sorted, de-duplicated);
/// throws InputError on malformed text.
std::vector<int> ParseRunList(const std::string& text);

/// The run indices of a dataset in words, for messages: "run 0", "runs 0-3" for a
/// contiguous block, else "4 runs from 0 to 9" (`runs` ascending, not empty).
std::string RunsText(const std::vector<int>& runs);

/// The sensor of `run` (read from dataset `path`) named `name`, or its first sensor when
/// `name` is empty. Throws InputError "--sensor 'NAME': dataset 'PATH' has no such sensor
/// (its sensors: ...)" otherwise.
const SensorRecord& ChooseSensor(const RunRecord& run, const std::string& name, const std::string& path);

/// Throws ChooseSensor's InputError unless the first run of dataset `path` has sensor
/// `name` ("" = the first); reads only that run's summary.
void CheckSensorOption(const std::string& path, const std::string& name);

/// Which pin positions of a dataset a detector sees.
enum class PinSource {
  kCamera,    ///< pins/pos_px and pins/valid: the camera model (projection, noise, dropouts)
  kDetected,  ///< pins/detected_px and pins/detected_valid: the blob pipeline on rendered images
};

/// "camera" or "detected" as a PinSource; throws InputError naming --pins otherwise.
PinSource ParsePinSource(const std::string& text);

/// Which onset labels a run's frames.
enum class OnsetLabels {
  kExact,   ///< the simulator's exact gross-slip onset (events/gross_slip_onset_s)
  kMarker,  ///< the hardware-style onset of a marker camera on the object (events/marker_onset_s)
};

/// "exact" or "marker" as OnsetLabels; throws InputError naming --labels otherwise.
OnsetLabels ParseOnsetLabels(const std::string& text);

/// Reads runs of an HDF5 dataset as labelled frame sequences, as sensor `sensor` ("" =
/// the dataset's first) recorded them, with the pin positions of `pins` (kDetected throws
/// InputError naming the run and sensor when the dataset has no detected pins). `runs` empty = all runs. The labelled window
/// starts at the run's retraction; the onset frame is the first frame at or after
/// `gross_slip_onset_s`. That frame's velocity spans the onset (part static, part slip),
/// so unless `score_onset_frame` is set it is a transition frame and the slip frames start
/// at the next one. `labels` picks the onset: the exact one or the marker camera's. Throws
/// InputError for a missing/corrupt file, a run that is not in the dataset, a sensor it does
/// not have, or marker labels in a dataset made before they were recorded.
std::vector<LabeledRun> LoadDatasetRuns(const std::string& path, const std::vector<int>& runs,
                                        bool score_onset_frame = false, const std::string& sensor = "",
                                        PinSource pins = PinSource::kCamera,
                                        OnsetLabels labels = OnsetLabels::kExact);

/// Reads pin frames from the project's HDF5 datasets (of sensor `sensor`, "" = the first)
/// or from a real-TacTip CSV recording (by extension: .h5/.hdf5 or .csv). CSV input is
/// one run (index 0) of one sensor with no ground truth: a `sensor` name and detected pins
/// are refused.
/// Throws InputError naming the file and problem.
std::vector<LabeledRun> LoadFrames(const std::string& path, const std::vector<int>& runs,
                                   const std::string& sensor = "", PinSource pins = PinSource::kCamera);

}  // namespace tactip
