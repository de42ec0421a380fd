#include "sensors/camera.h"
#include "sensors/pin_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sensors/labels.h"

namespace tactip {
namespace {

TEST(CameraTest, DefaultsAreValid) {
  CameraConfig c;
  EXPECT_NO_THROW(ValidateConfig(c));
  LabelConfig l;
  EXPECT_NO_THROW(ValidateConfig(l));
}

TEST(CameraTest, AxisPointProjectsToPrincipalPoint) {
  CameraConfig c;
  const PinholeCamera cam(c);
  const auto uv = cam.Project({0.0175, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(uv[0], c.cx_px);
  EXPECT_DOUBLE_EQ(uv[1], c.cy_px);
}

TEST(CameraTest, PinholeScalesWithDepthAndFlipsVertical) {
  CameraConfig c;
  const PinholeCamera cam(c);
  const double depth = 0.01 + c.camera_offset_mm * 1e-3;
  const auto up = cam.Project({0.01, 0.0, 0.002});
  const auto right = cam.Project({0.01, 0.002, 0.0});
  EXPECT_NEAR(up[1], c.cy_px - c.fy_px * 0.002 / depth, 1e-9);  // +z is up, image v grows down
  EXPECT_NEAR(right[0], c.cx_px + c.fx_px * 0.002 / depth, 1e-9);
}

TEST(CameraTest, ImageGainIsTheProjectionJacobiansNorm) {
  // The analytic gain against central differences of Project, off axis, and its bound:
  // no direction moves the image by more than the gain per metre.
  CameraConfig c;
  const PinholeCamera cam(c);
  const std::array<double, 3> p{0.012, 0.006, -0.004};
  constexpr double h = 1e-6;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    auto a = p, b = p;
    a[k] += h;
    b[k] -= h;
    const auto ua = cam.Project(a), ub = cam.Project(b);
    sum += (ua[0] - ub[0]) * (ua[0] - ub[0]) + (ua[1] - ub[1]) * (ua[1] - ub[1]);
  }
  const double numeric = std::sqrt(sum) / (2.0 * h);
  EXPECT_NEAR(cam.ImageGain(p), numeric, 1e-6 * numeric);
  auto q = p;
  q[2] += 1e-6;  // a step along z alone
  const auto u0 = cam.Project(p), u1 = cam.Project(q);
  EXPECT_LT(std::hypot(u1[0] - u0[0], u1[1] - u0[1]), cam.ImageGain(p) * 1e-6);
}

TEST(CameraTest, FramesSampleTheNearestPhysicsStep) {
  EXPECT_EQ(FrameStep(0, 100.0, 0.002), 0);
  EXPECT_EQ(FrameStep(7, 100.0, 0.002), 35);
  // 60 Hz on a 2 ms step: frame 1 at 16.67 ms -> step 8 (16 ms).
  EXPECT_EQ(FrameStep(1, 60.0, 0.002), 8);
}

TEST(CameraTest, NoiseHasConfiguredSpreadAndIsSeeded) {
  CameraConfig c;
  c.noise_model = "independent";
  c.pixel_noise_px = 0.5;
  c.dropout_prob = 0.0;
  DetectionNoise a(c, 42), b(c, 42);
  const int n = 20000;
  std::vector<float> pa(2 * n, 100.f), pb(2 * n, 100.f);
  std::vector<std::uint8_t> va(n), vb(n);
  a.Apply(pa, va, {});
  b.Apply(pb, vb, {});
  EXPECT_EQ(pa, pb);
  double s2 = 0.0;
  for (float v : pa) s2 += (v - 100.0) * (v - 100.0);
  EXPECT_NEAR(std::sqrt(s2 / (2.0 * n)), 0.5, 0.01);
  for (auto v : va) EXPECT_EQ(v, 1);
}

TEST(CameraTest, MissedPinKeepsItsPreviousPosition) {
  CameraConfig c;
  c.noise_model = "independent";
  c.dropout_prob = 0.3;
  DetectionNoise noise(c, 7);
  const int n = 1000;
  std::vector<float> prev(2 * n, 5.f), px(2 * n, 50.f);
  std::vector<std::uint8_t> valid(n);
  noise.Apply(px, valid, prev);
  int missed = 0;
  for (int i = 0; i < n; ++i) {
    if (valid[i]) continue;
    ++missed;
    EXPECT_EQ(px[2 * i], 5.f);
    EXPECT_EQ(px[2 * i + 1], 5.f);
  }
  EXPECT_NEAR(missed / double(n), 0.3, 0.05);
}

TEST(LabelsTest, GrossSlipOnlyWhenEveryContactingPinSlides) {
  LabelConfig cfg;
  std::vector<std::uint8_t> contact(4), slip(4);
  // Two touching pins, one sliding: partial slip.
  std::vector<PinContactSample> pins = {{true, 1e-3, 1.0}, {true, 1e-6, 1.0}, {false, 1.0, 0.0}, {false, 0.0, 0.0}};
  FrameLabels f = LabelFrame(pins, cfg, contact.data(), slip.data());
  EXPECT_EQ(f.n_contact, 2);
  EXPECT_EQ(f.n_slip, 1);
  EXPECT_EQ(f.gross_slip, 0);
  EXPECT_EQ(slip[2], 0) << "a pin out of contact never slips";
  // Both touching pins sliding: gross slip.
  pins[1].slip_speed_m_s = 2e-4;
  f = LabelFrame(pins, cfg, contact.data(), slip.data());
  EXPECT_EQ(f.gross_slip, 1);
  // No contact at all: no slip.
  pins = {{false, 1.0, 0.0}, {false, 1.0, 0.0}, {false, 1.0, 0.0}, {false, 1.0, 0.0}};
  EXPECT_EQ(LabelFrame(pins, cfg, contact.data(), slip.data()).gross_slip, 0);
}

TEST(LabelsTest, MotionInsideTheFrictionConeIsNotSlip) {
  // Fast relative motion at a force well inside the cone is contact compliance, not
  // Coulomb sliding.
  LabelConfig cfg;
  std::vector<std::uint8_t> contact(1), slip(1);
  std::vector<PinContactSample> pins = {{true, 5e-4, 0.2}};
  EXPECT_EQ(LabelFrame(pins, cfg, contact.data(), slip.data()).n_slip, 0);
  pins[0].cone_use = 0.99;
  EXPECT_EQ(LabelFrame(pins, cfg, contact.data(), slip.data()).n_slip, 1);
}

}  // namespace
}  // namespace tactip
