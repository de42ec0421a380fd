// tactip track: the blob pipeline on a folder of PNG frames, written as a pin CSV; and the
// one-line refusals of bad input (exit 2, nothing written).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/scenarios/cli_helpers.h"
#include "detectors/pin_csv.h"
#include "dome_tips.h"
#include "sensors/tactile_image.h"
#include "tests/hex_pattern.h"

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
  ExpectRefused("--images " + P("dark") + " --out " + P("pins.csv"), "a.png' (the first frame) shows no marker-like blobs");
}

TEST_F(TrackCliTest, AnOutputThatIsAnInputFrameIsRefused) {
  const std::string dir = WriteFrames("frames");
  const auto before = fs::file_size(dir + "/frame_100.png");
  ExpectRefused("--images " + dir + " --out " + dir + "/frame_100.png", "--out");
  EXPECT_EQ(fs::file_size(dir + "/frame_100.png"), before);
}

// Frames made to look like a real 127-pin TacTip's (real-sensor.md section 1): 640 x 480, the
// outer ring at 131 px, white markers of 16-61 px on black, a bright rim around the pattern,
// pressed over kPressFrames frames: the markers move outward, the central ones shrink to a few
// px, and three pairs of neighbours close up until they merge in the deepest frames.
constexpr int kPressFrames = 30;
constexpr double kPitchPx = 131.0 / 6.0;

struct RealLikeSequence {
  std::vector<std::vector<cv::Point2f>> truth;  // per frame, per pattern pin
  std::vector<std::vector<bool>> merged;        // per frame, per pin: touching its pair's marker
  std::vector<std::vector<float>> gap;          // per frame, per pin: half the distance to its pair (0: none)
};

// Marker radius of pin i at press fraction a: 2.3-4.4 px by a fixed pattern (areas 16-61 px),
// the central ones shrinking to a third of their area at full press.
double MarkerRadius(size_t i, double r_px, double a) {
  const double base = 2.3 + 2.1 * static_cast<double>((i * 37) % 11) / 10.0;
  return r_px < 2.5 * kPitchPx ? base * std::sqrt(1.0 - 0.67 * a) : base;
}

// Pin i of the pattern at press fraction `a` (0..1); pairs (j, k) listed in `pairs` close up.
RealLikeSequence RealLikeTruth(const std::vector<float>& hex, const std::vector<std::pair<int, int>>& pairs) {
  RealLikeSequence seq;
  const size_t n = hex.size() / 2;
  for (int f = 0; f < kPressFrames; ++f) {
    const double a = static_cast<double>(f) / (kPressFrames - 1);
    std::vector<cv::Point2f> pts(n);
    for (size_t i = 0; i < n; ++i) {
      const double du = hex[2 * i] - 320.0, dv = hex[2 * i + 1] - 240.0, r = std::hypot(du, dv);
      // Outward by up to 7 px at mid-radius (the press field's shape, roughly).
      const double out = 7.0 * a * std::sin(std::min(r / 131.0, 1.0) * 3.14159);
      const double s = r > 0.0 ? (r + out) / r : 1.0;
      pts[i] = cv::Point2f(static_cast<float>(320.0 + s * du), static_cast<float>(240.0 + s * dv));
    }
    std::vector<bool> merged(n, false);
    std::vector<float> gap(n, 0.0f);
    for (const auto& [j, k] : pairs) {
      // The pair's gap closes to 6 px at full press: their discs touch over the last frames.
      const cv::Point2f mid = 0.5f * (pts[j] + pts[k]), half = 0.5f * (pts[k] - pts[j]);
      const float len = std::hypot(half.x, half.y), want = static_cast<float>(len - a * (len - 3.0));
      pts[j] = mid - half * (want / len);
      pts[k] = mid + half * (want / len);
      gap[j] = gap[k] = want;
      // Within 3 px of touching: the drawn, binarised discs may already have joined into one
      // blob, which both pins then share.
      const auto radius = [&](int i) { return MarkerRadius(static_cast<size_t>(i), std::hypot(pts[i].x - 320.0, pts[i].y - 240.0), a); };
      merged[j] = merged[k] = 2.0 * want < radius(j) + radius(k) + 3.0;
    }
    seq.truth.push_back(pts);
    seq.merged.push_back(merged);
    seq.gap.push_back(gap);
  }
  return seq;
}

