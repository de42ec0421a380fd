#pragma once
// Small text helpers for model files: reading, exact number text and strict parsing
// (writing goes through the base layer's WriteFileAtomic).

#include <charconv>
#include <string>
#include <system_error>

namespace tactip {

/// Reads a whole file; throws InputError naming the path if it cannot be read.
std::string ReadText(const std::string& path);

/// Shortest decimal text that reads back as exactly `v` (std::to_chars).
std::string RoundTripText(double v);
/// Shortest decimal text that reads back as exactly `v` (std::to_chars).
std::string RoundTripText(float v);

/// Parses the whole of `s` as a number of type T (std::from_chars); false on anything else.
template <typename T>
bool ParseWhole(const std::string& s, T& out) {
  const char* end = s.data() + s.size();
  const auto [p, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && p == end;
}

}  // namespace tactip
