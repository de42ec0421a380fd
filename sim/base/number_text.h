#pragma once
// Numbers as text, exactly: the shortest text that reads back as the same value, and strict
// parsing of a whole text (std::to_chars / std::from_chars: locale-free, the same everywhere).

#include <charconv>
#include <string>
#include <system_error>

namespace tactip {

/// Shortest decimal text that reads back as exactly `v` (std::to_chars).
inline std::string RoundTripText(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, res.ptr);
}

/// Shortest decimal text that reads back as exactly `v` (std::to_chars).
inline std::string RoundTripText(float v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, res.ptr);
}

/// A table's cell: `v` in the fmt format `spec`, or `missing` when `v` is NaN (not measured,
/// did not happen).
std::string NumberCell(double v, const char* spec = "{:.3f}", const char* missing = "-");

/// Parses the whole of `s` as a number of type T (std::from_chars); false on anything else
/// (empty text, a sign or space around it, trailing characters, out of range).
template <typename T>
bool ParseWhole(const std::string& s, T& out) {
  const char* end = s.data() + s.size();
  const auto [p, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && p == end;
}

}  // namespace tactip
