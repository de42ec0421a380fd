// The rendered tactile image and the blob pipeline, on synthetic pin patterns.

#include "sensors/tactile_image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "sensors/blob_tracker.h"
#include "sensors/dataset.h"
#include "sensors/image_pipeline.h"
#include "sensors/run_recorder.h"
#include "dome_tips.h"
#include "input_error.h"

namespace tactip {
namespace {

constexpr double kWithinPx = 1.0;       // the acceptance radius of a detected pin
constexpr double kAreaTolerance = 0.15; // drawn disc area against pi r^2
constexpr double kGreyTolerance = 12.0; // grey levels: noise (2) and blur at a disc's centre

// One pin at `p` (sensor frame, m) on an otherwise empty image.
cv::Mat RenderOne(const TactileImageConfig& cfg, const std::array<float, 3>& p, std::uint64_t seed = 1) {
  const CameraConfig camera;
  const std::vector<float> pos_m(p.begin(), p.end());
  TactileImageRenderer renderer(cfg, camera, seed);
  return renderer.Render(ProjectTips(camera, pos_m), pos_m).clone();
}

TEST(TactileImageTest, TipRadiusIsThePhysicalRadiusProjectedThroughTheCamera) {
  CameraConfig camera;
  camera.fx_px = 600.0;
  camera.fy_px = 560.0;
  EXPECT_DOUBLE_EQ(TipRadiusPx(camera, 0.5, 0.04), 580.0 * 0.5e-3 / 0.04);
}

TEST(TactileImageTest, APinIsABrightDiscOfItsProjectedRadiusOnTheDarkSkin) {
  TactileImageConfig cfg;
  const CameraConfig camera;
  const cv::Mat image = RenderOne(cfg, {0.018f, 0.0f, 0.0f});
  ASSERT_EQ(image.type(), CV_8UC1);
  ASSERT_EQ(image.cols, camera.width_px);
  ASSERT_EQ(image.rows, camera.height_px);
  EXPECT_NEAR(image.at<std::uint8_t>(240, 320), cfg.pin_grey, kGreyTolerance);
  EXPECT_NEAR(image.at<std::uint8_t>(20, 20), cfg.skin_grey, kGreyTolerance);
  // Pixels above the half-way grey cover the disc: pi r^2.
  const double r = TipRadiusPx(camera, cfg.pin_tip_radius_mm, 0.018 + camera.camera_offset_mm * 1e-3);
  const double bright = cv::countNonZero(image > 0.5 * (cfg.pin_grey + cfg.skin_grey));
  EXPECT_NEAR(bright / (std::numbers::pi * r * r), 1.0, kAreaTolerance);
}

TEST(TactileImageTest, APinTowardsTheRimIsDimmerThanOneOnTheAxis) {
  TactileImageConfig cfg;
  cfg.noise_grey = 0.0;
  const cv::Mat centre = RenderOne(cfg, {0.018f, 0.0f, 0.0f});
  const cv::Mat rim = RenderOne(cfg, {0.009f, 0.015f, 0.0f});
  const auto uv = PinholeCamera(CameraConfig{}).Project({0.009, 0.015, 0.0});
  const double rim_grey = rim.at<std::uint8_t>(static_cast<int>(std::lround(uv[1])), static_cast<int>(std::lround(uv[0])));
  EXPECT_LT(rim_grey, centre.at<std::uint8_t>(240, 320) - 10.0);
  EXPECT_GT(rim_grey, cfg.skin_grey + 50.0);
}

TEST(TactileImageTest, TheSameSeedGivesTheSameImageAndAnotherSeedOtherNoise) {
  const TactileImageConfig cfg;
  const cv::Mat a = RenderOne(cfg, {0.018f, 0.0f, 0.0f}, 7), b = RenderOne(cfg, {0.018f, 0.0f, 0.0f}, 7);
  const cv::Mat c = RenderOne(cfg, {0.018f, 0.0f, 0.0f}, 8);
  EXPECT_EQ(cv::countNonZero(a != b), 0);
  EXPECT_GT(cv::countNonZero(a != c), 1000);
}

TEST(TactileImageTest, RenderRefusesPositionsAndTipsOfDifferentCounts) {
  TactileImageRenderer renderer(TactileImageConfig{}, CameraConfig{}, 1);
  EXPECT_THROW(renderer.Render({320.0f, 240.0f}, {0.018f, 0.0f}), std::invalid_argument);
}

TEST(TactileImageTest, TipsCutByTheBorderAreNotInTheImage) {
  const CameraConfig camera;
  EXPECT_TRUE(TipInImage(camera, 0.5, {0.018, 0.0, 0.0}));
  EXPECT_FALSE(TipInImage(camera, 0.5, {0.0, 0.0, 0.0157}));  // v ~ 3 px: its 7.5 px disc crosses the top edge
  EXPECT_FALSE(TipInImage(camera, 0.5, {-0.03, 0.0, 0.0}));   // behind the camera
}

TEST(TactileImageConfigTest, RulesNameTheKeyAndTheBound) {
  TactileImageConfig c;
  c.threshold_max = 80.0;
  EXPECT_EQ(InputErrorOf([&] { c.ValidateRules(); }),
            "images.threshold_max = 80: must be > images.threshold_min + images.threshold_step = 92 (a blob must "
            "show at two thresholds)");
  c = TactileImageConfig{};
  c.max_blob_area_px = 10.0;
  EXPECT_EQ(InputErrorOf([&] { c.ValidateRules(); }), "images.max_blob_area_px = 10: must be > images.min_blob_area_px = 12");
  c = TactileImageConfig{};
  c.pin_grey = 20.0;
  EXPECT_EQ(InputErrorOf([&] { c.ValidateRules(); }),
            "images.pin_grey = 20: must be > images.skin_grey = 25 (white markers on a dark skin)");
  EXPECT_NO_THROW(TactileImageConfig{}.ValidateRules());
}

TEST(BlobPipelineTest, RecoversEveryPinOfARenderedDomeWithin1Px) {
  const CameraConfig camera;
  const std::vector<float> pos_m = DomeTips(6);
  const std::vector<float> px = ProjectTips(camera, pos_m);
  SensorImagePipeline pipeline(TactileImageConfig{}, camera, 3);
  const ImageReading& r = pipeline.Capture(px, pos_m);
  ASSERT_EQ(r.detected_valid.size(), 127u);
  for (size_t i = 0; i < 127; ++i) {
    EXPECT_EQ(r.detected_valid[i], 1) << "pin " << i;
    EXPECT_LT(std::hypot(r.detected_px[2 * i] - px[2 * i], r.detected_px[2 * i + 1] - px[2 * i + 1]), kWithinPx)
        << "pin " << i;
  }
}

TEST(PinTrackerTest, APinTakesTheNearestBlobWithinTheGate) {
  PinTracker tracker({{100.0f, 100.0f}, {200.0f, 100.0f}}, 10.0);
  tracker.Update({{203.0f, 101.0f}, {104.0f, 100.0f}, {108.0f, 100.0f}});
  EXPECT_EQ(tracker.positions()[0], cv::Point2f(104.0f, 100.0f));
  EXPECT_EQ(tracker.positions()[1], cv::Point2f(203.0f, 101.0f));
  EXPECT_EQ(tracker.valid(), (std::vector<std::uint8_t>{1, 1}));
}

TEST(PinTrackerTest, APinWithoutABlobInTheGateKeepsItsPositionAndIsNotValid) {
  PinTracker tracker({{100.0f, 100.0f}, {200.0f, 100.0f}}, 10.0);
  tracker.Update({{111.0f, 100.0f}, {201.0f, 100.0f}});
  EXPECT_EQ(tracker.positions()[0], cv::Point2f(100.0f, 100.0f));
  EXPECT_EQ(tracker.valid(), (std::vector<std::uint8_t>{0, 1}));
  // Found again once a blob is back within the gate.
  tracker.Update({{105.0f, 100.0f}});
  EXPECT_EQ(tracker.positions()[0], cv::Point2f(105.0f, 100.0f));
  EXPECT_EQ(tracker.valid(), (std::vector<std::uint8_t>{1, 0}));
}

TEST(NumberPinsTest, ShuffledBlobsOfAConcentricPatternComeBackInTheSimulatorsPinOrder) {
  const std::vector<float> px = ProjectTips(CameraConfig{}, DomeTips(6));
  std::vector<cv::Point2f> blobs;
  for (size_t i = 0; i + 1 < px.size(); i += 2) blobs.emplace_back(px[i], px[i + 1]);
  std::vector<cv::Point2f> shuffled = blobs;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
  EXPECT_EQ(NumberPins(shuffled), blobs);
}

TEST(ImageFramesTest, AFrameRoundTripsAndAStreamOfAnotherSizeIsRefused) {
  std::vector<std::uint8_t> pixels(640 * 4);
  for (size_t k = 0; k < pixels.size(); ++k) pixels[k] = static_cast<std::uint8_t>(k * 7);
  const CompressedFrame z = CompressFrame(pixels.data(), pixels.size());
  EXPECT_EQ(DecompressFrame(z, pixels.size()), pixels);
  EXPECT_EQ(InputErrorOf([&] { DecompressFrame(z, 100); }), "an image frame is not a zlib stream of 100 pixels");
}

TEST(RunRecorderImagesTest, ImagesOfTheWrongPinCountAreRefusedAndRecordNothing) {
  RunRecord rec;
  RunRecorder recorder(rec, 0, {{"tactip", 2}}, {}, 4);
  ImageReading r;
  r.image = CompressFrame(std::vector<std::uint8_t>(16, 5).data(), 16);
  r.detected_px = {1.0f, 2.0f};
  r.detected_valid = {1};
  EXPECT_THROW(recorder.Images(0, r, 4, 4), std::logic_error);
  EXPECT_THROW(recorder.Images(1, r, 4, 4), std::logic_error);
  EXPECT_TRUE(rec.sensors[0].images.empty());
}

}  // namespace
}  // namespace tactip
