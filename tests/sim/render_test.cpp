#include "sim/render.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "sim/config.h"
#include "sim/png_file.h"
#include "test_display.h"

namespace tactip {
namespace {

// A red box on the left, a blue ball on the right (free, resting on the box's level) and a
// grey floor, seen from the front.
const char* kTwoObjectsXml = R"(
<mujoco>
  <option timestep="0.002"/>
  <worldbody>
    <light pos="0 -1 2" dir="0 0.5 -1"/>
    <geom name="floor" type="plane" size="1 1 0.1" rgba="0.4 0.4 0.4 1"/>
    <body name="box_body" pos="-0.15 0 0.1">
      <geom name="box" type="box" size="0.1 0.1 0.1" rgba="1 0 0 1"/>
    </body>
    <body name="ball_body" pos="0.15 0 0.1">
      <freejoint/>
      <geom name="ball" type="sphere" size="0.1" rgba="0 0 1 1"/>
    </body>
  </worldbody>
</mujoco>)";

// Pixels whose channel `c` (0 red, 1 green, 2 blue) clearly dominates the other two.
int Dominant(const RgbImage& img, int c) {
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const auto p = img.At(x, y);
      n += p[c] > 80 && p[c] > 2 * p[(c + 1) % 3] && p[c] > 2 * p[(c + 2) % 3];
    }
  }
  return n;
}

// Pixels that differ between two images of the same size.
int DifferentPixels(const RgbImage& a, const RgbImage& b) {
  int n = 0;
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  }
  return n;
}

// A substantial part of a 160 x 120 image: the box and the ball each cover far more.
constexpr int kManyPixels = 300;

class RenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!display_.unavailable().empty()) GTEST_SKIP() << display_.unavailable();
    sim_.Forward();
    renderer_ = std::make_unique<SceneRenderer>(model_, 160, 120);
    CameraView view;
    view.distance_m = 1.2;
    view.elevation_deg = -15.0;
    renderer_->SetView(view);
  }

  testing::TestDisplay display_;
  CompiledModel model_ = CompiledModel::FromXml(kTwoObjectsXml);
  Simulation sim_{model_};
  std::unique_ptr<SceneRenderer> renderer_;
};

TEST_F(RenderTest, ImageShowsEachGeomInItsModelColour) {
  const RgbImage img = renderer_->Render(sim_, {});
  ASSERT_EQ(img.width, 160);
  ASSERT_EQ(img.height, 120);
  ASSERT_EQ(img.rgb.size(), 160u * 120u * 3u);
  EXPECT_GT(Dominant(img, 0), kManyPixels);
  EXPECT_GT(Dominant(img, 2), kManyPixels);
  EXPECT_EQ(Dominant(img, 1), 0);
}

TEST_F(RenderTest, ColourOverrideRecoloursOnlyThatGeom) {
  const RgbImage plain = renderer_->Render(sim_, {});
  RenderOptions options;
  options.colours.push_back({model_.GeomId("box"), PinColours::kStick});
  const RgbImage green = renderer_->Render(sim_, options);
  EXPECT_EQ(Dominant(green, 0), 0);
  EXPECT_GT(Dominant(green, 1), kManyPixels);
  EXPECT_EQ(Dominant(green, 2), Dominant(plain, 2));
}

TEST_F(RenderTest, HiddenGeomIsLeftOut) {
  const RgbImage plain = renderer_->Render(sim_, {});
  RenderOptions options;
  options.hidden_geoms.push_back(model_.GeomId("ball"));
  const RgbImage hidden = renderer_->Render(sim_, options);
  EXPECT_EQ(Dominant(hidden, 2), 0);
  EXPECT_EQ(Dominant(hidden, 0), Dominant(plain, 0));
}

TEST_F(RenderTest, ContactForcesAddArrowsWhereTheBallTouchesTheFloor) {
  // Let the ball settle on the floor, then compare frames with and without the arrows (the
  // ball hidden: its contact force arrow points into it).
  for (int i = 0; i < 50; ++i) sim_.Step();
  ASSERT_GT(sim_.ContactCount(), 0);
  RenderOptions options;
  options.hidden_geoms.push_back(model_.GeomId("ball"));
  options.force_scale_m_N = 0.005;  // 0.2 m for the ball's weight
  const RgbImage plain = renderer_->Render(sim_, options);
  options.contact_forces = true;
  const RgbImage arrows = renderer_->Render(sim_, options);
  EXPECT_GT(DifferentPixels(plain, arrows), 50);
}

TEST_F(RenderTest, CameraFollowsTheChosenBody) {
  // Looking at the ball puts it in the middle of the image, the box off to the left.
  CameraView view;
  view.look_at_bodies = {model_.BodyId("ball_body")};
  view.distance_m = 1.0;
  view.elevation_deg = 0.0;
  renderer_->SetView(view);
  const RgbImage img = renderer_->Render(sim_, {});
  const auto centre = img.At(img.width / 2, img.height / 2);
  EXPECT_GT(centre[2], 2 * centre[0]) << "centre pixel " << int(centre[0]) << "," << int(centre[1]) << "," << int(centre[2]);
  const auto left = img.At(img.width / 8, img.height / 2);
  EXPECT_GT(left[0], 2 * left[2]) << "left pixel " << int(left[0]) << "," << int(left[1]) << "," << int(left[2]);
}

TEST_F(RenderTest, PngRoundTripKeepsEveryPixel) {
  const RgbImage img = renderer_->Render(sim_, {});
  const auto path = std::filesystem::temp_directory_path() / ("tactip_render_" + std::to_string(::getpid()) + ".png");
  SavePng(img, path.string());
  const RgbImage back = ReadPng(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(back.width, img.width);
  EXPECT_EQ(back.height, img.height);
  EXPECT_EQ(back.rgb, img.rgb);
}

TEST(RenderInputTest, ImageSideOutOfRangeIsRefusedBeforeAnyWindowOpens) {
  const auto model = CompiledModel::FromXml(kTwoObjectsXml);
  try {
    SceneRenderer renderer(model, 8, 100);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "image width = 8: must be in [16, 4096] pixels");
  }
}

TEST(RenderInputTest, NoDisplayIsAOneLineInputError) {
  // Without DISPLAY GLFW cannot open a window.
  const char* old = std::getenv("DISPLAY");
  const std::string saved = old ? old : "";
  ::unsetenv("DISPLAY");
  const auto model = CompiledModel::FromXml(kTwoObjectsXml);
  std::string message;
  try {
    SceneRenderer renderer(model, 64, 64);
  } catch (const InputError& e) {
    message = e.what();
  }
  if (old) ::setenv("DISPLAY", saved.c_str(), 1);
  EXPECT_EQ(message, "no display: run under xvfb-run or set DISPLAY");
}

TEST(RenderInputTest, PngIntoAMissingFolderIsRefusedWithThePath) {
  RgbImage img;
  img.width = img.height = 4;
  img.rgb.assign(4 * 4 * 3, 128);
  const std::string path = "/nonexistent_tactip_dir/out.png";
  try {
    SavePng(img, path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(RenderInputTest, ReadingAFileThatIsNotAnImageIsRefusedWithThePath) {
  const auto path = std::filesystem::temp_directory_path() / ("tactip_not_png_" + std::to_string(::getpid()) + ".png");
  { std::ofstream(path) << "not an image"; }
  try {
    ReadPng(path.string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": missing or not an image file");
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace tactip
