// Test support: simulated runs shared by the test processes of one ctest invocation.
// ctest runs every test in a process of its own, so a run several tests read would be
// simulated again in each; a folder named by TACTIP_TEST_SHARED_RUNS holds it instead.
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>

#include "sensors/dataset.h"

namespace tactip::testing {

/// An exclusive lock on a file, held for the object's lifetime; throws std::runtime_error
/// if the file cannot be opened or locked.
class FileLock {
 public:
  explicit FileLock(const std::filesystem::path& path)
      : fd_(::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw std::runtime_error("cannot open " + path.string() + ": " + std::strerror(errno));
    int rc = 0;
    while ((rc = ::flock(fd_, LOCK_EX)) != 0 && errno == EINTR) {
    }
    if (rc != 0) {
      const std::string reason = std::strerror(errno);
      ::close(fd_);
      throw std::runtime_error("cannot lock " + path.string() + ": " + reason);
    }
  }
  ~FileLock() {
    ::flock(fd_, LOCK_UN);
    ::close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

/// Run `key` (a file-name-safe name of what `simulate` computes). Without the environment
/// variable TACTIP_TEST_SHARED_RUNS this is `simulate()`. With it (ctest sets it for the
/// scenario tests and empties the folder before any of them runs; tests/CMakeLists.txt), the
/// first process to ask simulates and stores the run there as a one-run dataset, under a
/// lock that makes the others wait. Every process, the first included, then reads the stored
/// run back, so all of them test the same data. The dataset round trip is exact
/// (IncipientDatasetTest checks it on a simulated record). One process's file reads and
/// writes are serialised (the simulations still run in parallel).
inline RunRecord SharedRun(const std::string& key, const std::function<RunRecord()>& simulate) {
  const char* folder = std::getenv("TACTIP_TEST_SHARED_RUNS");
  if (folder == nullptr || *folder == '\0') return simulate();
  static std::mutex file_io;
  const std::filesystem::path dir(folder);
  std::filesystem::create_directories(dir);
  const FileLock lock(dir / (key + ".lock"));
  const std::filesystem::path path = dir / (key + ".h5");
  if (!std::filesystem::exists(path)) {
    const RunRecord rec = simulate();
    DatasetHeader header;
    header.tactip_version = "test";
    header.scenario = "shared-test-run";
    const std::lock_guard io(file_io);
    DatasetWriter writer(path.string(), header);
    writer.WriteRun(rec);
    writer.Commit();
  }
  const std::lock_guard io(file_io);
  return DatasetReader(path.string()).ReadRun(0);
}

}  // namespace tactip::testing
