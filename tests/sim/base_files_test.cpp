// File output helpers: same-file detection through links, the writable-location check,
// the output folder's creation and the removal of temporary files left by processes that no longer run.

#include "sim/base/files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dead_pid.h"
#include "input_error.h"
#include "sim/base/errors.h"
#include "temp_dir.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

class FilesTest : public ::testing::Test {
 protected:
  tactip::testing::TestTempDir temp_{"files"};
  std::string P(const std::string& name) const { return temp_.File(name); }
  void Touch(const std::string& name) const { std::ofstream(P(name)) << "x"; }

};

using testing::DeadPid;

TEST_F(FilesTest, SameFileSeesThroughLinksAndDotDot) {
  Touch("a.h5");
  Touch("b.h5");
  fs::create_symlink(P("a.h5"), P("sym.h5"));
  fs::create_hard_link(P("a.h5"), P("hard.h5"));
  fs::create_directories(P("sub"));
  EXPECT_TRUE(SameFile(P("a.h5"), P("a.h5")));
  EXPECT_TRUE(SameFile(P("sym.h5"), P("a.h5")));
  EXPECT_TRUE(SameFile(P("a.h5"), P("hard.h5")));
  EXPECT_TRUE(SameFile(P("sub/../a.h5"), P("a.h5")));
  EXPECT_FALSE(SameFile(P("a.h5"), P("b.h5")));
  // Not yet written: compared by the path with links and '..' resolved.
  fs::create_symlink(temp_.path() / "sub", P("link"));
  EXPECT_TRUE(SameFile(P("sub/../new.h5"), P("new.h5")));
  EXPECT_TRUE(SameFile(P("link/new.h5"), P("sub/new.h5")));
  EXPECT_FALSE(SameFile(P("new.h5"), P("sub/new.h5")));
  EXPECT_FALSE(SameFile(P("new.h5"), P("a.h5")));
}

TEST_F(FilesTest, StaleTempFilesOfDeadProcessesAreRemovedOthersKept) {
  const std::string dead = std::to_string(DeadPid()), alive = std::to_string(::getpid());
  for (const std::string& f : {"x.h5.tmp." + dead + ".0", "x.h5.tmp." + dead + ".3", "x.h5.tmp." + alive + ".0",
                               "y.h5.tmp." + dead + ".0", std::string("x.h5.tmp.notes"), "x.h5.tmp." + dead + ".0.bak"}) {
    Touch(f);
  }
  const auto removed = RemoveStaleTempFiles(P("x.h5"));
  EXPECT_EQ(removed.size(), 2u);
  EXPECT_FALSE(fs::exists(P("x.h5.tmp." + dead + ".0")));
  EXPECT_FALSE(fs::exists(P("x.h5.tmp." + dead + ".3")));
  EXPECT_TRUE(fs::exists(P("x.h5.tmp." + alive + ".0"))) << "a running process's temp file";
  EXPECT_TRUE(fs::exists(P("y.h5.tmp." + dead + ".0"))) << "another target's temp file";
  EXPECT_TRUE(fs::exists(P("x.h5.tmp.notes")));
  EXPECT_TRUE(fs::exists(P("x.h5.tmp." + dead + ".0.bak")));
}

TEST_F(FilesTest, WritingAPathRemovesItsStaleTempFilesAndSaysSoOnOneLine) {
  const std::string name = "out.csv.tmp." + std::to_string(DeadPid()) + ".0", stale = P(name);
  Touch(name);
  ::testing::internal::CaptureStderr();
  WriteFileAtomic(P("out.csv"), "a,b\n");
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_NE(err.find("removed 1 stale temporary file(s) of processes no longer running: " + stale), std::string::npos)
      << err;
  EXPECT_EQ(err.find('\n'), err.size() - 1) << "one line: " << err;
  // Nothing stale left: the next write is silent.
  ::testing::internal::CaptureStderr();
  WriteFileAtomic(P("out.csv"), "c,d\n");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(FilesTest, WritableLocationNeedsAFolderThatTakesNewFiles) {
  EXPECT_NO_THROW(CheckWritableLocation(P("ok.h5")));
  EXPECT_FALSE(fs::exists(P("ok.h5")));
  EXPECT_TRUE(fs::is_empty(temp_.path())) << "the probe file is removed";
  auto message = [](const std::string& path) { return InputErrorOf([&] { CheckWritableLocation(path); }); };
  EXPECT_NE(message(P("missing/x.h5")).find("folder '" + P("missing") + "' does not exist"), std::string::npos);
  Touch("file");
  EXPECT_NE(message(P("file/x.h5")).find("'" + P("file") + "' is not a folder"), std::string::npos);
  EXPECT_NE(message(temp_.path().string()).find("it is a folder"), std::string::npos);
  // /proc exists but takes no new files (whoever asks): the system's reason is given.
  const std::string proc = message("/proc/x.h5");
  EXPECT_EQ(proc.rfind("cannot write '/proc/x.h5': cannot create a file in folder '/proc' (", 0), 0u) << proc;
}

TEST_F(FilesTest, OutputFolderIsCreatedWithItsParentsOrRefusedInOneLine) {
  EXPECT_NO_THROW(CreateOutputFolder(P("a/b/c")));
  EXPECT_TRUE(fs::is_directory(P("a/b/c")));
  EXPECT_NO_THROW(CreateOutputFolder(P("a/b/c"))) << "an existing folder is fine";
  auto message = [](const std::string& dir) { return InputErrorOf([&] { CreateOutputFolder(dir); }); };
  Touch("file");
  const std::string on_file = message(P("file"));
  EXPECT_EQ(on_file.rfind("cannot create output folder '" + P("file") + "': ", 0), 0u) << on_file;
  const std::string below_file = message(P("file/sub"));
  EXPECT_EQ(below_file.rfind("cannot create output folder '" + P("file/sub") + "': ", 0), 0u) << below_file;
  EXPECT_EQ(below_file.find('\n'), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(P("file"))) << "the file in the way is left as it was";
}

}  // namespace
}  // namespace tactip
