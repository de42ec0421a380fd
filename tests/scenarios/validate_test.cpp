// The pin lattice against the brush model (physics.md: uncoupled pins stick while
// k_t u <= mu N_i; the transmitted load is sum_i min(k_t u, mu N_i)).

#include <gtest/gtest.h>

#include "scenarios/validate.h"

namespace tactip {
namespace {

constexpr double kStateAgreement = 0.98;  // acceptance: pins in the brush model's state
constexpr double kLoadTolerance = 0.03;   // acceptance: transmitted load within 3 %

TEST(BrushModelTest, UncoupledLatticeMatchesTheBrushModel) {
  const BrushCheck c = RunBrushCheck(BrushCheckOptions{});
  ASSERT_GT(c.pins_in_contact, 19) << "the 2 mm press should load at least three rings";
  EXPECT_GE(c.state_agreement, kStateAgreement) << "over " << c.pin_samples << " pin-samples";
  EXPECT_LE(c.load_error_max, kLoadTolerance);
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

}  // namespace
}  // namespace tactip
