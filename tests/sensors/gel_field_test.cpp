#include "sensors/gel_field.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tactip {
namespace {

constexpr double kTangentTol = 1e-12;  // m: a shift along the dome's surface has no normal part

std::array<double, 3> Meridian(const PinGeometry& p) {
  const double ct = std::cos(p.polar_rad), st = std::sin(p.polar_rad);
  return {-st, ct * std::cos(p.azimuth_rad), ct * std::sin(p.azimuth_rad)};
}

double Dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double Norm(const std::array<double, 3>& a) { return std::sqrt(Dot(a, a)); }

struct Field {
  SkinConfig skin;
  PinLattice lattice;
  GelField gel;
  explicit Field(SkinConfig s = {}) : skin(s), lattice(PinLattice::Build(skin)), gel(GelField::Build(skin, lattice)) {}
  // Shifts with only pin `j` indented by `w_m`.
  std::vector<std::array<double, 3>> Indent(int j, double w_m) const {
    std::vector<double> w(lattice.size(), 0.0);
    w[j] = w_m;
    std::vector<std::array<double, 3>> shift;
    gel.Shifts(w, shift);
    return shift;
  }
};

TEST(GelFieldTest, PinsMarkerModelHasNoField) {
  SkinConfig skin;
  skin.marker_model = "pins";
  EXPECT_TRUE(GelField::Build(skin, PinLattice::Build(skin)).empty());
  EXPECT_FALSE(Field().gel.empty());
  EXPECT_EQ(Field().gel.n_pins(), 127);
}

TEST(GelFieldTest, NoIndentationMovesNothing) {
  const Field f;
  std::vector<double> w(f.lattice.size(), 0.0);
  w[5] = -1e-3;  // a pin pulled outwards squeezes nothing
  std::vector<std::array<double, 3>> shift;
  f.gel.Shifts(w, shift);
  ASSERT_EQ(shift.size(), f.lattice.size());
  for (const auto& s : shift) EXPECT_EQ(Norm(s), 0.0);
}

TEST(GelFieldTest, SqueezeIsLinearWhenShallowAndSaturatesWhenDeep) {
  const Field f;
  const double h = f.skin.gel_squeeze_mm * 1e-3;
  EXPECT_NEAR(f.gel.Squeeze(0.01 * h), 0.01 * h, 1e-6 * h);
  EXPECT_NEAR(f.gel.Squeeze(10.0 * h), h, 1e-6 * h);
  EXPECT_LT(f.gel.Squeeze(h), f.gel.Squeeze(2.0 * h));
}

TEST(GelFieldTest, AnIndentedApexPushesEveryMarkerOutwardAlongTheDome) {
  const Field f;
  const auto shift = f.Indent(0, 1e-3);
  EXPECT_EQ(Norm(shift[0]), 0.0);  // a source does not move itself
  double previous_ring_mean = INFINITY;
  for (int ring = 1; ring <= f.skin.rings; ++ring) {
    double sum = 0.0;
    int n = 0;
    for (size_t i = 1; i < f.lattice.size(); ++i) {
      const PinGeometry& p = f.lattice.pins[i];
      if (p.ring != ring) continue;
      EXPECT_NEAR(Dot(shift[i], p.normal), 0.0, kTangentTol) << "pin " << i;
      EXPECT_GT(Dot(shift[i], Meridian(p)), 0.0) << "pin " << i;
      sum += Norm(shift[i]);
      ++n;
    }
    EXPECT_LT(sum / n, previous_ring_mean) << "ring " << ring;  // the flow spreads and weakens
    previous_ring_mean = sum / n;
  }
}

TEST(GelFieldTest, AThinnerFlowLayerMovesTheMarkersFurther) {
  SkinConfig thin;
  thin.gel_flow_depth_mm = 0.5 * SkinConfig{}.gel_flow_depth_mm;
  const auto base = Field().Indent(0, 1e-3), halved = Field(thin).Indent(0, 1e-3);
  for (size_t i = 1; i < base.size(); ++i) EXPECT_NEAR(Norm(halved[i]), 2.0 * Norm(base[i]), 1e-12);
}

TEST(GelFieldTest, SourcesSuperpose) {
  const Field f;
  std::vector<double> w(f.lattice.size(), 0.0);
  w[3] = 0.2e-3;
  w[40] = 0.7e-3;
  std::vector<std::array<double, 3>> both;
  f.gel.Shifts(w, both);
  const auto a = f.Indent(3, 0.2e-3), b = f.Indent(40, 0.7e-3);
  for (size_t i = 0; i < both.size(); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(both[i][c], a[i][c] + b[i][c], 1e-15);
  }
}

TEST(GelFieldTest, FingerprintLatticesGetAFieldToo) {
  SkinConfig v2;
  for (const std::string& assignment : SkinPreset("fingerprint-v2")) {
    auto [key, value] = ParseAssignment(assignment);
    ApplyFlat(v2, FlatConfig{{key.substr(5), value}});  // strip "skin."
  }
  const Field f(v2);
  EXPECT_EQ(f.gel.n_pins(), static_cast<int>(f.lattice.size()));
  const auto shift = f.Indent(0, 1e-3);
  EXPECT_GT(Dot(shift[1], Meridian(f.lattice.pins[1])), 0.0);
}

}  // namespace
}  // namespace tactip
