#pragma once
// HDF5 datasets of simulated runs: writing (atomically) and reading. The schema is
// documented in docs/dataset-format.md and readable with h5py without project code.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sensors/image_frames.h"
#include "sensors/shard.h"

namespace tactip {

/// Layout of the files DatasetWriter writes (root attribute `layout_version`): 2 = one
/// group per sensor under sensors/, events/ and actions/ per run. Files without the
/// attribute are layout 1 (one sensor, its arrays directly under the run).
constexpr int kDatasetLayoutVersion = 2;

/// Root attributes of a dataset file.
struct DatasetHeader {
  std::string tactip_version;  ///< project version that wrote the file
  std::string scenario;        ///< scenario name, e.g. "rail"
  std::uint64_t seed = 0;      ///< master seed; run i uses a seed derived from it
  std::string config_yaml;     ///< full resolved config
  /// Layout of the file read (root attribute `layout_version`; 1 when absent). The writer
  /// always writes kDatasetLayoutVersion.
  int layout_version = kDatasetLayoutVersion;
  /// Set in shard files only: which part of which job the file holds (root attributes
  /// `shard` = "i/n" and `runs_total` = R); `tactip merge` joins shards into one dataset.
  std::optional<ShardSpec> shard;
};

/// One tactile sensor's recording of a run (group sensors/<name>). Arrays are row-major;
/// T frames (the run's), N pins.
struct SensorRecord {
  std::string name = "tactip";          ///< the sensor's name: its group, and its MJCF prefix
  int n_pins = 0;                       ///< N
  std::vector<float> pos_px;            ///< (T,N,2) inner pin positions in the image (noisy)
  std::vector<std::uint8_t> valid;      ///< (T,N) 1 = detected this frame
  std::vector<float> pos_m;             ///< (T,N,3) true inner pin positions, sensor frame, m
  std::vector<std::uint8_t> gross_slip; ///< (T) 1 while the object slips on the sensor
  std::vector<std::uint8_t> pin_slip;   ///< (T,N) 1 = this pin's contact is sliding
  std::vector<std::uint8_t> pin_contact;///< (T,N) 1 = this pin touches the stimulus
  std::vector<std::uint8_t> incipient;  ///< (T) 1 = partial slip: some contacting pins slide, others stick
  /// (N) per pin: the time of the first physics step, from the retraction start up to the
  /// gross-slip onset, at which it is labelled slipping (NaN: not in that window); empty when
  /// not recorded (files from before it, scenarios without a retraction).
  std::vector<double> pin_first_slip_s;
  std::vector<float> external_px;       ///< (T,N,2) outer contact points in the external camera, or empty
  std::vector<float> external_m;        ///< (T,N,3) true outer contact points, sensor frame, m, or empty
  std::vector<float> normal_N;          ///< (T,N) normal force at each pin, N
  std::vector<float> tangential_N;      ///< (T,N,2) tangential force (sensor y, z), N
  /// Rendered camera frames (images.enabled), or empty: T frames of image_height x
  /// image_width uint8 pixels, each zlib-compressed (one HDF5 chunk of `images`).
  std::vector<CompressedFrame> images;
  int image_width = 0, image_height = 0;  ///< frame size (px) when `images` is not empty
  std::vector<float> detected_px;         ///< (T,N,2) pins tracked by the blob pipeline, px, or empty
  std::vector<std::uint8_t> detected_valid;  ///< (T,N) 1 = a blob within the gate that frame, or empty
  /// Scalar sensor attributes (besides n_pins, which the group always carries).
  std::map<std::string, double> attrs;
  /// Text sensor attributes (skin_pattern, ...).
  std::map<std::string, std::string> text_attrs;

  /// Throws std::logic_error if the name cannot name a group (empty, '/', "." or "..")
  /// or array sizes disagree with `frames` and N; `who` starts the message.
  void CheckShapes(size_t frames, const std::string& who) const;
  /// The part of CheckShapes that analyses of the pins frame by frame rely on: throws
  /// std::invalid_argument unless pos_px, valid, pos_m, pin_slip, pin_contact (and
  /// external_px, external_m when either is present) hold a value per pin and frame; `who`
  /// starts the message.
  void CheckPinArrays(size_t frames, const std::string& who) const;
};

/// One thing a controller did, for the dataset's actions/ group.
struct ControllerAction {
  double time_s = 0.0;  ///< when (s)
  std::string what;     ///< e.g. "slip_declared", "catch", "stop"
};

/// What the controller of a run did (group actions/): the actuators' controls at each
/// frame and the list of its actions.
struct ActionRecord {
  std::vector<std::string> actuators;  ///< U actuator names, in control order
  std::vector<double> controls;        ///< (T,U) each actuator's control at each frame
  std::vector<ControllerAction> list;  ///< (A) what the controller did, and when

