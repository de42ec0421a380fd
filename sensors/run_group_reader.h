#pragma once
// Reading one run group of a dataset file, in either layout: layout 2 (sensors/<name>/,
// events/, actions/) or layout 1 (one sensor's pins/, labels/, contact/, external/
// directly under the run, event times among the run's attributes). Internal to sensors/.

#include <hdf5.h>

#include <map>
#include <string>
#include <vector>

#include "sensors/dataset.h"
#include "sensors/hdf5_io.h"

namespace tactip {

/// Reads the open run group `group` (/runs/run_NNNN) of the dataset at `path`, written in
/// layout `layout_version`. Throws InputError naming the file, the run and the part.
class RunGroupReader {
 public:
  /// Does not own `group`, which must stay open while the reader is used.
  RunGroupReader(hid_t group, int index, int layout_version, const std::string& path);

  /// The run's attributes (events included), frame times, and each sensor's name, pin
  /// count and attributes; no arrays besides time.
  RunRecord Summary() const;
  /// Everything: Summary() plus every sensor's arrays, the object and the actions.
  RunRecord Full() const;

 private:
  std::string Name() const;
  bool HasLink(const std::string& rel) const;
  hdf5::Hid OpenArray(const std::string& rel) const;
  std::vector<hsize_t> ShapeOf(const std::string& rel) const;
  template <class T>
  std::vector<T> ReadArray(const std::string& rel, const std::vector<hsize_t>& expected) const;
  void ReadAttrs(hid_t obj, const std::string& rel, std::map<std::string, double>& attrs,
                 std::map<std::string, std::string>& text) const;
  void ReadRunAttrs(RunRecord& run) const;
  void ReadTime(RunRecord& run) const;
  std::vector<std::string> SensorGroupNames() const;
  SensorRecord ReadSensorSummary(const std::string& name, hsize_t t) const;
  void ReadSensorArrays(SensorRecord& s, hsize_t t) const;
  ActionRecord ReadActions(hsize_t t) const;

  const hid_t group_;
  const int index_;
  const int layout_;
  const std::string run_;   // "run_0003"
  const std::string path_;  // the file
  const std::string err_;   // "cannot read dataset 'PATH': "
};

}  // namespace tactip
