// The lean rail scene and the parts SceneOptions puts back: each switch changes the model
// in its own part only (DOFs, contact geoms, visual geoms, sites), and the default scene
// has the smaller count.

#include <gtest/gtest.h>

#include <string>

#include "mujoco_warning_guard.h"
#include "models/rail_rig.h"
#include "sim/model_counts.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

struct Built {
  BuiltScene scene;
  ModelCounts counts;
};

Built Build(const std::string& stimulus, const SceneOptions& options, bool external_markers = false) {
  RailSceneSpec spec;
  spec.rail.stimulus = stimulus;
  spec.max_depth_m = 3.1e-3;
  spec.external_markers = external_markers;
  spec.options = options;
  Built b;
  b.scene = BuildRailScene(spec);
  b.counts = CountModel(CompiledModel::FromXml(b.scene.xml));
  return b;
}

// Every test compiles scenes, which runs MuJoCo (its setup pass on a scratch mjData): no warning allowed.
class SceneOptionsTest : public testing::MujocoWarningGuard {};

TEST_F(SceneOptionsTest, TheLeanSceneHasOnlyWhatItsRunsNeed) {
  for (const char* stimulus : {"flat", "curved40"}) {
    SCOPED_TRACE(stimulus);
    const Built lean = Build(stimulus, SceneOptions{});
    const ModelCounts& c = lean.counts;
    EXPECT_EQ(c.ngeom, c.ngeom_collidable) << "no visual-only geoms";
    EXPECT_EQ(c.ngeom_collidable, lean.scene.n_collidable + 1) << "the reachable pins and the stimulus";
    EXPECT_LT(lean.scene.n_collidable, lean.scene.n_pins);
    EXPECT_EQ(c.nsite, lean.scene.n_pins + 1) << "every inner marker, the centre pin's contact point";
    EXPECT_EQ(c.ncam, 0) << "the cameras are projections of sites, not MuJoCo cameras";
    EXPECT_EQ(c.nlight, 0);
    EXPECT_EQ(c.nv, 3 + 2 + lean.scene.n_pins) << "rail slide, arm x and z, shell shear y and z, one per pin";
  }
}

TEST_F(SceneOptionsTest, AllPinsCollidePutsAContactGeomOnEveryPin) {
  const Built lean = Build("flat", SceneOptions{});
  SceneOptions o;
  o.all_pins_collide = true;
  const Built all = Build("flat", o);
  EXPECT_EQ(all.scene.n_collidable, all.scene.n_pins);
  EXPECT_EQ(all.counts.ngeom_collidable, all.scene.n_pins + 1);
  EXPECT_GT(all.counts.nconmax, lean.counts.nconmax);
  EXPECT_GT(all.counts.njmax, lean.counts.njmax);
  EXPECT_EQ(all.counts.nv, lean.counts.nv);
  EXPECT_EQ(all.counts.nsite, lean.counts.nsite);
}

TEST_F(SceneOptionsTest, VisualGeomsAddTheBeamHousingPlateAndLightButNoContact) {
  SceneOptions o;
  o.visual_geoms = true;
  for (const char* stimulus : {"flat", "curved40"}) {
    SCOPED_TRACE(stimulus);
    const Built lean = Build(stimulus, SceneOptions{});
    const Built visual = Build(stimulus, o);
    const int added = std::string(stimulus) == "flat" ? 2 : 3;  // beam, housing (, base plate)
    EXPECT_EQ(visual.counts.ngeom, lean.counts.ngeom + added);
    EXPECT_EQ(visual.counts.ngeom_collidable, lean.counts.ngeom_collidable);
    EXPECT_EQ(visual.counts.nlight, 1);
    EXPECT_EQ(visual.counts.nv, lean.counts.nv);
    EXPECT_NE(visual.scene.xml.find("tactip/housing"), std::string::npos);
    EXPECT_EQ(lean.scene.xml.find("tactip/housing"), std::string::npos);
  }
}

TEST_F(SceneOptionsTest, OuterSitesOnEveryPinWithTheExternalCameraOrWhenAsked) {
  const Built lean = Build("acrylic", SceneOptions{});
  SceneOptions o;
  o.outer_sites = true;
  const Built sites = Build("acrylic", o);
  const Built external = Build("acrylic", SceneOptions{}, true);
  EXPECT_EQ(sites.counts.nsite, 2 * sites.scene.n_pins);
  EXPECT_EQ(external.counts.nsite, 2 * external.scene.n_pins);
  EXPECT_EQ(lean.counts.nsite, lean.scene.n_pins + 1);
  EXPECT_EQ(sites.counts.ngeom, lean.counts.ngeom);
  EXPECT_EQ(sites.counts.nv, lean.counts.nv);
  const CompiledModel m = CompiledModel::FromXml(lean.scene.xml);
  EXPECT_NO_THROW(m.SiteId(SkinNames{"tactip/"}.PinOuterSite(0)));
  EXPECT_THROW(m.SiteId(SkinNames{"tactip/"}.PinOuterSite(1)), ModelError);
}

TEST_F(SceneOptionsTest, AFreeObjectHasSixDofsWhereTheRailHasOne) {
  const Built lean = Build("curved40", SceneOptions{});
  SceneOptions o;
  o.object_free_joint = true;
  const Built free = Build("curved40", o);
  EXPECT_EQ(free.counts.nv, lean.counts.nv + 5);
  EXPECT_EQ(free.counts.ngeom, lean.counts.ngeom);
  EXPECT_NE(free.scene.xml.find("type=\"free\""), std::string::npos);
  EXPECT_EQ(free.scene.xml.find("frictionloss"), std::string::npos) << "no rail friction without the rail";
}

}  // namespace
}  // namespace tactip
