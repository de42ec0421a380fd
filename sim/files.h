#pragma once
// Atomic file output: write to a temporary file beside the target, then rename.

#include <string>

namespace tactip {

/// Writes `text` to `path` atomically (temp file in the same folder + rename); throws
/// InputError naming the path if it cannot be written. A failure leaves no file.
void WriteFileAtomic(const std::string& path, const std::string& text);

/// Throws InputError naming `path` if its folder does not exist or is not writable, so
/// long jobs fail before they start rather than at the end.
void CheckWritableLocation(const std::string& path);

/// A unique temporary name beside `path` ("path.tmp.<pid>.<n>").
std::string TempPathFor(const std::string& path);

}  // namespace tactip
