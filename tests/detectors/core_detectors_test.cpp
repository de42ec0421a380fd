// Velocity features, the threshold and incipient detectors, response strategies and the
// contact measure on synthetic pin frames whose answers are known by construction.

#include <gtest/gtest.h>

#include "scratch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "detectors/detector.h"
#include "detectors/incipient.h"
#include "detectors/metrics.h"
#include "detectors/response.h"
#include "detectors/threshold.h"

namespace tactip {
namespace {

using testing::TempPath;
using testing::WriteFile;

constexpr float kPitchPx = 10.0f;   // lattice pitch of the synthetic sensor
constexpr double kExact = 1e-6;     // float arithmetic on pixel-sized values, integer shifts
constexpr double kFloatPx = 1e-4;   // sub-pixel shifts of float positions near 300 px
constexpr double kAngleTol = 1e-5;  // radians

/// 19-pin hexagonal lattice: pin 0 at the centre, ring 1 = pins 1..6, ring 2 = pins 7..18.
Eigen::Matrix<float, Eigen::Dynamic, 2> Lattice19() {
  Eigen::Matrix<float, Eigen::Dynamic, 2> p(19, 2);
  const Eigen::Vector2f centre(320.0f, 240.0f);
  p.row(0) = centre.transpose();
  int k = 1;
  for (int ring = 1; ring <= 2; ++ring) {
    // Walk the hexagon of this ring: 6 sides of `ring` steps.
    Eigen::Vector2f q = centre + ring * kPitchPx * Eigen::Vector2f(1.0f, 0.0f);
    for (int side = 0; side < 6; ++side) {
      const double a = std::numbers::pi * (2.0 + side) / 3.0;
      const Eigen::Vector2f step =
          kPitchPx * Eigen::Vector2f(static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)));
      for (int s = 0; s < ring; ++s) {
        p.row(k++) = q.transpose();
        q += step;
      }
    }
  }
  return p;
}

/// A frame with every pin detected.
PinFrame Frame(const Eigen::Matrix<float, Eigen::Dynamic, 2>& pos, double t) {
  PinFrame f;
  f.time_s = t;
  f.pos_px = pos;
  f.valid.assign(pos.rows(), 1);
  return f;
}

