#pragma once
// Reading a whole text file (model files, pin CSVs); writing goes through the base layer's
// WriteFileAtomic, number text through sim/base/number_text.h.

#include <string>

namespace tactip {

/// Reads a whole file; throws InputError naming the path if it cannot be read.
std::string ReadText(const std::string& path);

}  // namespace tactip
