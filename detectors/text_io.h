#pragma once
// Small text-file helpers for model files (detectors depend on nothing but Eigen and
// the ML libraries, so they carry their own).

#include <string>

namespace tactip {

/// Writes `text` to `path` through a temporary file and a rename; throws
/// DetectorInputError naming the path if it cannot be written. No partial file remains.
void WriteTextAtomic(const std::string& path, const std::string& text);

/// Reads a whole file; throws DetectorInputError naming the path if it cannot be read.
std::string ReadText(const std::string& path);

}  // namespace tactip