/// Portable standard normal draws (Box-Muller on mt19937_64, whose output the standard fixes).
class Gaussian {
 public:
  explicit Gaussian(std::uint64_t seed) : gen_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(gen_() >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
    const double u2 = static_cast<double>(gen_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 gen_;
};

/// Lattice frames at 100 Hz: still for `n_still` frames, then every pin translates by
/// `slip_px` in x per frame; position noise of `noise_px` std on every coordinate.
std::vector<PinFrame> StillThenSlide(int n_still, int n_slide, float slip_px, double noise_px, Gaussian& g) {
  const auto base = Lattice19();
  std::vector<PinFrame> frames;
  float shift = 0.0f;
  for (int k = 0; k < n_still + n_slide; ++k) {
    if (k >= n_still) shift += slip_px;
    Eigen::Matrix<float, Eigen::Dynamic, 2> p = base;
    p.col(0).array() += shift;
    for (int i = 0; i < p.rows(); ++i) {
      p(i, 0) += static_cast<float>(noise_px * g());
      p(i, 1) += static_cast<float>(noise_px * g());
    }
    frames.push_back(Frame(p, 0.01 * k));
  }
  return frames;
}



/// The message of the InputError thrown by `f`, or "" if none is thrown.
template <typename F>
std::string ErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// ---------------------------------------------------------------------------------------
// Features

TEST(VelocityFeaturesTest, FirstFrameHasNoVelocity) {
  VelocityFeatures feat;
  Eigen::VectorXf out;
  EXPECT_FALSE(feat.Update(Frame(Lattice19(), 0.0), out));
  EXPECT_TRUE(feat.Update(Frame(Lattice19(), 0.01), out));
  feat.Reset();
  EXPECT_FALSE(feat.Update(Frame(Lattice19(), 0.02), out));
}

TEST(VelocityFeaturesTest, PureTranslationGivesUnitDrAndZeroDtheta) {
  VelocityFeatures feat(FeatureSet::kDrDtheta);
  Eigen::VectorXf out;
  auto p = Lattice19();
  feat.Update(Frame(p, 0.0), out);
  p.col(0).array() += 1.0f;
  ASSERT_TRUE(feat.Update(Frame(p, 0.01), out));
  ASSERT_EQ(out.size(), 2 * 19);
  for (int i = 0; i < 19; ++i) {
    EXPECT_NEAR(out[2 * i], 1.0, kExact) << "pin " << i;
    EXPECT_NEAR(out[2 * i + 1], 0.0, kAngleTol) << "pin " << i;
  }
  EXPECT_NEAR(feat.mean_velocity().x(), 1.0, kExact);
  EXPECT_NEAR(feat.mean_velocity().y(), 0.0, kExact);
}

TEST(VelocityFeaturesTest, DthetaIsCentredOnTheFrameCircularMean) {
  // Even pins move along +x (angle 0), odd pins along +y (pi/2), 10:9: the circular
  // mean is atan2(9, 10), so dtheta = -atan2(9, 10) and pi/2 - atan2(9, 10).
  VelocityFeatures feat(FeatureSet::kDtheta);
  Eigen::VectorXf out;
  auto p = Lattice19();
  feat.Update(Frame(p, 0.0), out);
  for (int i = 0; i < 19; ++i) p(i, i % 2) += 1.0f;
  ASSERT_TRUE(feat.Update(Frame(p, 0.01), out));
  const double mean = std::atan2(9.0, 10.0);
  for (int i = 0; i < 19; ++i) {
    const double expected = i % 2 == 0 ? -mean : std::numbers::pi / 2.0 - mean;
    EXPECT_NEAR(out[i], expected, kAngleTol) << "pin " << i;
  }
}

TEST(VelocityFeaturesTest, SlipTowardsPiDoesNotSplitIntoTwoClusters) {
  // All pins move along -x with tiny opposite y wobble: raw angles sit at +pi and -pi.
  // After centring on the circular mean every dtheta is near 0.
  VelocityFeatures feat(FeatureSet::kDtheta);
  Eigen::VectorXf out;
  auto p = Lattice19();
  feat.Update(Frame(p, 0.0), out);
  for (int i = 0; i < 19; ++i) {
    p(i, 0) -= 2.0f;
    p(i, 1) += (i % 2 == 0 ? 0.01f : -0.01f);
  }
  ASSERT_TRUE(feat.Update(Frame(p, 0.01), out));
  for (int i = 0; i < 19; ++i) EXPECT_NEAR(out[i], 0.0, 0.02) << "pin " << i;
}

TEST(VelocityFeaturesTest, MissedPinContributesZeroAndIsLeftOutOfTheMeans) {
  // All detected pins move +1 px in y; pin 3 is missed in the second frame and carries a
  // far-away position. If it entered the dtheta mean the others would not centre on 0.
  VelocityFeatures feat(FeatureSet::kDrDtheta);
  Eigen::VectorXf out;
  auto p = Lattice19();
  feat.Update(Frame(p, 0.0), out);
  p.col(1).array() += 1.0f;
  p(3, 0) += 50.0f;
  PinFrame f = Frame(p, 0.01);
  f.valid[3] = 0;
  ASSERT_TRUE(feat.Update(f, out));
  EXPECT_EQ(out[2 * 3], 0.0f);
  EXPECT_EQ(out[2 * 3 + 1], 0.0f);
  for (int i = 0; i < 19; ++i) {
    if (i == 3) continue;
    EXPECT_NEAR(out[2 * i], 1.0, kExact) << "pin " << i;
    EXPECT_NEAR(out[2 * i + 1], 0.0, kAngleTol) << "pin " << i;
  }
  EXPECT_NEAR(feat.mean_velocity().x(), 0.0, kExact);
  EXPECT_NEAR(feat.mean_velocity().y(), 1.0, kExact);
}

TEST(VelocityFeaturesTest, PinCountChangeThrows) {
  VelocityFeatures feat;
  Eigen::VectorXf out;
  feat.Update(Frame(Lattice19(), 0.0), out);
  const Eigen::Matrix<float, Eigen::Dynamic, 2> fewer = Lattice19().topRows(18);
  EXPECT_THROW(feat.Update(Frame(fewer, 0.01), out), InputError);
}

// ---------------------------------------------------------------------------------------
// Threshold

TEST(ThresholdTest, CoLinearJumpIsSlipAndStillNoiseIsNot) {
  constexpr double kThresholdPx = 0.5;
  constexpr double kNoisePx = 0.05;
  constexpr float kJumpPx = 2.0f;
  Gaussian g(7);
  ThresholdDetector det(kThresholdPx);
  const auto frames = StillThenSlide(30, 5, kJumpPx, kNoisePx, g);
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    const Decision d = det.Update(frames[k]);
    EXPECT_EQ(d.slip, k >= 30) << "frame " << k;
    if (k >= 30) {
      EXPECT_NEAR(d.score, kJumpPx, 0.1);
    }
  }
}

TEST(ThresholdTest, FirstFrameIsNeverSlip) {
  // With T = 0 every frame with a velocity is slip, but the first has none.
  ThresholdDetector det(0.0);
  EXPECT_FALSE(det.Update(Frame(Lattice19(), 0.0)).slip);
  EXPECT_TRUE(det.Update(Frame(Lattice19(), 0.01)).slip);
  det.Reset();
  EXPECT_FALSE(det.Update(Frame(Lattice19(), 0.02)).slip);
}

TEST(ThresholdTest, RejectsNegativeOrNonFiniteThreshold) {
  EXPECT_THROW(ThresholdDetector(-0.1), InputError);
  EXPECT_THROW(ThresholdDetector(std::nan("")), InputError);
  EXPECT_THROW(ThresholdDetector(std::numeric_limits<double>::infinity()), InputError);
}

/// Noise-free run: still frames (v = 0) and then a slide of `slip_px` per frame.
LabeledRun CleanRun(int run, float slip_px) {
  Gaussian g(1);
  LabeledRun r;
  r.run = run;
  r.frames = StillThenSlide(20, 10, slip_px, 0.0, g);
  r.first_frame = 2;
  r.onset_frame = 20;
  return r;
}

TEST(ThresholdTest, TrainPutsThresholdMidwayBetweenStillAndSlidingSpeeds) {
  // Selected static frames have v = 0 and slip frames v = 2 (or 3): the best cut is the
  // midpoint 1 (ties would go to the smaller candidate).
  TrainOptions opts;
  opts.static_fraction = 1.0;
  const std::vector<LabeledRun> runs = {CleanRun(0, 2.0f), CleanRun(1, 3.0f)};
  const auto det = ThresholdDetector::Train(runs, opts);
  EXPECT_NEAR(det->threshold_px(), 1.0, kExact);
}

TEST(ThresholdTest, TrainOnNoisySyntheticRunsSeparatesThemWithF1One) {
  constexpr double kNoisePx = 0.05;
  Gaussian g(11);
  std::vector<LabeledRun> runs;
  for (int r = 0; r < 6; ++r) {
    LabeledRun run;
    run.run = r;
    run.frames = StillThenSlide(40, 12, 0.8f + 0.2f * r, kNoisePx, g);
    run.first_frame = 3;
    run.onset_frame = 40;
    runs.push_back(std::move(run));
  }
  TrainOptions opts;  // defaults: n_slip 4, static fraction 0.4, seed 1
  const auto det = ThresholdDetector::Train(runs, opts);
  EXPECT_GT(det->threshold_px(), 0.0);
  const Evaluation ev = Evaluate(*det, runs, opts.n_slip);
  EXPECT_DOUBLE_EQ(ev.confusion.F1(), 1.0);
  EXPECT_EQ(ev.confusion.fp, 0);
  EXPECT_EQ(ev.confusion.fn, 0);
}

TEST(ThresholdTest, TrainSelectsTheFramesBuildTrainingSetSelects) {
  // Pure x-translations at random speeds, overlapping between classes, so the best T
  // depends on which static frames the seeded downsampling keeps. For a pure translation
  // v = mean dr, so the kDr training set gives every selected frame's v: a brute-force
  // F1 search over it must agree with Train.
  std::mt19937_64 gen(42);
  std::uniform_real_distribution<float> still(0.0f, 1.0f), slide(0.5f, 2.0f);
  std::vector<LabeledRun> runs;
  for (int r = 0; r < 3; ++r) {
    LabeledRun run;
    run.run = r;
    run.first_frame = 5;
    run.onset_frame = 40;
    auto p = Lattice19();
    for (int k = 0; k < 60; ++k) {
      p.col(0).array() += k >= run.onset_frame ? slide(gen) : still(gen);
      run.frames.push_back(Frame(p, 0.01 * k));
    }
    runs.push_back(std::move(run));
  }
  TrainOptions opts;
  opts.features = FeatureSet::kDr;
  const TrainingSet ts = BuildTrainingSet(runs, opts);
  const Eigen::VectorXf v = ts.x.rowwise().mean();
  const auto f1_at = [&](double t) {
    Confusion c;
    for (Eigen::Index b = 0; b < v.size(); ++b) {
      const bool slip = v[b] >= t;
      if (ts.y[b] == 1) {
        (slip ? c.tp : c.fn)++;
      } else {
        (slip ? c.fp : c.tn)++;
      }
    }
    return c.F1();
  };
  // Brute force over "everything is slip" and every midpoint of neighbouring values.
  std::vector<float> sorted(v.data(), v.data() + v.size());
  std::sort(sorted.begin(), sorted.end());
  double best_f1 = f1_at(0.0);
  for (size_t a = 1; a < sorted.size(); ++a)
    best_f1 = std::max(best_f1, f1_at(0.5 * (static_cast<double>(sorted[a - 1]) + sorted[a])));
  const auto det = ThresholdDetector::Train(runs, opts);
  EXPECT_DOUBLE_EQ(f1_at(det->threshold_px()), best_f1);
  EXPECT_LT(best_f1, 1.0);  // the classes do overlap
}

TEST(ThresholdTest, TrainWithoutSlipFramesThrows) {
  LabeledRun r = CleanRun(0, 2.0f);
  r.onset_frame = -1;
  r.frames.resize(20);
  EXPECT_THROW(ThresholdDetector::Train({r}, TrainOptions{}), InputError);
  TrainOptions bad;
  bad.n_slip = 0;
  EXPECT_THROW(ThresholdDetector::Train({CleanRun(0, 2.0f)}, bad), InputError);
}

TEST(ThresholdTest, SaveLoadRoundTripGivesIdenticalDecisions) {
  constexpr double kThresholdPx = 0.1 + 1e-12;  // no short decimal form
  const std::string path = TempPath("model.txt");
  ThresholdDetector det(kThresholdPx);
  det.Save(path);
  const auto loaded = ThresholdDetector::Load(path);
  EXPECT_EQ(loaded->threshold_px(), kThresholdPx);
  EXPECT_EQ(loaded->name(), "threshold");
  Gaussian g(3);
  for (const PinFrame& f : StillThenSlide(20, 5, 0.3f, 0.08, g)) {
    const Decision a = det.Update(f), b = loaded->Update(f);
    EXPECT_EQ(a.slip, b.slip);
    EXPECT_EQ(a.score, b.score);
  }
}

TEST(ThresholdTest, CorruptModelThrowsNamingThePath) {
  const std::string path = TempPath("model.txt");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "empty file"},
      {"tactip-detector svm 1\nthreshold_px 1\n", "expected 'tactip-detector threshold 1'"},
      {"tactip-detector threshold 1\nthreshold_px abc\n", "threshold_px 'abc' is not a number"},
      {"tactip-detector threshold 1\nthreshold_px 1.5x\n", "is not a number"},
      {"tactip-detector threshold 1\n", "missing threshold_px"},
      {"tactip-detector threshold 1\nthreshold_px 1\nthreshold_px 2\n", "duplicate threshold_px"},
      {"tactip-detector threshold 1\nthreshold 1\n", "unknown key 'threshold'"},
      {"tactip-detector threshold 1\nthreshold_px 1 2\n", "expected 'key value'"},
      {"tactip-detector threshold 1\nthreshold_px -1\n", "must be finite and >= 0"},
  };
  for (const auto& [text, fragment] : cases) {
    WriteFile(path, text);
    const std::string msg = ErrorOf([&] { ThresholdDetector::Load(path); });
    EXPECT_NE(msg.find("model '" + path + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "text '" << text << "': " << msg;
  }
  EXPECT_NE(ErrorOf([&] { ThresholdDetector::Load(path + ".missing"); }).find(path + ".missing"), std::string::npos);
}

// ---------------------------------------------------------------------------------------
// Incipient

/// Lattice frames where the pins in `moving` advance `speed_px` per frame in x from frame
/// `start` on (first moving frame start + 1), all others still.
std::vector<PinFrame> RingFrames(const std::vector<int>& moving, int start, int n, float speed_px) {
  const auto base = Lattice19();
  std::vector<PinFrame> frames;
  for (int k = 0; k < n; ++k) {
    auto p = base;
    const float shift = k > start ? speed_px * static_cast<float>(k - start) : 0.0f;
    for (int i : moving) p(i, 0) += shift;
    frames.push_back(Frame(p, 0.01 * k));
  }
  return frames;
}

/// First frame declared slip, or -1.
int FirstSlip(Detector& det, const std::vector<PinFrame>& frames) {
  det.Reset();
  int first = -1;
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    if (det.Update(frames[k]).slip && first < 0) first = k;
  }
  return first;
}

