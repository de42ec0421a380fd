#include "sensors/marker_labels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tactip {
namespace {

// An object held at 50 mm until `fall_s`, then falling freely; frames at 100 Hz over 3 s.
struct Fall {
  std::vector<double> time_s, height_m;
  explicit Fall(double fall_s) {
    for (int k = 0; k <= 300; ++k) {
      const double t = 0.01 * k, dt = std::max(0.0, t - fall_s);
      time_s.push_back(t);
      height_m.push_back(0.05 - 0.5 * 9.81 * dt * dt);
    }
  }
};

// Held from 0.5 s to 1 s.
constexpr HoldSpan kHold{0.5, 1.0};

TEST(MarkerLabelsTest, TheOnsetFollowsTheFallByTheTimeToDropTheThresholdAndAtMostOneFrame) {
  const Fall fall(2.0);
  MarkerCameraConfig cfg;
  cfg.jitter_px = 0.0;
  // Free fall covers 1 mm in sqrt(2 * 1e-3 / 9.81) = 14.3 ms; the 30 Hz frames add up to 33 ms.
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const double onset = MarkerOnset(fall.time_s, fall.height_m, kHold, cfg, seed);
    ASSERT_TRUE(std::isfinite(onset));
    // Rounding to 0.3 mm pixels moves the 1 mm threshold by up to half a pixel.
    EXPECT_GE(onset, 2.0 + std::sqrt(2.0 * 0.85e-3 / 9.81) - 1e-9) << seed;
    EXPECT_LE(onset, 2.0 + std::sqrt(2.0 * 1.15e-3 / 9.81) + 1.0 / cfg.frame_rate_hz + 1e-9) << seed;
  }
}

TEST(MarkerLabelsTest, SeededPhaseAndJitter) {
  const Fall fall(2.0);
  const MarkerCameraConfig cfg;
  EXPECT_EQ(MarkerOnset(fall.time_s, fall.height_m, kHold, cfg, 7), MarkerOnset(fall.time_s, fall.height_m, kHold, cfg, 7));
  int differ = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    differ += MarkerOnset(fall.time_s, fall.height_m, kHold, cfg, seed) != MarkerOnset(fall.time_s, fall.height_m, kHold, cfg, 7);
  }
  EXPECT_GE(differ, 5);
}

TEST(MarkerLabelsTest, AHeldObjectHasNoOnsetAndAJitterBeyondTheThresholdFiresEarly) {
  const Fall held(1e9);
  MarkerCameraConfig cfg;
  EXPECT_TRUE(std::isnan(MarkerOnset(held.time_s, held.height_m, kHold, cfg, 3)));
  // 10 px of jitter (3 mm) against a 1 mm threshold: a held object is labelled slipping.
  cfg.jitter_px = 10.0;
  const double early = MarkerOnset(held.time_s, held.height_m, kHold, cfg, 3);
  ASSERT_TRUE(std::isfinite(early));
  EXPECT_LT(early, 1.2);
}

TEST(MarkerLabelsTest, ACoarserCameraAndALargerThresholdLabelLater) {
  const Fall fall(2.0);
  MarkerCameraConfig fine, coarse;
  fine.jitter_px = coarse.jitter_px = 0.0;
  fine.frame_rate_hz = 1000.0;
  fine.mm_per_px = 0.01;
  coarse.threshold_mm = 10.0;
  const double a = MarkerOnset(fall.time_s, fall.height_m, kHold, fine, 1);
  const double b = MarkerOnset(fall.time_s, fall.height_m, kHold, coarse, 1);
  EXPECT_NEAR(a, 2.0 + std::sqrt(2.0 * 1e-3 / 9.81), 2e-3);
  EXPECT_NEAR(b, 2.0 + std::sqrt(2.0 * 1e-2 / 9.81), 1.0 / 30.0 + 0.05);
  EXPECT_GT(b, a);
}

TEST(MarkerLabelsTest, TheReferenceIsTheHoldNotTheLiftBeforeIt) {
  // Lifted by 10 mm until 0.9 s, held 0.1 s, falling from 2 s: a reference over the last
  // 0.5 s would average the lift in and label the held object slipping at once.
  Fall fall(2.0);
  for (size_t k = 0; k < fall.time_s.size(); ++k) {
    if (fall.time_s[k] < 0.9) fall.height_m[k] -= 0.01 * (0.9 - fall.time_s[k]) / 0.9;
  }
  MarkerCameraConfig cfg;
  cfg.jitter_px = 0.0;
  const double onset = MarkerOnset(fall.time_s, fall.height_m, HoldSpan{0.9, 1.0}, cfg, 4);
  EXPECT_GT(onset, 2.0);
  EXPECT_LT(onset, 2.06);
}

TEST(MarkerLabelsTest, TooFewFramesOrNoHoldGiveNaN) {
  const MarkerCameraConfig cfg;
  EXPECT_TRUE(std::isnan(MarkerOnset({0.0}, {0.0}, HoldSpan{0.0, 0.0}, cfg, 1)));
  const Fall fall(2.0);
  EXPECT_TRUE(std::isnan(MarkerOnset(fall.time_s, fall.height_m, HoldSpan{0.0, std::nan("")}, cfg, 1)));
  // The hold ends at the first frame: the first marker frame is the reference.
  EXPECT_TRUE(std::isfinite(MarkerOnset(fall.time_s, fall.height_m, HoldSpan{0.0, 0.0}, cfg, 1)));
}

}  // namespace
}  // namespace tactip
