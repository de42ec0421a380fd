#pragma once
// Checking that a file is a real PNG image: signature and pixel size from its header.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace tactip::testing {

/// Width and height (px) of a PNG, both 0 if the file is missing or not a PNG.
struct PngInfo {
  std::uint32_t width = 0;   ///< pixels
  std::uint32_t height = 0;  ///< pixels
  std::uintmax_t bytes = 0;  ///< file size
};

/// Reads the PNG signature and IHDR chunk of `path`.
inline PngInfo ReadPngInfo(const std::filesystem::path& path) {
  PngInfo info;
  std::ifstream in(path, std::ios::binary);
  std::string head(24, '\0');
  if (!in.read(head.data(), static_cast<std::streamsize>(head.size()))) return info;
  if (head.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || head.compare(12, 4, "IHDR") != 0) return info;
  auto be32 = [&](size_t at) {
    std::uint32_t v = 0;
    for (size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(head[at + k]);
    return v;
  };
  info.width = be32(16);
  info.height = be32(20);
  info.bytes = std::filesystem::file_size(path);
  return info;
}

/// Files in `dir` whose name contains ".tmp." (left behind by a non-atomic write).
inline int TempFilesIn(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    n += e.path().filename().string().find(".tmp.") != std::string::npos;
  }
  return n;
}

}  // namespace tactip::testing