TEST(IncipientTest, BulkTranslationNeverDeclaresIncipientSlip) {
  // All pins move together at speeds from 0.05 to 8 px/frame, changing abruptly.
  IncipientDetector det;
  auto p = Lattice19();
  const float speeds[] = {0.0f, 0.05f, 0.5f, 8.0f, 0.0f, 3.0f, 1.0f, 0.2f};
  for (int k = 0; k < 80; ++k) {
    const float v = speeds[(k / 10) % 8];
    p.col(0).array() += v;
    p.col(1).array() += 0.5f * v;
    const Decision d = det.Update(Frame(p, 0.01 * k));
    EXPECT_FALSE(d.slip) << "frame " << k;
    EXPECT_EQ(d.n_slipping, 0) << "frame " << k;
  }
}

TEST(IncipientTest, RingMovingAloneIsExactlyTheSlippingSet) {
  // Ring 1 (pins 1..6) moves 1 px/frame from frame 10 on; the rest is still.
  const std::vector<int> ring = {1, 2, 3, 4, 5, 6};
  IncipientParams params;
  params.window = 1;
  IncipientDetector det(params);
  const auto frames = RingFrames(ring, 10, 30, 1.0f);
  for (int k = 0; k < 30; ++k) {
    const Decision d = det.Update(frames[k]);
    if (k <= 10) {
      EXPECT_FALSE(d.slip) << "frame " << k;
      EXPECT_TRUE(d.slipping_pins.empty()) << "frame " << k;
    } else {
      // s(t) over the 19 pins = 6/19 px in the first moving frame; ring excess 13/19 > 0.2.
      EXPECT_TRUE(d.slip) << "frame " << k;
      EXPECT_EQ(d.slipping_pins, ring) << "frame " << k;
      EXPECT_EQ(d.n_slipping, 6);
    }
  }
  // The set is re-judged every frame: once the ring stops (the same frame again, zero
  // velocity) it empties; Reset empties it too.
  const Decision still = det.Update(frames.back());
  EXPECT_TRUE(still.slipping_pins.empty());
  EXPECT_FALSE(still.slip);
  det.Reset();
  EXPECT_TRUE(det.slipping_pins().empty());
  EXPECT_EQ(det.Update(frames.back()).n_slipping, 0);
}

