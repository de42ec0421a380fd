#pragma once
// Atomic file output: write to a temporary file beside the target, then rename.

#include <string>
#include <vector>

namespace tactip {

/// Writes `text` to `path` atomically (temp file in the same folder + rename); throws
/// InputError naming the path if it cannot be written. A failure leaves no file.
void WriteFileAtomic(const std::string& path, const std::string& text);

/// Throws InputError naming `path` if its folder does not exist or no file can be created
/// in it (with the system's reason), so long jobs fail before they start rather than at the end.
void CheckWritableLocation(const std::string& path);

/// Creates the output folder `dir` and its parents if missing; throws InputError
/// ("cannot create output folder 'DIR': reason") when it cannot, or when `dir` names a file.
void CreateOutputFolder(const std::string& dir);

/// Allocates disk space for the first `size` bytes of the existing file `path` (holes
/// included, contents unchanged), so that later writes within them cannot run out of
/// space. Returns 0, or the errno value saying why not (ENOSPC: the disk is full).
int ReserveFileSpace(const std::string& path, long long size);

/// A unique temporary name beside `path` ("path.tmp.<pid>.<n>"). Temporary files of `path`
/// left by processes that are no longer running are removed first, named in one line on stderr.
std::string TempPathFor(const std::string& path);

/// Removes the temporary files of `path` ("path.tmp.<pid>.<n>") whose process is no longer
/// running; returns their paths. Those of running processes (this one included) are kept.
std::vector<std::string> RemoveStaleTempFiles(const std::string& path);

/// True when `a` and `b` name the same file: through symbolic and hard links when both
/// exist, by their absolute paths with links and '..' resolved otherwise.
bool SameFile(const std::string& a, const std::string& b);

}  // namespace tactip
