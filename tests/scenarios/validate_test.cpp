// The pin lattice against the brush model (physics.md: uncoupled pins stick while
// k_t u <= mu N_i; the transmitted load is sum_i min(k_t u, mu N_i)).

#include <gtest/gtest.h>

#include <cmath>

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

TEST(BrushModelTest, SpearmanHandlesTiesAndDirection) {
  EXPECT_NEAR(SpearmanCorrelation({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0, 1e-12);
  EXPECT_NEAR(SpearmanCorrelation({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0, 1e-12);
  // Ties share the average rank: x ranks (0.5, 0.5, 2), y ranks (0, 1, 2).
  EXPECT_NEAR(SpearmanCorrelation({1, 1, 2}, {1, 2, 3}), 0.8660254037844386, 1e-12);
  EXPECT_TRUE(std::isnan(SpearmanCorrelation({1}, {1})));
}

}  // namespace
}  // namespace tactip
