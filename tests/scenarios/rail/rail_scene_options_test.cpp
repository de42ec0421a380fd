// The rail scenario on a scene with the parts it leaves out put back (SceneOptions): the
// runs record exactly what they record on the lean scene, and a free object runs.

#include <gtest/gtest.h>

#include <cmath>

#include "mujoco_warning_guard.h"
#include "scenarios/rail/rail.h"

namespace tactip {
namespace {

RailScenarioConfig ShortRun() {
  RailScenarioConfig cfg;
  cfg.rail.stimulus = "curved20";
  cfg.rail.retract_speed_mm_s = 2.0;
  cfg.rail.lift_mm = 10.0;
  return cfg;
}

// The runs must go without a MuJoCo warning (a warning also stops the run).
class RailSceneOptionsTest : public testing::MujocoWarningGuard {};

TEST_F(RailSceneOptionsTest, PuttingThePartsBackChangesNothingARunRecords) {
  // Smooth skin: every pin keeps its normal DOF, so a contact geom on a pin that cannot
  // reach the stimulus adds no physics either.
  const RailScenarioConfig cfg = ShortRun();
  SceneOptions back;
  back.all_pins_collide = back.visual_geoms = back.outer_sites = true;
  const RailScenario lean(cfg), full(cfg, back);
  EXPECT_GT(full.n_collidable(), lean.n_collidable());
  RunRecord a, b;
  const RailRunSummary sa = lean.Run(0, 5, a);
  const RailRunSummary sb = full.Run(0, 5, b);
  EXPECT_EQ(sa.steps, sb.steps);
  EXPECT_EQ(sa.gross_slip_onset_s, sb.gross_slip_onset_s);
  EXPECT_EQ(sa.creep_um, sb.creep_um);
  EXPECT_EQ(a.sensors[0].pos_px, b.sensors[0].pos_px);
  EXPECT_EQ(a.sensors[0].normal_N, b.sensors[0].normal_N);
  EXPECT_EQ(a.sensors[0].tangential_N, b.sensors[0].tangential_N);
  EXPECT_EQ(a.sensors[0].pin_slip, b.sensors[0].pin_slip);
  EXPECT_EQ(a.object_height_m, b.object_height_m);
}

TEST_F(RailSceneOptionsTest, AFreeObjectIsPressedAndLeftBehindInTheLift) {
  // Held by damping instead of the rail: the skin presses it, then slides over it.
  SceneOptions o;
  o.object_free_joint = true;
  const RailScenario free(ShortRun(), o);
  RunRecord rec;
  const RailRunSummary s = free.Run(0, 5, rec);
  EXPECT_FALSE(s.held);
  EXPECT_FALSE(std::isnan(s.object_fall_s)) << "left behind during the lift";
  float total_N = 0.0f;
  for (float n : rec.sensors[0].normal_N) total_N += n;
  EXPECT_GT(total_N, 0.0f) << "the skin touched the object";
}

}  // namespace
}  // namespace tactip
