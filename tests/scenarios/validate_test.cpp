// The pin lattice against the brush model (physics.md: uncoupled pins stick while
// k_t u <= mu N_i; the transmitted load is sum_i min(k_t u, mu N_i)).

#include <gtest/gtest.h>

#include <cmath>

#include "scenarios/rail.h"
#include "scenarios/validate.h"

namespace tactip {
namespace {

constexpr double kStateAgreement = 0.98;  // acceptance: pins in the brush model's state
constexpr double kLoadTolerance = 0.03;   // acceptance: transmitted load within 3 %
constexpr double kSlipOrder = 0.9;        // acceptance: rank correlation of slip order and load

TEST(BrushModelTest, UncoupledLatticeMatchesTheBrushModel) {
  const BrushCheck c = RunBrushCheck(BrushCheckOptions{});
  ASSERT_GT(c.pins_in_contact, 19) << "the 2 mm press should load at least three rings";
  EXPECT_GE(c.state_agreement, kStateAgreement) << "over " << c.pin_samples << " pin-samples";
  EXPECT_LE(c.load_error_max, kLoadTolerance);
  EXPECT_GE(c.slip_order_correlation, kSlipOrder);
  // Outer (least loaded) pins slip first: the slipping count only grows with u, and the
  // ramp ends in gross slip carrying mu P.
  int prev = 0;
  for (const BrushSample& s : c.samples) {
    EXPECT_GE(s.slipping_brush, prev);
    prev = s.slipping_brush;
  }
  ASSERT_FALSE(c.samples.empty());
  EXPECT_EQ(c.samples.back().slipping, c.pins_in_contact);
  EXPECT_NEAR(c.samples.back().q_N, c.mu_P_N, kLoadTolerance * c.mu_P_N);
}

// The membrane-coupled fingerprint-v2 lattice under rising tangential load (physics.md:
// gross slip at Q = mu P; the stick region shrinks from the outside in).
TEST(DomeCheckTest, CoupledLatticeSlipsOutsideInAndGrossSlipsAtMuP) {
  DomeCheckOptions o;
  o.rig.skin = LoadConfig<RailScenarioConfig>("", SkinPreset("fingerprint-v2")).skin;
  ASSERT_EQ(o.rig.skin.pattern, "fingerprint-v2");
  o.rig.sim.timestep_s = 0.001;
  const DomeCheck c = RunDomeCheck(o);
  ASSERT_GE(c.pins_in_contact, 19);
  EXPECT_NEAR(c.gross_q_ratio, 1.0, 0.03);
  EXPECT_GE(c.outside_in_correlation, 0.9);
  // The stick region only shrinks while the load rises, from full stick to gross slip.
  ASSERT_FALSE(c.samples.empty());
  EXPECT_EQ(c.samples.front().sticking, c.samples.front().contacting);
  int prev = c.samples.front().sticking;
  for (const DomeSample& s : c.samples) {
    EXPECT_LE(s.sticking, prev) << "at Q/muP = " << s.q_ratio;
    prev = s.sticking;
  }
  EXPECT_EQ(c.samples.back().sticking, 0);
  // The fitted contact radius lies beyond the outermost contacting ring (9 mm at 3 mm
  // spacing) and short of the next (12 mm); the resolved stick boundary is a disc.
  EXPECT_GT(c.contact_radius_mm, 9.0);
  EXPECT_LT(c.contact_radius_mm, 12.0);
  for (const DomeSample& s : c.samples) EXPECT_LE(s.c_lo, s.c_hi + 1e-9) << "at Q/muP = " << s.q_ratio;
  EXPECT_GT(c.bracket_fraction, 0.0);
  EXPECT_LE(c.bracket_fraction, 1.0);
  // A membrane check needs the membrane lattice.
  DomeCheckOptions rigid = o;
  rigid.rig.skin.coupling = "shell";
  EXPECT_THROW(RunDomeCheck(rigid), InputError);
}

// Membrane coupling grows with skin thickness; a strongly coupled lattice releases each
// ring before Cattaneo-Mindlin does, a weakly coupled one stays between CM and the brush.
TEST(DomeCheckTest, ThinnerSkinKeepsTheStickBoundaryCloserToTheContinuumBand) {
  DomeCheckOptions o;
  o.rig.skin = LoadConfig<RailScenarioConfig>("", SkinPreset("fingerprint-v2")).skin;
  o.rig.sim.timestep_s = 0.001;
  o.shear_speed_mm_s = 0.3;
  o.rig.skin.thickness_mm = 0.3;
  const DomeCheck thin = RunDomeCheck(o);
  o.rig.skin.thickness_mm = 1.0;
  const DomeCheck thick = RunDomeCheck(o);
  EXPECT_NEAR(thin.gross_q_ratio, 1.0, 0.03);
  EXPECT_GE(thin.bracket_fraction, 0.9);
  EXPECT_GT(thin.bracket_fraction, thick.bracket_fraction + 0.1);
  // Same lattice, so the coupling lengths scale as sqrt(k_couple / k_tip).
  const PinLattice lattice = PinLattice::Build(o.rig.skin);
  const SkinMechanics m_thick = SkinMechanics::From(o.rig.skin, lattice);
  o.rig.skin.thickness_mm = 0.3;
  const SkinMechanics m_thin = SkinMechanics::From(o.rig.skin, lattice);
  ASSERT_GT(thin.coupling_length_mm, 0.0);
  EXPECT_NEAR(thick.coupling_length_mm / thin.coupling_length_mm,
              std::sqrt((m_thick.k_couple_N_m / m_thick.k_tip_N_m) / (m_thin.k_couple_N_m / m_thin.k_tip_N_m)), 1e-9);
  EXPECT_GT(thick.coupling_length_mm, thick.contact_radius_mm) << "v2's 1 mm membrane couples beyond the contact";
}

TEST(BrushModelTest, SpearmanHandlesTiesAndDirection) {
  EXPECT_NEAR(SpearmanCorrelation({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0, 1e-12);
  EXPECT_NEAR(SpearmanCorrelation({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0, 1e-12);
  // Ties share the average rank: x ranks (0.5, 0.5, 2), y ranks (0, 1, 2).
  EXPECT_NEAR(SpearmanCorrelation({1, 1, 2}, {1, 2, 3}), 0.8660254037844386, 1e-12);
  EXPECT_TRUE(std::isnan(SpearmanCorrelation({1}, {1})));
}

}  // namespace
}  // namespace tactip
