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
void CheckRunValues(const RunRecord& run, const std::string& source);

}  // namespace tactip
