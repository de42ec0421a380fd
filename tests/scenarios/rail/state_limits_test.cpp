// Physically impossible states stop a rail run: the limits of a frame (a pin marker a dome
// radius from where it rests, a pin or the skin pressed far beyond what the press and the
// object's weight allow), and a run whose solver diverges without any MuJoCo warning (one
// Newton iteration, below the allowed range) stopped with a message instead of being
// recorded.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "scenarios/rail/rail_run.h"
#include "scenarios/studies/stability/stability_suite.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

TEST(StateLimitsTest, LimitsFollowThePressTheWeightAndTheDome) {
  RailScenarioConfig c;  // 3 mm press + 0.1 mm jitter, 100 g, 20 mm dome
  const StateLimits l = RailStateLimits(c, 70);
  EXPECT_DOUBLE_EQ(l.max_marker_shift_m, 0.020);
  // k_normal + 12 k_bend of the default skin: 39.0 + 12 x 12.35 = 187.1 N/m, 0.77 N at 4.1 mm,
  // plus 0.98 N of weight and 5 mN of rail friction.
  EXPECT_NEAR(l.max_pin_force_N, 2.0 * (187.1 * 4.1e-3 + 0.1 * 9.81 + 0.005), 0.01);
  EXPECT_NEAR(l.max_total_force_N, 2.0 * (70 * 187.1 * 4.1e-3 + 0.1 * 9.81 + 0.005), 0.1);
  // A heavier object and a deeper press allow more.
  c.object.mass_kg = 5.0;
  c.rail.press_depth_mm = 7.0;
  c.rail.press_depth_jitter_mm = 0.0;
  const StateLimits heavy = RailStateLimits(c, 70);
  EXPECT_GT(heavy.max_pin_force_N, l.max_pin_force_N + 2.0 * 48.0);
  EXPECT_GT(heavy.max_total_force_N, l.max_total_force_N);
}

TEST(StateLimitsTest, AControllerThatPressesDeeperDeepensTheLimits) {
  // A catch 3.9 mm past the 3.1 mm protocol press: the limits of an 8 mm press plus margin.
  const RailScenarioConfig c;
  const StateLimits l = RailStateLimits(c, 70, 3.9e-3);
  EXPECT_NEAR(l.max_pin_force_N, 2.0 * (187.1 * 8.0e-3 + 0.1 * 9.81 + 0.005), 0.01);
  EXPECT_NEAR(l.max_total_force_N, 2.0 * (70 * 187.1 * 8.0e-3 + 0.1 * 9.81 + 0.005), 0.2);
}

TEST(StateLimitsTest, AbsurdFramesAreNamedAndPlausibleOnesPass) {
  StateLimits l;
  l.max_marker_shift_m = 0.02;
  l.max_pin_force_N = 4.0;
  l.max_total_force_N = 100.0;
  const std::vector<double> shifts(10, 0.004), forces(10, 0.5);  // a firm press: 4 mm, 0.5 N per pin
  EXPECT_EQ(ImplausibleState(l, shifts, forces), "");
  auto far = shifts;
  far[3] = 83.0;
  EXPECT_EQ(ImplausibleState(l, far, forces),
            "pin 3's marker is 8.3e+04 mm from where it rests, beyond the dome's 20 mm radius");
  auto nan = shifts;
  nan[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(ImplausibleState(l, nan, forces).find("pin 1's marker is nan mm"), std::string::npos);
  auto hard = forces;
  hard[7] = 4285.0;
  EXPECT_EQ(ImplausibleState(l, shifts, hard),
            "pin 7 carries 4.28e+03 N, more than 2 times the 2 N that the deepest press and the object's weight allow");
  const std::vector<double> many(40, 3.0);  // each pin within its 4 N, 120 N in total
  EXPECT_EQ(ImplausibleState(l, std::vector<double>(40, 0.004), many),
            "the pins carry 120 N in total, more than 2 times the 50 N that the deepest press on every pin that can "
            "touch and the object's weight allow");
}

// The smooth skin on the flat plate on the stability suite's short protocol.
RailScenarioConfig ShortFlatRun() {
  return ApplyConfig<RailScenarioConfig>("", StabilityProtocol());
}

TEST(StateLimitsTest, ADivergingSolverStopsTheRunInsteadOfRecordingIt) {
  // One Newton iteration per step (the config refuses fewer than SimConfig::kMinIterations,
  // so the scene is built directly): no MuJoCo warning fires, but once the object leaves
  // the pins are thrown metres away with kN forces.
  RailScenarioConfig c = ShortFlatRun();
  c.sim.iterations = 1;
  const RailScene ids(c, SceneOptions{});
  RailRun run(c, ids, 0, 1);
  RunRecord rec;
  std::string message;
  try {
    run.Execute(rec, nullptr);
  } catch (const SimulationError& e) {
    message = e.what();
  }
  EXPECT_EQ(message.rfind("run 0 stopped at t = ", 0), 0u) << message;
  EXPECT_NE(message.find("the solver diverged without a MuJoCo warning; use a smaller sim.timestep_s or more "
                         "sim.iterations"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(StateLimitsTest, TheSameRunAtTheDefaultIterationsRunsThrough) {
  const RailScenarioConfig c = ShortFlatRun();
  const RailScene ids(c, SceneOptions{});
  RailRun run(c, ids, 0, 1);
  RunRecord rec;
  EXPECT_NO_THROW(run.Execute(rec, nullptr));
  EXPECT_GT(rec.frames(), 100u);
}

}  // namespace
}  // namespace tactip
