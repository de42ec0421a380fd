#include "sim/viewer_window.h"

#include <gtest/gtest.h>

#include <string>

#include "sim/config.h"
#include "test_display.h"

namespace tactip {
namespace {

const char* kBallXml = "<mujoco><worldbody><body><freejoint/><geom type='sphere' size='0.1'/></body></worldbody></mujoco>";

TEST(ViewerWindowTest, OpensAVisibleWindowOnTheDisplay) {
  testing::TestDisplay display;
  if (!display.unavailable().empty()) GTEST_SKIP() << display.unavailable();
  const auto model = CompiledModel::FromXml(kBallXml);
  EXPECT_NO_THROW(ViewerWindow(model, 320, 240, "test"));
}

TEST(ViewerWindowTest, WindowSizeOutOfRangeIsRefusedInOneLine) {
  const auto model = CompiledModel::FromXml(kBallXml);
  try {
    ViewerWindow window(model, 320, 10000, "test");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "window height = 10000: must be in [16, 4096] pixels");
  }
}

}  // namespace
}  // namespace tactip
