#pragma once
// HDF5 datasets of simulated runs: writing (atomically) and reading. The schema is
// documented in the README and readable with h5py without project code.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sensors/shard.h"

namespace tactip {

/// Root attributes of a dataset file.
struct DatasetHeader {
  std::string tactip_version;  ///< project version that wrote the file
  std::string scenario;        ///< scenario name, e.g. "rail"
  std::uint64_t seed = 0;      ///< master seed; run i uses a seed derived from it
  std::string config_yaml;     ///< full resolved config
  /// Set in shard files only: which part of which job the file holds (root attributes
  /// `shard` = "i/n" and `runs_total` = R); `tactip merge` joins shards into one dataset.
  std::optional<ShardSpec> shard;
};

/// One recorded run. Arrays are row-major; T frames, N pins.
struct RunRecord {
  int index = 0;                        ///< run number (group /runs/run_NNNN)
  int n_pins = 0;                       ///< N
  std::vector<double> time;             ///< (T) s, camera frame times
  std::vector<float> pos_px;            ///< (T,N,2) inner pin positions in the image (noisy)
  std::vector<std::uint8_t> valid;      ///< (T,N) 1 = detected this frame
  std::vector<float> pos_m;             ///< (T,N,3) true inner pin positions, sensor frame, m
  std::vector<std::uint8_t> gross_slip; ///< (T) 1 while the object slips on the sensor
  std::vector<std::uint8_t> pin_slip;   ///< (T,N) 1 = this pin's contact is sliding
  std::vector<std::uint8_t> pin_contact;///< (T,N) 1 = this pin touches the stimulus
  std::vector<std::uint8_t> incipient;  ///< (T) 1 = partial slip: some contacting pins slide, others stick
  std::vector<float> external_px;       ///< (T,N,2) outer contact points in the external camera, or empty
  std::vector<float> external_m;        ///< (T,N,3) true outer contact points, sensor frame, m, or empty
  std::vector<float> normal_N;          ///< (T,N) normal force at each pin, N
  std::vector<float> tangential_N;      ///< (T,N,2) tangential force (sensor y, z), N
  std::vector<double> object_height_m;  ///< (T) object position along the rail, m
  /// Scalar run attributes (gross_slip_onset_s, object_fall_s, object_mass_kg,
  /// friction_coefficient, retract_speed_mm_s, press_depth_mm, ...). NaN = did not happen.
  std::map<std::string, double> attrs;
  /// Text run attributes (stimulus, ...).
  std::map<std::string, std::string> text_attrs;

  /// Number of frames T.
  size_t frames() const { return time.size(); }
  /// Throws std::logic_error if array sizes disagree with T and N.
  void CheckShapes() const;
};

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

  /// Writes /runs/run_NNNN with all arrays (float arrays chunked and compressed) and
  /// attributes. Throws InputError, writing nothing of the run, if an array holds a
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

/// Reads datasets written by DatasetWriter. Throws InputError naming the file and the
/// problem when it is missing, not HDF5, lacks a required group/attribute, has no runs or
/// a /runs member not named run_NNNN; and, naming the run and the array, when a run read
/// has no frames, frame times not finite and strictly increasing, or a non-finite value
/// (see run_checks.h).
class DatasetReader {
 public:
  explicit DatasetReader(const std::string& path);
  ~DatasetReader();
  DatasetReader(const DatasetReader&) = delete;
  DatasetReader& operator=(const DatasetReader&) = delete;

  const DatasetHeader& header() const { return header_; }
  /// Run indices present, ascending.
  const std::vector<int>& run_indices() const { return runs_; }
  /// Reads one run completely.
  RunRecord ReadRun(int index) const;
  /// Reads only the attributes, the frame times and the pin count of one run (cheap).
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
