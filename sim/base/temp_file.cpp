#include "sim/base/temp_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "sim/base/errors.h"

namespace tactip {

TempFile::TempFile() {
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) dir = "/tmp";
  std::string pattern = (dir / "tactip-model-XXXXXX").string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw InputError("cannot create a temporary file in '" + dir.string() + "': " + std::strerror(errno));
  ::close(fd);
  path_ = pattern;
}

TempFile::~TempFile() { std::remove(path_.c_str()); }

void TempFile::Write(const std::string& text, const std::string& for_what) const {
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out.flush()) {
    throw InputError(for_what + ": cannot write temporary file '" + path_ + "'");
  }
}

}  // namespace tactip
