#include "detectors/text_io.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "sim/base/errors.h"

namespace tactip {

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace tactip
