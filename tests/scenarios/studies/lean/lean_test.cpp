// The lean-scene study: it measures every variant of a scene, and `tactip bench --lean` prints its table,
// writes lean.csv, and refuses an unknown scene in one line before anything runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "mujoco_warning_guard.h"
#include "scenarios/studies/lean/lean.h"
#include "scenarios/rail/rail.h"
#include "temp_dir.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::RunTactip;
using testing::Slurp;

// A short protocol with contact: press, a 10 mm lift, retraction at 2 mm/s to the fall.
const std::vector<std::string> kShortLeanSets = {"rail.retract_speed_mm_s=2", "rail.lift_mm=10"};

// MeasureLean replays each variant with bare mj_step, on an mjData whose warnings only
// MuJoCo's hook sees.
class LeanSceneTest : public testing::MujocoWarningGuard {};

TEST_F(LeanSceneTest, TheVariantsAreTheLeanSceneAndEachOmissionPutBack) {
  const std::vector<LeanVariant> v = LeanVariants();
  ASSERT_GE(v.size(), 5u);
  EXPECT_EQ(v[0].name, "lean");
  const SceneOptions& o0 = v[0].options;
  EXPECT_FALSE(o0.all_pins_collide || o0.visual_geoms || o0.outer_sites || o0.object_free_joint);
  for (size_t i = 1; i < 5; ++i) {
    const SceneOptions& o = v[i].options;
    EXPECT_EQ(o.all_pins_collide + o.visual_geoms + o.outer_sites + o.object_free_joint, 1) << v[i].name;
    EXPECT_EQ(v[i].protocol, !o.object_free_joint) << v[i].name;
  }
}

TEST_F(LeanSceneTest, MeasuresEveryVariantWithContactAndTheLeanSceneIsTheSmallest) {
  LeanOptions o;
  o.overrides = kShortLeanSets;
  const std::vector<LeanRow> rows = MeasureLean(ChooseLeanScenes({"rail curved20"}), o);
  ASSERT_EQ(rows.size(), LeanVariants().size());
  const LeanRow& lean = rows[0];
  for (const auto& r : rows) {
    SCOPED_TRACE(r.variant.name);
    EXPECT_EQ(r.speed.scene.name, "rail curved20");
    EXPECT_GT(r.speed.profile.steps, 0);
    EXPECT_GT(r.physics_us(), 0.0);
    EXPECT_GT(r.bare_us(), 0.0);
    EXPECT_GT(r.speed.ncon_mean(), 0.0) << "the protocol presses the stimulus";
    EXPECT_GT(r.speed.nefc_mean(), r.speed.ncon_mean());
    EXPECT_GE(r.counts.ngeom, lean.counts.ngeom);
    EXPECT_GE(r.counts.nsite, lean.counts.nsite);
    EXPECT_GE(r.counts.nv, lean.counts.nv);
    EXPECT_GE(r.speed.memory_bytes, lean.speed.memory_bytes);
    if (r.variant.protocol) {
      // Same protocol, same contacts: only the model differs.
      EXPECT_EQ(r.speed.profile.steps, lean.speed.profile.steps);
      EXPECT_DOUBLE_EQ(r.speed.nefc_mean(), lean.speed.nefc_mean());
    }
  }
  EXPECT_GT(rows[1].counts.ngeom_collidable, lean.counts.ngeom_collidable);  // + all pins collide
  EXPECT_GT(rows[1].speed.memory_bytes, lean.speed.memory_bytes);
  EXPECT_GT(rows[2].counts.ngeom, lean.counts.ngeom);                        // + visual geoms
  EXPECT_GT(rows[3].counts.nsite, lean.counts.nsite);                        // + outer sites
  EXPECT_EQ(rows[4].counts.nv, lean.counts.nv + 5);                          // + free object
}

TEST_F(LeanSceneTest, AnUnknownSceneIsRefused) {
  EXPECT_THROW(ChooseLeanScenes({"rail bumpy"}), InputError);
  EXPECT_EQ(ChooseLeanScenes({}).size(), 2u);
}

class LeanCliTest : public ::testing::Test {
 protected:
  tactip::testing::TestTempDir temp_{"lean_test"};
};

TEST_F(LeanCliTest, PrintsTheTableAndWritesOneCsvRowPerVariant) {
  const CliResult r = RunTactip("bench --lean --scene \"rail curved20\" --set rail.retract_speed_mm_s=2 --set "
                                "rail.lift_mm=10 --out " + temp_.File("lean"),
                                temp_.path());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const auto& v : LeanVariants()) EXPECT_NE(r.out.find(v.name), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("bench --lean: rail curved20, lean"), std::string::npos) << r.err;
  std::istringstream csv(Slurp(temp_.path() / "lean" / "lean.csv"));
  std::string header, row;
  ASSERT_TRUE(std::getline(csv, header));
  EXPECT_EQ(header.rfind("scene,variant,rail_protocol,nv,ngeom", 0), 0u) << header;
  int rows = 0;
  while (std::getline(csv, row)) {
    ++rows;
    EXPECT_EQ(row.rfind("\"rail curved20\",", 0), 0u) << row;
  }
  EXPECT_EQ(rows, static_cast<int>(LeanVariants().size()));
}

TEST_F(LeanCliTest, AnUnknownSceneIsOneLineAndNothingRuns) {
  const CliResult r = RunTactip("bench --lean --scene \"rail bumpy\" --out " + temp_.File("lean"), temp_.path());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(r.err.rfind("tactip: unknown speed scene 'rail bumpy'", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(temp_.path() / "lean" / "lean.csv"));
}

TEST_F(LeanCliTest, LeanAndSpeedAreSeparateStudies) {
  const CliResult r = RunTactip("bench --lean --speed", temp_.path());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--speed"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tactip