// Writes the frames: `style` binary (0/255), grey (blurred, noisy) or inverted (black on white).
void WriteRealLike(const std::string& dir, const RealLikeSequence& seq, const std::string& style) {
  fs::create_directories(dir);
  cv::RNG rng(7);
  for (int f = 0; f < kPressFrames; ++f) {
    const double a = static_cast<double>(f) / (kPressFrames - 1);
    cv::Mat img(480, 640, CV_8UC1, cv::Scalar(style == "grey" ? 40 : 0));
    const int fg = style == "grey" ? 210 : 255;
    cv::circle(img, {320, 240}, 158, cv::Scalar(fg), 12, cv::LINE_8);  // the bright rim
    for (size_t i = 0; i < seq.truth[f].size(); ++i) {
      const cv::Point2f p = seq.truth[f][i];
      const double r = std::hypot(p.x - 320.0, p.y - 240.0);
      // Sub-pixel discs: drawn at 16x and shifted.
      cv::circle(img, cv::Point(static_cast<int>(std::lround(p.x * 16)), static_cast<int>(std::lround(p.y * 16))),
                 static_cast<int>(std::lround(MarkerRadius(i, r, a) * 16)), cv::Scalar(fg), cv::FILLED, cv::LINE_AA, 4);
    }
    if (style == "grey") {
      cv::GaussianBlur(img, img, {0, 0}, 0.8);
      cv::Mat noise(img.size(), CV_8UC1);
      rng.fill(noise, cv::RNG::NORMAL, 0, 6);
      img += noise;
    } else {
      cv::threshold(img, img, 127, 255, cv::THRESH_BINARY);
    }
    if (style == "inverted") img = 255 - img;
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%03d.png", f);
    cv::imwrite(dir + name, img);
  }
}

TEST_F(TrackCliTest, RealLookingPressedFramesAreTrackedWithSettingsFromTheFrames) {
  const std::vector<float> hex = testing::HexPattern(6, kPitchPx);
  // Three neighbour pairs at ~3 pitches from the centre, each pin with its right-hand neighbour,
  // no pin in two pairs.
  std::vector<std::pair<int, int>> pairs;
  std::vector<bool> used(hex.size() / 2, false);
  for (size_t i = 0; i < hex.size() / 2 && pairs.size() < 3; ++i) {
    const double r = std::hypot(hex[2 * i] - 320.0, hex[2 * i + 1] - 240.0);
    if (used[i] || r < 2.8 * kPitchPx || r > 3.2 * kPitchPx) continue;
    for (size_t j = 0; j < hex.size() / 2; ++j) {
      if (!used[j] && std::abs(hex[2 * j + 1] - hex[2 * i + 1]) < 0.1 && std::abs(hex[2 * j] - hex[2 * i] - kPitchPx) < 0.1) {
        pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
        used[i] = used[j] = true;
        break;
      }
    }
  }
  ASSERT_EQ(pairs.size(), 3u);
  const RealLikeSequence seq = RealLikeTruth(hex, pairs);
  for (const std::string style : {"binary", "grey", "inverted"}) {
    SCOPED_TRACE(style);
    WriteRealLike(P(style), seq, style);
    const auto r = Run("track --images " + P(style) + " --out " + P(style + ".csv") + " --counts " +
                       P(style + "-counts.csv"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find(style == "inverted" ? "markers: dark on bright" : "markers: bright on dark"),
              std::string::npos) << r.err;
    const std::vector<PinFrame> frames = ReadPinCsv(P(style + ".csv"));
    ASSERT_EQ(frames.size(), static_cast<size_t>(kPressFrames));
    ASSERT_EQ(frames[0].size(), 127) << r.err;
    // Each tracked pin is the pattern pin nearest it in the first frame.
    std::vector<size_t> of(127);
    for (int i = 0; i < 127; ++i) {
      double best = 1e9;
      for (size_t j = 0; j < 127; ++j) {
        const double d = std::hypot(frames[0].pos_px(i, 0) - seq.truth[0][j].x, frames[0].pos_px(i, 1) - seq.truth[0][j].y);
        if (d < best) best = d, of[i] = j;
      }
    }
    // Found: detected and within 1 px of the truth (merged pairs: of their blob's centre).
    int all_found = 0;
    long long found = 0;
    for (int f = 0; f < kPressFrames; ++f) {
      int n = 0;
      for (int i = 0; i < 127; ++i) {
        const cv::Point2f t = seq.truth[f][of[i]];
        const double err = std::hypot(frames[f].pos_px(i, 0) - t.x, frames[f].pos_px(i, 1) - t.y);
        // A merged pair's pins both sit at the merged blob's centre, half their distance away.
        const double within = seq.merged[f][of[i]] ? seq.gap[f][of[i]] + 1.0 : 1.0;
        n += frames[f].valid[i] == 1 && err < within ? 1 : 0;
      }
      all_found += n == 127 ? 1 : 0;
      found += n;
    }
    EXPECT_GE(all_found, static_cast<int>(std::ceil(0.95 * kPressFrames))) << r.err;
    EXPECT_GE(static_cast<double>(found) / (127.0 * kPressFrames), 0.99) << r.err;
    const std::string counts = testing::Slurp(P(style + "-counts.csv"));
    EXPECT_EQ(counts.rfind("frame,time_s,pins_found,markers\n0,0,127,127\n", 0), 0u) << counts;
  }
}

}  // namespace
}  // namespace tactip
