// tactip track: the blob pipeline on a folder of PNG frames, written as a pin CSV; and the
// one-line refusals of bad input (exit 2, nothing written).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "tests/scenarios/cli_helpers.h"
#include "detectors/pin_csv.h"
#include "dome_tips.h"
#include "sensors/tactile_image.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::CliFolderTest;

constexpr int kTrackFrames = 5;
constexpr double kStepM = 40e-6;     // tips move 40 um along y per frame (~0.5 px)
constexpr double kTrackWithinPx = 1.0;    // every tracked pin this close to its projected truth

class TrackCliTest : public CliFolderTest {
 protected:
  // Renders kTrackFrames frames of the dome pattern moving along y into folder `name`.
  std::string WriteFrames(const std::string& name) {
    const std::string dir = P(name);
    fs::create_directories(dir);
    const CameraConfig camera;
    TactileImageRenderer renderer(TactileImageConfig{}, camera, 9);
    for (int f = 0; f < kTrackFrames; ++f) {
      const std::vector<float> pos_m = DomeTips(6, f * kStepM);
      cv::imwrite(dir + "/frame_" + std::to_string(100 + f) + ".png", renderer.Render(ProjectTips(camera, pos_m), pos_m));
    }
    return dir;
  }
  // Expects a one-line refusal with exit code 2 mentioning `fragment`, and no pins.csv.
  void ExpectRefused(const std::string& args, const std::string& fragment) {
    const auto r = Run("track " + args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(P("pins.csv")));
  }
};

TEST_F(TrackCliTest, RenderedFramesAreTrackedIntoAPinCsvInTheSimulatorsPinOrder) {
  const std::string dir = WriteFrames("frames");
  const auto r = Run("track --images " + dir + " --out " + P("pins.csv") + " --fps 50");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<PinFrame> frames = ReadPinCsv(P("pins.csv"));
  ASSERT_EQ(frames.size(), static_cast<size_t>(kTrackFrames));
  for (int f = 0; f < kTrackFrames; ++f) {
    EXPECT_DOUBLE_EQ(frames[f].time_s, f / 50.0);
    const std::vector<float> truth = ProjectTips(CameraConfig{}, DomeTips(6, f * kStepM));
    ASSERT_EQ(frames[f].size(), 127);
    for (int i = 0; i < 127; ++i) {
      EXPECT_EQ(frames[f].valid[i], 1);
      EXPECT_LT(std::hypot(frames[f].pos_px(i, 0) - truth[2 * i], frames[f].pos_px(i, 1) - truth[2 * i + 1]),
                kTrackWithinPx)
          << "frame " << f << " pin " << i;
    }
  }
}

TEST_F(TrackCliTest, AMissingFolderIsRefused) {
  ExpectRefused("--images " + P("nope") + " --out " + P("pins.csv"), "--images '" + P("nope") + "': no such folder");
}

TEST_F(TrackCliTest, AFolderWithoutPngsIsRefused) {
  fs::create_directories(P("empty"));
  std::ofstream(P("empty/notes.txt")) << "x";
  ExpectRefused("--images " + P("empty") + " --out " + P("pins.csv"), "holds no PNG frames");
}

TEST_F(TrackCliTest, AnUnreadablePngIsRefused) {
  const std::string dir = WriteFrames("frames");
  std::ofstream(dir + "/frame_999.png") << "not a png";
  ExpectRefused("--images " + dir + " --out " + P("pins.csv"), "frame_999.png' cannot be read as a PNG image");
}

TEST_F(TrackCliTest, FramesOfDifferentSizesAreRefused) {
  const std::string dir = WriteFrames("frames");
  cv::imwrite(dir + "/frame_999.png", cv::Mat(100, 100, CV_8UC1, cv::Scalar(0)));
  ExpectRefused("--images " + dir + " --out " + P("pins.csv"), "frame_999.png' is 100 x 100 px, but the first frame");
}

TEST_F(TrackCliTest, AFirstFrameWithoutBlobsIsRefused) {
  fs::create_directories(P("dark"));
  cv::imwrite(P("dark/a.png"), cv::Mat(480, 640, CV_8UC1, cv::Scalar(10)));
  ExpectRefused("--images " + P("dark") + " --out " + P("pins.csv"), "a.png' (the first frame) shows no blobs");
}

TEST_F(TrackCliTest, AnOutputThatIsAnInputFrameIsRefused) {
  const std::string dir = WriteFrames("frames");
  const auto before = fs::file_size(dir + "/frame_100.png");
  ExpectRefused("--images " + dir + " --out " + dir + "/frame_100.png", "--out");
  EXPECT_EQ(fs::file_size(dir + "/frame_100.png"), before);
}

}  // namespace
}  // namespace tactip