TEST(IncipientTest, SlipNeedsCountThrPins) {
  // Only pins 1..3 move: 3 < count_thr = 4, so the set fills but no slip is declared.
  IncipientParams params;
  params.window = 1;
  IncipientDetector det(params);
  Decision d;
  for (const PinFrame& f : RingFrames({1, 2, 3}, 5, 20, 1.0f)) d = det.Update(f);
  EXPECT_EQ(d.n_slipping, 3);
  EXPECT_FALSE(d.slip);
}

TEST(IncipientTest, WindowOfFiveDelaysDetectionComparedWithWindowOne) {
  // Ring 1 at 0.5 px/frame after 15 still frames (first moving frame 16). With k moving
  // frames in a window of W: smoothed ring D = 0.5 min(k, W)/W, bulk s = 6/19 of it, so the
  // excess is (13/19) 0.5 k / W: W = 1 crosses 0.2 at k = 1, W = 5 at k = 3.
  const auto frames = RingFrames({1, 2, 3, 4, 5, 6}, 15, 40, 0.5f);
  IncipientParams p1;
  p1.window = 1;
  IncipientParams p5;
  p5.window = 5;
  IncipientDetector w1(p1), w5(p5);
  EXPECT_EQ(FirstSlip(w1, frames), 16);
  EXPECT_EQ(FirstSlip(w5, frames), 18);
}

