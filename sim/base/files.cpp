#include "sim/base/files.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "sim/base/errors.h"

namespace tactip {

namespace {

namespace fs = std::filesystem;

// The folder a file `path` goes into ("." for a bare name).
fs::path FolderOf(const std::string& path) {
  const fs::path p(path);
  return p.parent_path().empty() ? fs::path(".") : p.parent_path();
}

// The process id of a temporary file of `name` ("<name>.tmp.<pid>.<n>"), or 0 if `file`
// is not one.
pid_t TempFileOwner(const std::string& file, const std::string& name) {
  const std::string prefix = name + ".tmp.";
  if (file.size() <= prefix.size() || file.compare(0, prefix.size(), prefix) != 0) return 0;
  const char* first = file.data() + prefix.size();
  const char* last = file.data() + file.size();
  long pid = 0;
  unsigned long n = 0;
  auto r = std::from_chars(first, last, pid);
  if (r.ec != std::errc() || pid <= 0 || r.ptr == last || *r.ptr != '.') return 0;
  const auto rn = std::from_chars(r.ptr + 1, last, n);
  if (rn.ec != std::errc() || rn.ptr != last || r.ptr + 1 == last) return 0;
  return static_cast<pid_t>(pid);
}

// True unless the system says no process `pid` exists (one of another user is alive).
bool ProcessAlive(pid_t pid) { return ::kill(pid, 0) == 0 || errno != ESRCH; }

// Removes the stale temporary files of `path` and names them in one line on stderr.
void ReportStaleTempFiles(const std::string& path) {
  const std::vector<std::string> removed = RemoveStaleTempFiles(path);
  if (removed.empty()) return;
  std::fprintf(stderr, "removed %zu stale temporary file(s) of processes no longer running: %s\n", removed.size(),
               fmt::format("{}", fmt::join(removed, ", ")).c_str());
}

}  // namespace

std::vector<std::string> RemoveStaleTempFiles(const std::string& path) {
  std::vector<std::string> removed;
  const std::string name = fs::path(path).filename().string();
  if (name.empty()) return removed;
  std::error_code ec;
  for (fs::directory_iterator it(FolderOf(path), ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t pid = TempFileOwner(it->path().filename().string(), name);
    if (pid == 0 || ProcessAlive(pid)) continue;
    std::error_code rm;
    if (fs::remove(it->path(), rm)) removed.push_back((fs::path(path).parent_path() / it->path().filename()).string());
  }
  return removed;
}

std::string TempPathFor(const std::string& path) {
  static std::atomic<int> counter{0};  // distinguishes temp files of one process
  ReportStaleTempFiles(path);
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

bool SameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return ca.lexically_normal() == cb.lexically_normal();
}

void CheckWritableLocation(const std::string& path) {
  if (path.empty()) throw InputError("cannot write '': no file name given");
  const fs::path dir = FolderOf(path);
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    throw InputError("cannot write '" + path + "': folder '" + dir.string() + "' does not exist");
  }
  if (!fs::is_directory(dir, ec)) {
    throw InputError("cannot write '" + path + "': '" + dir.string() + "' is not a folder");
  }
  if (fs::is_directory(path, ec)) throw InputError("cannot write '" + path + "': it is a folder");
  // Create (and remove) a file beside the target: the only test that also catches file
  // systems that refuse new files whatever the permissions say.
  const std::string probe = TempPathFor(path);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    throw InputError("cannot write '" + path + "': cannot create a file in folder '" + dir.string() +
                     "' (" + std::strerror(errno) + ")");
  }
  ::close(fd);
  std::remove(probe.c_str());
}

void CreateOutputFolder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("cannot create output folder '" + dir + "': " + ec.message());
  if (!fs::is_directory(dir, ec)) throw InputError("cannot create output folder '" + dir + "': not a folder");
}

int ReserveFileSpace(const std::string& path, long long size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int status = size > 0 ? ::posix_fallocate(fd, 0, static_cast<off_t>(size)) : 0;
  ::close(fd);
  return status;
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
