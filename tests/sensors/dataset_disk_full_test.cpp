// DatasetWriter on a file system that runs out of space at every stage of a file: a one-line
// InputError, no file left behind, and no HDF5 identifier left open (HDF5 1.10 crashes at
// exit when a failed file close leaves one).

#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "input_error.h"
#include "sensors/dataset.h"
#include "small_tmpfs.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

/// Run with T frames and N pins of poorly compressible values.
RunRecord NoisyRun(int index, int t, int n) {
  RunRecord r;
  r.index = index;
  SensorRecord& s = r.sensors.emplace_back();
  s.n_pins = n;
  std::uint32_t state = 12345u + static_cast<std::uint32_t>(index);
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 65536.0f;
  };
  const auto fill = [&](std::vector<float>& v, size_t count) {
    for (size_t k = 0; k < count; ++k) v.push_back(next());
  };
  const size_t tn = static_cast<size_t>(t) * static_cast<size_t>(n);
  for (int i = 0; i < t; ++i) r.time.push_back(0.01 * i);
  r.object_height_m.assign(static_cast<size_t>(t), 0.1);
  s.gross_slip.assign(static_cast<size_t>(t), 0);
  s.incipient.assign(static_cast<size_t>(t), 0);
  fill(s.pos_px, tn * 2);
  fill(s.pos_m, tn * 3);
  fill(s.normal_N, tn);
  fill(s.tangential_N, tn * 2);
  s.valid.assign(tn, 1);
  s.pin_slip.assign(tn, 0);
  s.pin_contact.assign(tn, 1);
  r.attrs["friction_coefficient"] = 0.5;
  return r;
}

/// Bytes still free on the file system of `dir`.
std::uintmax_t FreeBytes(const fs::path& dir) {
  struct statvfs st {};
  if (::statvfs(dir.c_str(), &st) != 0) return 0;
  return static_cast<std::uintmax_t>(st.f_bavail) * st.f_frsize;
}

class DatasetDiskFullTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    tmpfs_ = std::make_unique<testing::SmallTmpfs>(
        fs::temp_directory_path() / ("tactip_disk_full_" + std::to_string(::getpid()) + "_" + info->name()), "256k");
    if (!tmpfs_->mounted()) GTEST_SKIP() << tmpfs_->reason();
  }
  void TearDown() override { tmpfs_.reset(); }

  std::unique_ptr<testing::SmallTmpfs> tmpfs_;
};

TEST_F(DatasetDiskFullTest, RunningOutOfSpaceAnywhereFailsCleanly) {
  const fs::path dir = tmpfs_->dir();
  const std::string path = (dir / "x.h5").string();
  const fs::path filler = dir / "filler";
  DatasetHeader header;
  header.tactip_version = "0.1.0";
  header.scenario = "rail";
  header.config_yaml = "rail: {}\n";
  const std::vector<RunRecord> runs = {NoisyRun(0, 20, 4), NoisyRun(1, 300, 16)};  // ~200 KiB in all
  const std::uintmax_t capacity = FreeBytes(dir);
  ASSERT_GE(capacity, 240u * 1024u);
  // Where the space ran out: creating the file, writing a run, committing; or nowhere.
  enum Stage { kCreate, kWrite, kCommit, kDone };
  int outcomes[4] = {0, 0, 0, 0};
  // Identifiers open before (the HDF5 C++ library, when loaded, holds its predefined types).
  const ssize_t open_before = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  // Leave 0, 4, 8, ... KiB free: the space runs out at a different point of the file each time.
  for (std::uintmax_t free = 0; free + 4096 < capacity; free += 4096) {
    SCOPED_TRACE("free bytes " + std::to_string(free));
    {
      std::ofstream out(filler, std::ios::binary | std::ios::trunc);
      out << std::string(capacity - free, 'x');
      ASSERT_TRUE(out.flush()) << "cannot fill the file system";
    }
    Stage stage = kCreate;
    const std::string msg = InputErrorOf([&] {
      DatasetWriter writer(path, header);
      stage = kWrite;
      for (const RunRecord& run : runs) writer.WriteRun(run);
      stage = kCommit;
      writer.Commit();
      stage = kDone;
    });
    ++outcomes[stage];
    std::vector<std::string> entries;
    for (const auto& e : fs::directory_iterator(dir)) entries.push_back(e.path().filename().string());
    std::sort(entries.begin(), entries.end());
    if (stage == kDone) {
      // It fitted: the file is complete.
      EXPECT_EQ(entries, (std::vector<std::string>{"filler", "x.h5"}));
      EXPECT_EQ(DatasetReader(path).ReadRun(1).sensors.at(0).pos_px, runs[1].sensors[0].pos_px);
    } else {
      // One line naming the dataset and the reason; nothing left but the filler.
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_EQ(msg.rfind("cannot write dataset '" + path + "': ", 0), 0u) << msg;
      EXPECT_NE(msg.find("No space left on device"), std::string::npos) << msg;
      EXPECT_EQ(entries, std::vector<std::string>{"filler"});
    }
    // Every HDF5 identifier closed (a failed file close leaves one, and the library's
    // shutdown at exit then crashes on it).
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), open_before);
    fs::remove(path);
    fs::remove(filler);
  }
  EXPECT_GT(outcomes[kCreate], 0);
  EXPECT_GT(outcomes[kWrite], 0);
  EXPECT_GT(outcomes[kCommit], 0);
  EXPECT_GT(outcomes[kDone], 0);
}

}  // namespace
}  // namespace tactip
