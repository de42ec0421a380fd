// The viewer's rail scene and `tactip view`: the screenshot shows the sensor and the object,
// and bad options are refused before anything is built or written.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "tests/scenarios/cli_helpers.h"
#include "tests/scenarios/png_check.h"
#include "scenarios/app/viewer/rail_view_source.h"
#include "scenarios/registry.h"
#include "sim/png_file.h"
#include "sim/render.h"
#include "test_display.h"

namespace tactip {
namespace {

constexpr int kWidth = 320, kHeight = 240;
// A part of the image no smaller than the object or the pins cover at this size.
constexpr int kSubstantialPixels = 500;
// A part of the image the pins in contact cover at this size, seen from the side.
constexpr int kSomePinsPixels = 50;

// Pixels that differ between two images of the same size.
int DifferentPixels(const RgbImage& a, const RgbImage& b) {
  int n = 0;
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  }
  return n;
}

// Distinct colours in the image (a blank image has one).
int DistinctColours(const RgbImage& img) {
  std::vector<bool> seen(1 << 24, false);
  int n = 0;
  for (size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
    const int key = (img.rgb[i] << 16) | (img.rgb[i + 1] << 8) | img.rgb[i + 2];
    if (!seen[key]) {
      seen[key] = true;
      ++n;
    }
  }
  return n;
}

// Pixels of the stick colour (green clearly over red and blue).
int GreenPixels(const RgbImage& img) {
  int n = 0;
  for (size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
    const int r = img.rgb[i], g = img.rgb[i + 1], b = img.rgb[i + 2];
    n += g > r + 40 && g > b + 40;
  }
  return n;
}

// Pixels of the object's orange (red over green over blue, clearly).
int OrangePixels(const RgbImage& img) {
  int n = 0;
  for (size_t i = 0; i + 2 < img.rgb.size(); i += 3) {
    const int r = img.rgb[i], g = img.rgb[i + 1], b = img.rgb[i + 2];
    n += r > 60 && r > g + 15 && g > b + 15;
  }
  return n;
}

class RailViewTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!display_.unavailable().empty()) GTEST_SKIP() << display_.unavailable();
    source_ = std::make_unique<RailViewSource>(RailFamily(FindScenario("rail")).Load({}), 0, 1);
    renderer_ = std::make_unique<SceneRenderer>(source_->model(), kWidth, kHeight);
    renderer_->SetView(source_->Camera());
  }
  RgbImage Render(const std::vector<int>& hidden) {
    RenderOptions options;
    options.colours = source_->Colours();
    options.hidden_geoms = hidden;
    return renderer_->Render(source_->sim(), options);
  }

  testing::TestDisplay display_;
  std::unique_ptr<RailViewSource> source_;
  std::unique_ptr<SceneRenderer> renderer_;
};

TEST_F(RailViewTest, FrameShowsTheObjectAndTheSensorPins) {
  const RgbImage all = Render({});
  EXPECT_GT(DistinctColours(all), 50);
  // Leaving the object out, or the pins, changes a substantial part of the frame.
  EXPECT_GT(DifferentPixels(all, Render({source_->object_geom()})), kSubstantialPixels);
  ASSERT_FALSE(source_->pin_geoms().empty());
  EXPECT_GT(DifferentPixels(all, Render(source_->pin_geoms())), kSubstantialPixels);
}

TEST_F(RailViewTest, PinsAreDrawnInTheNoContactGrey) {
  // Recolouring the pins green turns many grey pixels green.
  const RgbImage grey = Render({});
  RenderOptions options;
  for (int g : source_->pin_geoms()) options.colours.push_back({g, PinColours::kStick});
  const RgbImage green = renderer_->Render(source_->sim(), options);
  EXPECT_GT(DifferentPixels(grey, green), kSubstantialPixels);
}

TEST_F(RailViewTest, AdvanceToStepsTheSceneToTheGivenTime) {
  source_->AdvanceTo(0.01);
  EXPECT_GE(source_->time(), 0.01);
  EXPECT_LT(source_->time(), 0.01 + source_->model().timestep());
}

class ViewCliTest : public testing::CliFolderTest {};