TEST(IncipientTest, NoPinIsJudgedBeforeTheWindowIsFull) {
  // Ring 1 moves 1 px/frame from the very start (first velocity at frame 1). W = 1 judges
  // at once; W = 5 waits for 5 velocity frames (frame 5) although the average over the
  // frames so far would already exceed the threshold.
  const auto frames = RingFrames({1, 2, 3, 4, 5, 6}, 0, 12, 1.0f);
  IncipientParams p1;
  p1.window = 1;
  IncipientParams p5;
  p5.window = 5;
  IncipientDetector w1(p1), w5(p5);
  EXPECT_EQ(FirstSlip(w1, frames), 1);
  EXPECT_EQ(FirstSlip(w5, frames), 5);
}

TEST(IncipientTest, PositionNoiseOfTenthPixelRaisesNoAlarm) {
  // 0.1 px position noise gives smoothed speed excesses above 0.2 px/frame in about 2e-4
  // of pin-frames (measured), so over 19 pins x 300 frames about one pin may join the set
  // on noise: far from the 4 needed for an alarm.
  constexpr double kNoisePx = 0.1;
  constexpr int kFrames = 300;
  Gaussian g(2024);
  IncipientDetector det;  // hardware parameters: W = 5, 0.2 px/frame, 4 pins
  const auto frames = StillThenSlide(kFrames, 0, 0.0f, kNoisePx, g);
  int max_slipping = 0;
  for (int k = 0; k < kFrames; ++k) {
    const Decision d = det.Update(frames[k]);
    ASSERT_FALSE(d.slip) << "frame " << k;
    max_slipping = std::max(max_slipping, d.n_slipping);
  }
  EXPECT_LE(max_slipping, 1);
}

