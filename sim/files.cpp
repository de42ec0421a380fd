#include "sim/files.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "sim/config.h"

namespace tactip {

std::string TempPathFor(const std::string& path) {
  static std::atomic<int> counter{0};  // distinguishes temp files of one process
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

void CheckWritableLocation(const std::string& path) {
  const std::filesystem::path p(path);
  const std::filesystem::path dir = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError("cannot write '" + path + "': folder '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw InputError("cannot write '" + path + "': folder '" + dir.string() + "' is not writable");
  }
  if (std::filesystem::is_directory(p, ec)) throw InputError("cannot write '" + path + "': it is a folder");
}

void WriteFileAtomic(const std::string& path, const std::string& text) {
  const std::string tmp = TempPathFor(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot write '" + path + "': " + std::strerror(errno));
    out << text;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw InputError("cannot write '" + path + "': write failed");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw InputError("cannot write '" + path + "': " + why);
  }
}

}  // namespace tactip
