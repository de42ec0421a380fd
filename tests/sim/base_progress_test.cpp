// Progress lines and the heartbeat that fills their silences.

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "sim/base/progress.h"

namespace tactip {
namespace {

using std::chrono::milliseconds;

TEST(ProgressTest, LinesGoToStderrWholeAndPrintfStyle) {
  ::testing::internal::CaptureStderr();
  Progress("step one");
  ProgressF("step %d of %s\n", 2, "three");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "step one\nstep 2 of three\n");
}

TEST(HeartbeatTest, ASilenceLongerThanTheIntervalIsFilledWithTheLastLine) {
  ::testing::internal::CaptureStderr();
  {
    Heartbeat beat("tactip", milliseconds(100));
    Progress("training svm-rbf");
    std::this_thread::sleep_for(milliseconds(450));
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(err.find("training svm-rbf\n"), 0u) << err;
  EXPECT_NE(err.find("tactip: still working, 0 s since: training svm-rbf\n"), std::string::npos) << err;
  // About one beat per interval of silence, none while lines keep coming.
  const auto beats = [](const std::string& s) {
    size_t n = 0;
    for (size_t at = s.find("still working"); at != std::string::npos; at = s.find("still working", at + 1)) ++n;
    return n;
  };
  EXPECT_GE(beats(err), 1u);
  EXPECT_LE(beats(err), 5u);
  ::testing::internal::CaptureStderr();
  {
    Heartbeat beat("tactip", milliseconds(300));
    for (int i = 0; i < 6; ++i) {
      Progress("run " + std::to_string(i));
      std::this_thread::sleep_for(milliseconds(50));
    }
  }
  EXPECT_EQ(beats(::testing::internal::GetCapturedStderr()), 0u);
}

}  // namespace
}  // namespace tactip