TEST_F(ViewCliTest, ScreenshotShowsTheObjectAndIsWrittenAsPng) {
  testing::TestDisplay display;
  if (!display.unavailable().empty()) GTEST_SKIP() << display.unavailable();
  // In the hold: the object lifted, pressed by the sensor, pins in contact sticking.
  const auto r = Run("view rail --screenshot " + P("rail.png") + " --width 320 --height 240 --time 5.2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("wrote " + P("rail.png") + " (320 x 240 px, t = 5.2"), std::string::npos) << r.err;
  const RgbImage img = ReadPng(P("rail.png"));
  EXPECT_EQ(img.width, 320);
  EXPECT_EQ(img.height, 240);
  EXPECT_GT(DistinctColours(img), 50);
  EXPECT_GT(OrangePixels(img), kSubstantialPixels);
  EXPECT_GT(GreenPixels(img), kSomePinsPixels);
  EXPECT_EQ(testing::TempFilesIn(dir_), 0);
}

TEST_F(ViewCliTest, ScreenshotShowsAStoredRunReplayedExactly) {
  testing::TestDisplay display;
  if (!display.unavailable().empty()) GTEST_SKIP() << display.unavailable();
  const auto g = Run("generate rail --runs 2 --seed 4 --jobs 1 --quiet --set rail.lift_mm=5 "
                     "--set rail.retract_speed_mm_s=5 --out " + P("d.h5"));
  ASSERT_EQ(g.code, 0) << g.err;
  // Run 1 in its hold (3.1 s to 3.6 s).
  const auto r = Run("view --replay " + P("d.h5") + " --run 1 --screenshot " + P("replay.png") +
                     " --width 320 --height 240 --time 3.4");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("replay of run 1 of " + P("d.h5") + " up to t = 3.4"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": largest pos_px difference from the stored run: 0 px over 341 frames\n"), std::string::npos)
      << r.err;
  const RgbImage img = ReadPng(P("replay.png"));
  EXPECT_GT(OrangePixels(img), kSubstantialPixels);
  EXPECT_GT(GreenPixels(img), kSomePinsPixels);
}

TEST_F(ViewCliTest, ScreenshotShowsNothingAfterTheRunHasEnded) {
  testing::TestDisplay display;
  if (!display.unavailable().empty()) GTEST_SKIP() << display.unavailable();
  // The object falls about 4 s in; the protocol would give up at 5.6 s.
  const auto r = Run("view rail --set rail.lift_mm=5 --speed-mm-s 5 --time 5 --screenshot " + P("late.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("tactip: --time = 5: run 0 (seed 1) ended at t = 4.", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

TEST_F(ViewCliTest, WithoutADisplayTheScreenshotIsRefusedInOneLine) {
  const char* old = std::getenv("DISPLAY");
  const std::string saved = old ? old : "";
  ::unsetenv("DISPLAY");
  const auto r = Run("view rail --screenshot " + P("rail.png"));
  if (old) ::setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "tactip: no display: run under xvfb-run or set DISPLAY\n");
  EXPECT_FALSE(std::filesystem::exists(P("rail.png")));
}

TEST_F(ViewCliTest, BadOptionsAreRefusedBeforeTheSceneIsBuilt) {
  // Each one line naming the option and what it allows; nothing written.
  const std::pair<std::string, std::string> cases[] = {
      {"--screenshot " + P("rail.jpg"), "tactip: --screenshot " + P("rail.jpg") + ": must name a .png file\n"},
      {"--screenshot ''", "tactip: --screenshot: must name a .png file (see --help)\n"},
      {"--screenshot " + P("rail.png") + " --time -1", "tactip: --time = -1: must be in [0, 600] s\n"},
      {"--screenshot " + P("rail.png") + " --time nan", "tactip: --time = nan: must be in [0, 600] s\n"},
      {"--screenshot " + P("rail.png") + " --width 8", "tactip: --width = 8: must be in [16, 4096] pixels\n"},
      {"--screenshot " + P("rail.png") + " --height 5000", "tactip: --height = 5000: must be in [16, 4096] pixels\n"},
      {"--screenshot " + P("rail.png") + " --run 100000", "tactip: --run: Value 100000 not in range 0 to 99999 (see --help)\n"},
      {"--screenshot " + P("rail.png") + " --seed -1",
       "tactip: --seed: '-1': must be a whole number from 0 to 18446744073709551615 (see --help)\n"},
      {"--screenshot " + P("rail.png") + " --stimulus round",
       "tactip: rail.stimulus = 'round': must be one of flat, acrylic, curved80, curved40, curved20\n"},
      {"--screenshot " + P("rail.png") + " --skin rough",
       "tactip: --skin 'rough': unknown skin (known: smooth, fingerprint-v1, fingerprint-v2)\n"},
      {"--screenshot " + P("rail.png") + " --speed-mm-s 0", "tactip: rail.retract_speed_mm_s = 0: must be > 0\n"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = Run("view rail " + args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, message) << args;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

TEST_F(ViewCliTest, ATimeAfterTheProtocolGivesUpIsRefusedBeforeSimulating) {
  // Run 0 of the default config presses 4.98 mm, retracts at 0.1 mm/s and gives up 5 mm
  // past the press.
  const auto r = Run("view rail --time 500 --screenshot " + P("rail.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "tactip: --time = 500: run 0 (seed 1) ends by t = 105.277 s; choose a time in [0, 105.277] s\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

TEST_F(ViewCliTest, ScreenshotIntoAMissingFolderIsRefusedWithThePath) {
  const std::string path = P("no_such_folder/rail.png");
  const auto r = Run("view rail --screenshot " + path);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST_F(ViewCliTest, UnknownScenarioIsRefused) {
  const auto r = Run("view nonsense --screenshot " + P("x.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nonsense"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tactip
