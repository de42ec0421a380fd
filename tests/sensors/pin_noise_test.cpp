#include "sensors/pin_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tests/hex_pattern.h"
namespace tactip {
namespace {

constexpr double kPitchPx = 20.0;

std::vector<float> HexPattern(int rings) { return testing::HexPattern(rings, kPitchPx); }

// Only the structured parts named by the test: everything else zero, no dropouts.
CameraConfig Structured() {
  CameraConfig c;
  c.noise_model = "structured";
  c.pixel_noise_px = 0.0;
  c.common_shift_px = c.common_rotation_deg = c.common_scale_pct = c.local_noise_px = 0.0;
  c.common_time_s = 0.0;
  c.dropout_prob = 0.0;
  return c;
}

// `frames` frames of noise on `clean`: the displacement of every pin, frame by frame.
std::vector<std::vector<double>> Displacements(const CameraConfig& c, const std::vector<float>& clean, int frames,
                                               std::uint64_t seed = 3) {
  DetectionNoise noise(c, seed);
  std::vector<std::vector<double>> out;
  std::vector<float> prev;
  std::vector<std::uint8_t> valid(clean.size() / 2);
  for (int f = 0; f < frames; ++f) {
    std::vector<float> px = clean;
    noise.Apply(px, valid, prev);
    std::vector<double> d(px.size());
    for (size_t k = 0; k < px.size(); ++k) d[k] = static_cast<double>(px[k]) - clean[k];
    out.push_back(d);
    prev = px;
  }
  return out;
}

TEST(PinNoiseTest, TheIndependentModelIgnoresTheStructuredKeys) {
  CameraConfig a;
  a.noise_model = "independent";
  CameraConfig b = a;
  b.common_shift_px = 3.0;
  b.local_noise_px = 2.0;
  b.common_time_s = 1.0;
  const std::vector<float> clean = HexPattern(6);
  EXPECT_EQ(Displacements(a, clean, 5), Displacements(b, clean, 5));
}

TEST(PinNoiseTest, DropoutsAndTheIndependentPartAreTheIndependentModelsStream) {
  // The structured parts draw from a stream of their own: with them at zero the structured
  // model reports exactly what the independent model does, missed pins included.
  CameraConfig independent;
  independent.noise_model = "independent";
  independent.dropout_prob = 0.2;
  CameraConfig structured = Structured();
  structured.pixel_noise_px = independent.pixel_noise_px;
  structured.dropout_prob = 0.2;
  const std::vector<float> clean = HexPattern(6);
  EXPECT_EQ(Displacements(independent, clean, 4), Displacements(structured, clean, 4));
}

TEST(PinNoiseTest, TheCommonShiftMovesEveryPinAlikeWithItsStdAndCorrelationTime) {
  CameraConfig c = Structured();
  c.common_shift_px = 0.3;
  c.common_time_s = 0.02;  // a = exp(-1 / (100 Hz * 0.02 s)) = exp(-0.5)
  const std::vector<float> clean = HexPattern(3);
  const auto d = Displacements(c, clean, 20000);
  double s2 = 0.0, lag1 = 0.0;
  for (size_t f = 0; f < d.size(); ++f) {
    for (size_t k = 2; k < d[f].size(); ++k) ASSERT_NEAR(d[f][k], d[f][k % 2], 1e-4) << "frame " << f;
    s2 += d[f][0] * d[f][0];
    if (f > 0) lag1 += d[f][0] * d[f - 1][0];
  }
  const double var = s2 / static_cast<double>(d.size());
  EXPECT_NEAR(std::sqrt(var), 0.3, 0.3 * 0.05);
  EXPECT_NEAR(lag1 / static_cast<double>(d.size() - 1) / var, std::exp(-0.5), 0.03);
}

TEST(PinNoiseTest, RotationAndScaleGrowWithTheDistanceFromThePrincipalPoint) {
  const std::vector<float> clean = HexPattern(6);
  for (const bool rotation : {true, false}) {
    CameraConfig c = Structured();
    (rotation ? c.common_rotation_deg : c.common_scale_pct) = 0.5;
    const auto d = Displacements(c, clean, 1).front();
    // One angle (or scale) per frame: each displacement is that times the pin's position
    // about (320, 240), turned by 90 degrees for the rotation.
    double factor = 0.0;
    for (size_t i = 0; i < clean.size() / 2; ++i) {
      const double u = clean[2 * i] - 320.0, v = clean[2 * i + 1] - 240.0;
      const double r = std::hypot(u, v);
      if (r < 1.0) {
        EXPECT_NEAR(std::hypot(d[2 * i], d[2 * i + 1]), 0.0, 1e-4);
        continue;
      }
      const double along = (d[2 * i] * u + d[2 * i + 1] * v) / r, across = (-d[2 * i] * v + d[2 * i + 1] * u) / r;
      const double f = (rotation ? across : along) / r;
      if (factor == 0.0) factor = f;
      EXPECT_NEAR(f, factor, 1e-5) << "pin " << i;
      EXPECT_NEAR(rotation ? along : across, 0.0, 2e-4) << "pin " << i;
    }
    EXPECT_NE(factor, 0.0);
  }
}

TEST(PinNoiseTest, TheNeighbourFieldHasItsStdAndCorrelatesNeighboursAsItsKernelSays) {
  CameraConfig c = Structured();
  c.local_noise_px = 0.2;
  c.local_length_pitch = 0.64;
  const std::vector<float> clean = HexPattern(6);
  const auto d = Displacements(c, clean, 4000);
  // Pins one pitch apart: exp(-1 / (4 0.64^2)) = 0.543 on a continuum, 0.52 summed over the
  // lattice's pins; two pitches apart: 0.087 (0.077).
  const size_t n = clean.size() / 2;
  double s2 = 0.0, near = 0.0, far = 0.0;
  long n_near = 0, n_far = 0, n_s = 0;
  for (const auto& frame : d) {
    for (size_t i = 0; i < n; ++i) {
      s2 += frame[2 * i] * frame[2 * i] + frame[2 * i + 1] * frame[2 * i + 1];
      n_s += 2;
      for (size_t j = i + 1; j < n; ++j) {
        const double dist = std::hypot(clean[2 * i] - clean[2 * j], clean[2 * i + 1] - clean[2 * j + 1]);
        const double prod = frame[2 * i] * frame[2 * j] + frame[2 * i + 1] * frame[2 * j + 1];
        if (std::abs(dist - kPitchPx) < 0.5) near += prod, n_near += 2;
        if (std::abs(dist - 2 * kPitchPx) < 0.5) far += prod, n_far += 2;
      }
    }
  }
  const double var = s2 / static_cast<double>(n_s);
  EXPECT_NEAR(std::sqrt(var), 0.2, 0.2 * 0.03);
  EXPECT_NEAR(near / static_cast<double>(n_near) / var, std::exp(-1.0 / (4 * 0.64 * 0.64)), 0.05);
  EXPECT_NEAR(far / static_cast<double>(n_far) / var, std::exp(-4.0 / (4 * 0.64 * 0.64)), 0.03);
}

TEST(PinNoiseTest, ThePitchIsTheMeanNearestNeighbourDistanceOfTheFirstFrame) {
  const std::vector<float> clean = HexPattern(2);
  EXPECT_NEAR(MeanNearestNeighbourPx(clean), kPitchPx, 1e-3);
  EXPECT_EQ(MeanNearestNeighbourPx({1.f, 2.f}), 0.0);
  CameraConfig c = Structured();
  DetectionNoise noise(c, 5);
  EXPECT_EQ(noise.pitch_px(), 0.0);
  std::vector<float> px = clean;
  std::vector<std::uint8_t> valid(px.size() / 2);
  noise.Apply(px, valid, {});
  EXPECT_NEAR(noise.pitch_px(), kPitchPx, 1e-3);
}

TEST(PinNoiseTest, TheSameSeedGivesTheSameNoiseAndAnotherSeedOther) {
  CameraConfig c;
  c.noise_model = "structured";
  const std::vector<float> clean = HexPattern(6);
  EXPECT_EQ(Displacements(c, clean, 3, 9), Displacements(c, clean, 3, 9));
  EXPECT_NE(Displacements(c, clean, 3, 9), Displacements(c, clean, 3, 10));
}

}  // namespace
}  // namespace tactip
