// The scene-size estimate that configs are checked against before anything is built: its
// pins, DOFs and constraint rows equal those of the compiled scene for every coupling, and
// its solver stack is the one MuJoCo reserves.

#include <gtest/gtest.h>

#include <string>

#include "mujoco_warning_guard.h"
#include "models/scene_size.h"
#include "sim/model_counts.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

RailSceneSpec Spec(const std::string& coupling, const std::string& pattern, const std::string& stimulus) {
  RailSceneSpec spec;
  spec.skin.coupling = coupling;
  spec.skin.pattern = pattern;
  spec.rail.stimulus = stimulus;
  spec.max_depth_m = 3.1e-3;
  return spec;
}

// Compiling a scene runs MuJoCo (its setup pass on a scratch mjData): no warning allowed.
class SceneSizeTest : public testing::MujocoWarningGuard {};

TEST_F(SceneSizeTest, EstimateEqualsTheCompiledScene) {
  const RailSceneSpec specs[] = {Spec("shell", "smooth", "flat"), Spec("membrane", "fingerprint-v2", "acrylic"),
                                 Spec("none", "smooth", "curved40"), Spec("membrane", "fingerprint-v1", "curved20")};
  for (RailSceneSpec spec : specs) {
    SCOPED_TRACE(spec.skin.coupling + " " + spec.skin.pattern + " " + spec.rail.stimulus);
    for (bool free_object : {false, true}) {
      spec.options.object_free_joint = free_object;
      const SceneSize est = EstimateRailScene(spec);
      const BuiltScene built = BuildRailScene(spec);
      const CompiledModel model = CompiledModel::FromXml(built.xml);
      const ModelCounts counts = CountModel(model);
      EXPECT_EQ(est.n_pins, built.n_pins);
      EXPECT_EQ(est.n_collidable, built.n_collidable);
      EXPECT_EQ(est.nv, counts.nv);
      EXPECT_EQ(est.njmax, counts.njmax);
      // MuJoCo's stack: 5 (njmax + nv)^2 numbers plus a term linear in the model's size.
      const double stack = static_cast<double>(counts.nstack) * 8.0;
      EXPECT_LE(est.stack_bytes, stack);
      EXPECT_GT(est.stack_bytes, 0.9 * stack);
      EXPECT_TRUE(est.Fits());
    }
  }
}

TEST_F(SceneSizeTest, AFingerprintSkinWithThousandsOfPinsDoesNotFit) {
  // 24 pins per ring on 1 mm rings out to 18 mm: 4105 pins (MuJoCo cannot create its data).
  RailSceneSpec spec = Spec("membrane", "fingerprint-v2", "acrylic");
  spec.skin.pins_per_ring = 24;
  spec.skin.ridge_spacing_mm = 1.0;
  spec.skin.pattern_radius_mm = 18.0;
  const SceneSize s = EstimateRailScene(spec);
  EXPECT_EQ(s.n_pins, 1 + 24 * (18 * 19 / 2));
  EXPECT_FALSE(s.Fits());
  EXPECT_GT(s.stack_bytes, 8.0 * kMaxSolverStackBytes);
}

}  // namespace
}  // namespace tactip
