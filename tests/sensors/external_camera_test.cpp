// The external camera of the transparent rig (a mirrored view of the skin's outside) and
// the per-frame partial-slip label derived from per-pin labels.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "sensors/camera.h"
#include "sensors/dataset.h"

namespace tactip {
namespace {

constexpr double kApexM = 0.022;  // fingerprint dome: 20 mm + 2 mm ridges

TEST(ExternalCameraTest, DefaultsAreValidAndDisabled) {
  ExternalCameraConfig c;
  EXPECT_NO_THROW(ValidateConfig(c));
  EXPECT_FALSE(c.enabled);
}

TEST(ExternalCameraTest, AxisPointProjectsToPrincipalPoint) {
  ExternalCameraConfig c;
  c.cx_px = 300.0;
  c.cy_px = 200.0;
  const ExternalCamera cam(c, kApexM);
  const auto uv = cam.Project({kApexM, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(uv[0], 300.0);
  EXPECT_DOUBLE_EQ(uv[1], 200.0);
}

TEST(ExternalCameraTest, ImageIsMirroredHorizontallyRelativeToTheInternalCamera) {
  ExternalCameraConfig ec;
  CameraConfig ic;
  const ExternalCamera ext(ec, kApexM);
  const PinholeCamera in(ic);
  // A point to the sensor's +y side and above the axis, on the skin.
  const std::array<double, 3> p{0.02, 0.005, 0.003};
  const auto e = ext.Project(p);
  const auto i = in.Project(p);
  EXPECT_LT(e[0], ec.cx_px) << "external view: +y appears left of centre";
  EXPECT_GT(i[0], ic.cx_px) << "internal view: +y appears right of centre";
  // Both cameras are upright: +z is up (smaller v) in both images.
  EXPECT_LT(e[1], ec.cy_px);
  EXPECT_LT(i[1], ic.cy_px);
  // Pinhole at distance_mm in front of the apex, looking back along -x.
  const double depth = kApexM + ec.distance_mm * 1e-3 - p[0];
  EXPECT_NEAR(e[0], ec.cx_px - ec.f_px * p[1] / depth, 1e-9);
  EXPECT_NEAR(e[1], ec.cy_px - ec.f_px * p[2] / depth, 1e-9);
  // Mirror symmetry: the point at -y lands where +y lands in the internal orientation.
  const auto m = ext.Project({p[0], -p[1], p[2]});
  EXPECT_NEAR(m[0] - ec.cx_px, ec.cx_px - e[0], 1e-9);
  EXPECT_NEAR(m[1], e[1], 1e-12);
}

TEST(ExternalCameraTest, PointsFartherFromTheCameraLookSmaller) {
  ExternalCameraConfig c;
  const ExternalCamera cam(c, kApexM);
  // The apex region is nearer to the external camera than the dome's rim.
  const auto near = cam.Project({kApexM, 0.004, 0.0});
  const auto far = cam.Project({0.0, 0.004, 0.0});
  EXPECT_GT(c.cx_px - near[0], c.cx_px - far[0]);
  EXPECT_GT(c.cx_px - far[0], 0.0);
  // Moving the camera away shrinks the image.
  ExternalCameraConfig away = c;
  away.distance_mm = 2.0 * c.distance_mm;
  const auto shrunk = ExternalCamera(away, kApexM).Project({kApexM, 0.004, 0.0});
  EXPECT_NEAR(c.cx_px - shrunk[0], 0.5 * (c.cx_px - near[0]), 1e-9);
}

// ---- Partial-slip labels --------------------------------------------------------------

TEST(PartialSlipLabelsTest, PartialOnlyWhenSomeContactingPinsSlideAndOthersStick) {
  // 3 pins, one row per frame.
  const std::vector<std::uint8_t> contact = {
      0, 0, 0,  // no contact
      1, 1, 1,  // all stick
      1, 1, 1,  // one slides: partial
      1, 1, 1,  // all slide: gross, not partial
      1, 1, 0,  // both contacting pins slide: gross, not partial
      1, 1, 0,  // slip flag on a pin out of contact does not count
      1, 0, 1,  // one of two contacting pins slides: partial
  };
  const std::vector<std::uint8_t> slip = {
      0, 0, 0,  //
      0, 0, 0,  //
      0, 1, 0,  //
      1, 1, 1,  //
      1, 1, 0,  //
      0, 0, 1,  //
      0, 1, 1,  //
  };
  EXPECT_EQ(PartialSlipLabels(contact, slip, 3), (std::vector<std::uint8_t>{0, 0, 1, 0, 0, 0, 1}));
}

TEST(PartialSlipLabelsTest, OneLabelPerFrame) {
  const std::vector<std::uint8_t> contact(5 * 127, 1), slip(5 * 127, 0);
  EXPECT_EQ(PartialSlipLabels(contact, slip, 127).size(), 5u);
  EXPECT_TRUE(PartialSlipLabels({}, {}, 127).empty());
}

}  // namespace
}  // namespace tactip