TEST(IncipientTest, MissedPinIsNeitherAveragedNorJudged) {
  // Pin 3 is reported 40 px away while missed in frame 5: no D is computed from it.
  IncipientParams params;
  params.window = 1;
  IncipientDetector det(params);
  const auto base = Lattice19();
  for (int k = 0; k < 10; ++k) {
    PinFrame f = Frame(base, 0.01 * k);
    if (k == 5) {
      f.pos_px(3, 0) += 40.0f;
      f.valid[3] = 0;
    }
    const Decision d = det.Update(f);
    EXPECT_EQ(d.n_slipping, 0) << "frame " << k;
    EXPECT_EQ(d.score, 0.0) << "frame " << k;
  }
}

TEST(IncipientTest, ScoreIsTheBulkSpeedOfTheStaticPins) {
  // Everything translates 0.3 px/frame: s(t) = 0.3 once the first velocity exists.
  IncipientDetector det;
  auto p = Lattice19();
  EXPECT_EQ(det.Update(Frame(p, 0.0)).score, 0.0);
  p.col(0).array() += 0.3f;
  EXPECT_NEAR(det.Update(Frame(p, 0.01)).score, 0.3, kFloatPx);
}

TEST(IncipientTest, InvalidParametersAreRejected) {
  IncipientParams p;
  p.window = 0;
  EXPECT_NE(ErrorOf([&] { IncipientDetector d(p); }).find("window = 0: must be in [1, 1000]"), std::string::npos);
  p = {};
  p.speed_thr_px = 0.0;
  EXPECT_NE(ErrorOf([&] { IncipientDetector d(p); }).find("speed_thr_px = 0"), std::string::npos);
  p = {};
  p.count_thr = 0;
  EXPECT_NE(ErrorOf([&] { IncipientDetector d(p); }).find("count_thr = 0: must be in [1, 1000000]"), std::string::npos);
}