  /// True when nothing was recorded (no actuators, no actions): no actions/ group.
  bool empty() const { return actuators.empty() && list.empty(); }
};

/// One recorded run: frame times, every sensor's recording, the object, the controller.
struct RunRecord {
  int index = 0;                        ///< run number (group /runs/run_NNNN)
  std::vector<double> time;             ///< (T) s, camera frame times
  std::vector<SensorRecord> sensors;    ///< one per tactile sensor, in scene order
  std::vector<double> object_height_m;  ///< (T) object position along the rail, m
  ActionRecord actions;                 ///< what the controller did
  /// Scalar run attributes (gross_slip_onset_s, object_fall_s, object_mass_kg,
  /// friction_coefficient, retract_speed_mm_s, press_depth_mm, ...). NaN = did not happen.
  /// The event times among them (IsEventAttribute) live in the file's events/ group.
  std::map<std::string, double> attrs;
  /// Text run attributes (stimulus, ...).
  std::map<std::string, std::string> text_attrs;

  /// Number of frames T.
  size_t frames() const { return time.size(); }
  /// Throws std::logic_error if there is no sensor, two sensors share a name, or array
  /// sizes disagree with T and a sensor's N.
  void CheckShapes() const;
  /// The sensor named `name`, or nullptr.
  const SensorRecord* FindSensor(const std::string& name) const;
};

/// True for the run attributes that are event times (gross_slip_onset_s,
/// incipient_onset_s, incipient_lead_s, object_fall_s, retract_start_s, predicted_onset_s,
/// coulomb_early_s): a file keeps them in the run's events/ group.
bool IsEventAttribute(const std::string& key);

/// Attributes of a layout-1 run that belong to its sensor (skin_pattern).
bool IsSensorAttribute(const std::string& key);

/// "tactip, left": the names of the run's sensors, for messages.
std::string SensorNames(const RunRecord& run);

/// Path of sensor `name`'s arrays relative to its run group in a file of layout
/// `layout_version`: "sensors/NAME/" (layout 2) or "" (layout 1: directly under the run).
std::string SensorPath(int layout_version, const std::string& name);

/// Writes a dataset to `path` through a temporary file in the same folder; the file
/// appears under its final name only after Commit(). Destroying an uncommitted writer
/// removes the temporary file, so a failed or interrupted run leaves no partial dataset.
class DatasetWriter {
 public:
  /// Creates the temporary file and writes the root attributes; throws InputError if
  /// the folder is not writable.
  DatasetWriter(const std::string& path, const DatasetHeader& header);
  ~DatasetWriter();
  DatasetWriter(const DatasetWriter&) = delete;
  DatasetWriter& operator=(const DatasetWriter&) = delete;

  /// Writes /runs/run_NNNN in layout kDatasetLayoutVersion: time, one group per sensor,
  /// object/, events/, actions/ (float arrays with a pin axis chunked and compressed) and
  /// the attributes. Throws InputError, writing nothing of the run, if an array holds a
  /// non-finite value (NaN in an attribute means "did not happen" and is kept).
  void WriteRun(const RunRecord& run);
  /// Flushes, closes and renames the temporary file to `path`.
  void Commit();
  /// Path of the temporary file (for tests).
  const std::string& temp_path() const { return temp_path_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  std::string temp_path_;
  bool committed_ = false;
};

/// Reads datasets written by DatasetWriter, in layout 2 or (files without a root attribute
/// `layout_version`) layout 1, whose one sensor is read as "tactip". Throws InputError
/// naming the file and the problem when it is missing, not HDF5, of an unknown layout,
/// lacks a required group/attribute, has no runs or a /runs member not named run_NNNN;
/// and, naming the run and the array, when a run read has no sensor, no frames, frame
/// times not finite and strictly increasing, or a non-finite value (see run_checks.h).
class DatasetReader {
 public:
  explicit DatasetReader(const std::string& path);
  ~DatasetReader();
  DatasetReader(const DatasetReader&) = delete;
  DatasetReader& operator=(const DatasetReader&) = delete;

  const DatasetHeader& header() const { return header_; }
  /// Run indices present, ascending.
  const std::vector<int>& run_indices() const { return runs_; }
  /// Reads one run completely; the event times land in its attrs.
  RunRecord ReadRun(int index) const;
  /// Reads only the attributes (run, events and sensors), the frame times and each
  /// sensor's name and pin count of one run (cheap).
  RunRecord ReadRunSummary(int index) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  DatasetHeader header_;
  std::vector<int> runs_;
};

/// Partial-slip label per frame from (T,N) per-pin labels: 1 when at least one contacting
/// pin slides while at least one other sticks.
std::vector<std::uint8_t> PartialSlipLabels(const std::vector<std::uint8_t>& pin_contact,
                                            const std::vector<std::uint8_t>& pin_slip, int n_pins);

/// Group name of a run: "run_0007".
std::string RunGroupName(int index);

}  // namespace tactip
