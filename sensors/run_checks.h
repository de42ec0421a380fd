#pragma once
// What a recorded run read from a file must hold beyond its array shapes (the checks the
// pin-track CSV reader makes, for HDF5 datasets).

#include <string>

#include "sensors/dataset.h"

namespace tactip {

/// Throws InputError "<source>: run_NNNN/time ..." unless the run has at least one frame
/// and its frame times are finite and strictly increasing. `source` names the file,
/// e.g. "dataset 'rail.h5'".
void CheckRunTimes(const RunRecord& run, const std::string& source);

/// Throws InputError "<source>: run_NNNN/<array> ..." naming the frame (and pin) of the
/// first non-finite value of a float array, or of a detection flag (pins/valid) not 0 or 1.
/// A sensor's arrays are named by their path in a file of layout `layout_version`
/// ("run_0003/sensors/tactip/pins/pos_px"; layout 1: "run_0003/pins/pos_px").
void CheckRunValues(const RunRecord& run, const std::string& source, int layout_version = kDatasetLayoutVersion);

}  // namespace tactip