TEST(IncipientTest, PinCountChangeThrows) {
  IncipientDetector det;
  det.Update(Frame(Lattice19(), 0.0));
  const Eigen::Matrix<float, Eigen::Dynamic, 2> fewer = Lattice19().topRows(18);
  EXPECT_THROW(det.Update(Frame(fewer, 0.01)), InputError);
  // A new run may use another sensor.
  det.Reset();
  EXPECT_NO_THROW(det.Update(Frame(fewer, 0.02)));
}

TEST(IncipientTest, SaveLoadRoundTripKeepsParameters) {
  const std::string path = TempPath("model.txt");
  IncipientParams p;
  p.window = 7;
  p.speed_thr_px = 0.1 + 1e-13;
  p.count_thr = 9;
  IncipientDetector(p).Save(path);
  const auto loaded = IncipientDetector::Load(path);
  EXPECT_EQ(loaded->params().window, 7);
  EXPECT_EQ(loaded->params().speed_thr_px, p.speed_thr_px);
  EXPECT_EQ(loaded->params().count_thr, 9);
  EXPECT_EQ(loaded->name(), "incipient");
}

TEST(IncipientTest, CorruptModelThrowsNamingThePath) {
  const std::string path = TempPath("model.txt");
  const std::string head = "tactip-detector incipient 1\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "empty file"},
      {"tactip-detector threshold 1\n", "expected 'tactip-detector incipient 1'"},
      {head + "window 5\nspeed_thr_px 0.2\n", "missing count_thr"},
      {head + "window 5.5\nspeed_thr_px 0.2\ncount_thr 4\n", "window '5.5' is not a number"},
      {head + "window 0\nspeed_thr_px 0.2\ncount_thr 4\n", "window = 0: must be in [1, 1000]"},
      {head + "window 5\nwindow 5\n", "duplicate window"},
      {head + "colour red\n", "unknown key 'colour'"},
  };
  for (const auto& [text, fragment] : cases) {
    WriteFile(path, text);
    const std::string msg = ErrorOf([&] { IncipientDetector::Load(path); });
    EXPECT_NE(msg.find("model '" + path + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << "text '" << text << "': " << msg;
  }
}

// ---------------------------------------------------------------------------------------
// Response strategies and contact measure

TEST(ResponseStrategyTest, TwoFramesOneSensorNeedsTwoConsecutiveFrames) {
  ResponseStrategy r = ResponseStrategy::Parse("2Fr1Sen", 1);
  EXPECT_FALSE(r.Update({true}));
  EXPECT_FALSE(r.Update({false}));
  EXPECT_FALSE(r.Update({true}));
  EXPECT_TRUE(r.Update({true}));
  EXPECT_TRUE(r.Update({true}));
  EXPECT_FALSE(r.Update({false}));
}

TEST(ResponseStrategyTest, OneFrameTwoSensorsNeedsTwoAtOnce) {
  ResponseStrategy r(1, 2, 3);
  EXPECT_FALSE(r.Update({true, false, false}));
  EXPECT_FALSE(r.Update({false, true, false}));
  EXPECT_TRUE(r.Update({true, true, false}));
  EXPECT_TRUE(r.Update({false, true, true}));
  EXPECT_FALSE(r.Update({false, false, true}));
}

TEST(ResponseStrategyTest, StreaksMustOverlapAcrossSensors) {
  // 2Fr2Sen: sensor 0 completes a 2-frame streak at frame 1 and sensor 1 at frame 2, but
  // sensor 0's streak is broken by then; both streaks are long enough only at frame 4.
  ResponseStrategy r(2, 2, 2);
  EXPECT_FALSE(r.Update({true, false}));
  EXPECT_FALSE(r.Update({true, true}));
  EXPECT_FALSE(r.Update({false, true}));
  EXPECT_FALSE(r.Update({true, true}));
  EXPECT_TRUE(r.Update({true, true}));
}

TEST(ResponseStrategyTest, ResetClearsStreaks) {
  ResponseStrategy r(2, 1, 1);
  EXPECT_FALSE(r.Update({true}));
  r.Reset();
  EXPECT_FALSE(r.Update({true}));
  EXPECT_TRUE(r.Update({true}));
}

TEST(ResponseStrategyTest, ParseReadsCountsAndRejectsBadStrings) {
  const ResponseStrategy r = ResponseStrategy::Parse("2Fr3Sen", 3);
  EXPECT_EQ(r.n_frames(), 2);
  EXPECT_EQ(r.n_sensors_required(), 3);
  EXPECT_EQ(r.n_sensors_total(), 3);
  EXPECT_EQ(r.ToString(), "2Fr3Sen");
  EXPECT_EQ(ResponseStrategy::Parse("1fr1sen", 1).ToString(), "1Fr1Sen");
  for (const std::string bad : {"", "2Fr", "Fr1Sen", "2Fr1", "2Fr1Senx", "-1Fr1Sen", " 2Fr1Sen", "2 Fr1Sen", "0Fr1Sen",
                                "2Fr0Sen", "2Fr4Sen", "99999999999Fr1Sen"}) {
    const std::string msg = ErrorOf([&] { ResponseStrategy::Parse(bad, 3); });
    EXPECT_NE(msg.find("response strategy '" + bad + "'"), std::string::npos) << "'" << bad << "': " << msg;
  }
  EXPECT_THROW(ResponseStrategy(1, 2, 1), InputError);
}

TEST(ResponseStrategyTest, WrongNumberOfSensorDecisionsThrows) {
  ResponseStrategy r(1, 1, 2);
  EXPECT_THROW(r.Update({true}), InputError);
}

TEST(ContactMeasureTest, MeanDisplacementFromTheFirstFrame) {
  // Pins 0..9 move by (3, 4) = 5 px, pins 10..18 stay; pin 18 is missed in the reference
  // and pin 17 now, so d = 10 * 5 / 17.
  ContactMeasure cm;
  const auto base = Lattice19();
  PinFrame ref = Frame(base, 0.0);
  ref.valid[18] = 0;
  EXPECT_EQ(cm.Update(ref), 0.0);
  EXPECT_TRUE(cm.has_reference());
  auto p = base;
  for (int i = 0; i < 10; ++i) {
    p(i, 0) += 3.0f;
    p(i, 1) += 4.0f;
  }
  p(17, 0) += 100.0f;
  p(18, 0) += 100.0f;
  PinFrame now = Frame(p, 0.01);
  now.valid[17] = 0;
  EXPECT_NEAR(cm.Update(now), 50.0 / 17.0, kExact);
  // Reset takes the next frame as the new reference.
  cm.Reset();
  EXPECT_EQ(cm.Update(now), 0.0);
  EXPECT_NEAR(cm.Update(now), 0.0, kExact);
  EXPECT_THROW(cm.Update(Frame(base.topRows(5), 0.02)), InputError);
}

TEST(ResponseDetectorTest, TwoFrameStrategyDelaysTheActionByOneFrame) {
  // A threshold of 0.5 px on a 3 px co-linear jump lasting frames 10..12.
  std::vector<PinFrame> frames;
  auto p = Lattice19();
  for (int k = 0; k < 16; ++k) {
    if (k >= 10 && k <= 12) p.col(0).array() += 3.0f;
    frames.push_back(Frame(p, 0.01 * k));
  }
  ThresholdDetector plain(0.5);
  ResponseDetector twice(std::make_unique<ThresholdDetector>(0.5), ResponseStrategy::Parse("2Fr1Sen", 1));
  EXPECT_EQ(twice.name(), "threshold+2Fr1Sen");
  for (int k = 0; k < 16; ++k) {
    const bool a = plain.Update(frames[k]).slip, b = twice.Update(frames[k]).slip;
    EXPECT_EQ(a, k >= 10 && k <= 12) << "frame " << k;
    EXPECT_EQ(b, k >= 11 && k <= 12) << "frame " << k;
  }
  EXPECT_THROW(ResponseDetector(std::make_unique<ThresholdDetector>(0.5), ResponseStrategy::Parse("1Fr2Sen", 3)),
               InputError);
}

}  // namespace
}  // namespace tactip
