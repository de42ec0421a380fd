// The speed study: timing a run leaves its physics and output unchanged, bare mj_step
// replays the same run, and `tactip bench --speed` prints the table and writes speed.csv
// (or names an unknown scene).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "mujoco_warning_guard.h"
#include "scenarios/rail/rail.h"
#include "scenarios/studies/speed/speed.h"
#include "temp_dir.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::RunTactip;
using testing::Slurp;

RailScenarioConfig ShortSpeedRun() {
  RailScenarioConfig cfg;
  cfg.rail.stimulus = "curved20";
  cfg.rail.retract_speed_mm_s = 2.0;
  cfg.rail.lift_mm = 10.0;
  return cfg;
}

// The bare mj_step replay runs on an mjData whose warnings only MuJoCo's hook sees.
class SpeedStudyTest : public testing::MujocoWarningGuard {};

TEST_F(SpeedStudyTest, TimingARunChangesNeitherItsPhysicsNorItsRecord) {
  const RailScenario scenario(ShortSpeedRun());
  RunRecord plain, timed;
  RunInstrumentation inst;
  const RailRunSummary a = scenario.Run(0, 5, plain);
  const RailRunSummary b = scenario.RunInstrumented(0, 5, timed, inst);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.gross_slip_onset_s, b.gross_slip_onset_s);
  ASSERT_EQ(plain.sensors[0].pos_px.size(), timed.sensors[0].pos_px.size());
  EXPECT_EQ(plain.sensors[0].pos_px, timed.sensors[0].pos_px);
  EXPECT_EQ(plain.sensors[0].normal_N, timed.sensors[0].normal_N);
  EXPECT_EQ(plain.sensors[0].pin_slip, timed.sensors[0].pin_slip);
  // Every step was timed and its controls kept for the bare replay.
  EXPECT_EQ(inst.profile.steps, b.steps);
  EXPECT_EQ(inst.ctrl.size(), static_cast<size_t>(2 * b.steps));
  EXPECT_GT(inst.profile.step1_s, 0.0);
  EXPECT_GT(inst.profile.solve_s, 0.0);
  EXPECT_GT(inst.profile.friction_pass_s, 0.0);
  EXPECT_GT(inst.profile.nefc_sum, inst.profile.ncon_sum);  // a contact is at least one row; the rail adds more
}

TEST_F(SpeedStudyTest, BareReplayRunsTheSameStepsOnTheSameModel) {
  const RailScenario scenario(ShortSpeedRun());
  RunRecord rec;
  RunInstrumentation inst;
  const RailRunSummary s = scenario.RunInstrumented(0, 5, rec, inst);
  ASSERT_FALSE(std::isnan(s.gross_slip_onset_s));
  // The run refines its step at the gross-slip onset; the replay takes the same steps, so it
  // covers the run's simulated time (at the held step alone it would fall short).
  const double held = scenario.model().timestep();
  ASSERT_EQ(inst.timestep_s.size(), static_cast<size_t>(s.steps));
  EXPECT_EQ(inst.timestep_s.front(), held);
  EXPECT_LT(inst.timestep_s.back(), held);
  const BareReplay bare = ReplayBareSteps(scenario.model(), inst.ctrl, inst.timestep_s);
  EXPECT_GT(bare.wall_s, 0.0);
  EXPECT_NEAR(bare.sim_s, s.sim_time_s, 1e-9);
  EXPECT_GT(static_cast<double>(s.steps) * held - s.sim_time_s, held);
  // The shared model keeps its step.
  EXPECT_EQ(scenario.model().timestep(), held);
  // A replay of a different length is refused rather than timed.
  std::vector<double> odd = inst.ctrl;
  odd.pop_back();
  EXPECT_THROW(ReplayBareSteps(scenario.model(), odd, inst.timestep_s), std::invalid_argument);
  std::vector<double> short_steps(inst.timestep_s.begin(), inst.timestep_s.end() - 1);
  EXPECT_THROW(ReplayBareSteps(scenario.model(), inst.ctrl, short_steps), std::invalid_argument);
}

class SpeedCliTest : public ::testing::Test {
 protected:
  tactip::testing::TestTempDir temp_{"speed_test"};
};

TEST_F(SpeedCliTest, PrintsTheTableAndWritesOneCsvRowPerScene) {
  const CliResult r = RunTactip("bench --speed --scene \"rail curved20\" --set rail.retract_speed_mm_s=2 --set "
                                "rail.lift_mm=10 --out " + temp_.File("speed"),
                                temp_.path());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rail curved20"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cost split"), std::string::npos) << r.out;
  std::istringstream csv(Slurp(temp_.path() / "speed" / "speed.csv"));
  std::string header, row, extra;
  ASSERT_TRUE(std::getline(csv, header));
  ASSERT_TRUE(std::getline(csv, row));
  EXPECT_FALSE(std::getline(csv, extra));
  EXPECT_EQ(header.rfind("scene,sim_s,run_wall_s,physics_wall_s,bare_wall_s,rtf_run", 0), 0u) << header;
  // sim_s, run, physics, bare wall times: the physics steps are part of the run.
  std::vector<double> v;
  std::istringstream cells(row.substr(row.find("\",") + 2));
  for (std::string c; std::getline(cells, c, ',');) v.push_back(std::stod(c));
  ASSERT_GE(v.size(), 8u);
  EXPECT_GT(v[0], 1.0);
  EXPECT_GT(v[1], 0.0);
  EXPECT_LT(v[2], v[1]);
  EXPECT_GT(v[3], 0.0);
  EXPECT_NEAR(v[4], v[0] / v[1], 1e-3 * v[4]);  // rtf_run = sim_s / run_wall_s
}

TEST_F(SpeedCliTest, AnUnknownSceneIsNamedAndNothingRuns) {
  const CliResult r = RunTactip("bench --speed --scene \"rail bumpy\" --out " + temp_.File("speed"), temp_.path());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("unknown speed scene 'rail bumpy'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bench --speed: one run"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(temp_.path() / "speed" / "speed.csv"));
}

}  // namespace
}  // namespace tactip
