#pragma once
// Closing an HDF5 file that is being abandoned (a failed write, e.g. a full disk) without
// touching its disk again.

#include <hdf5.h>

namespace tactip {

/// Points the POSIX (sec2) file `file` at an anonymous in-memory file, so every later
/// write, flush and close of it succeeds and lands nowhere. HDF5 1.10 frees a file whose
/// H5Fclose fails (its final flush hits the full disk) yet keeps its identifier, and the
/// library's shutdown at exit then closes that identifier again and crashes; closing a
/// redirected file cannot fail that way. Only for files that are deleted afterwards.
/// Returns false (and changes nothing) if `file` is not an open sec2 file.
bool DiscardPendingWrites(hid_t file);

}  // namespace tactip
