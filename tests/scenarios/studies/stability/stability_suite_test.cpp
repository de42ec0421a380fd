// The stability suite and the automatic timestep: every refusal of the suite with its message
// (through the library and the command line, exit code 2), the case table, one healthy and
// one refused case through `tactip stability --case`, `--set` applied to every case beneath
// its own keys, the empty contact, and the step that --auto-timestep picks (stable, refused
// 10 % above, smaller for a stiff skin, the validated step of the shear-DOF skins), and the
// whole suite through the command (~40 s on 2 cores): exit 0, every case healthy or refused
// clearly.

#include <gtest/gtest.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "tests/long_experiment.h"
#include "tests/scenarios/cli_helpers.h"
#include "input_error.h"
#include "models/stability.h"
#include "scenarios/studies/stability/stability_suite.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;

// Every refusal of the suite: its case and the message it must give (fragments).
struct Refusal {
  const char* name;
  std::vector<std::string> fragments;
};
const Refusal kRefusals[] = {
    {"gel-x100",
     {"sim.timestep_s = 0.002: unstable: exceeds the limit 0.00076 s of the skin's pin normal mode",
      "use sim.timestep_s <= 0.00076"}},
    {"skin-x100",
     {"sim.timestep_s = 0.002: unstable: exceeds the limit 0.000216 s of the skin's pin normal mode",
      "use sim.timestep_s <= 0.000216"}},
    {"rim-thin-x100",
     {"sim.timestep_s = 0.002: unstable: exceeds the limit 0.00136 s of the smooth skin's in-plane shell mode",
      "use sim.timestep_s <= 0.00136"}},
    {"dt-5ms",
     {"sim.timestep_s = 0.005: unstable: exceeds the limit 0.00254 s of the skin's pin normal mode",
      "use sim.timestep_s <= 0.00254"}},
    {"v2-mu-3",
     {"sim.timestep_s = 5e-04: skin.coupling = membrane (per-pin shear DOFs) at contact.friction = 3 is validated up to "
      "0.000333 s",
      "use sim.timestep_s <= 0.000333"}},
    {"v2-dt-5ms",
     {"sim.timestep_s = 0.005: skin.coupling = membrane (per-pin shear DOFs) at contact.friction = 1 is validated up to "
      "0.001 s",
      "use sim.timestep_s <= 0.001"}},
    {"v1-dome", {"skin.normal_spring = 'dome': fingerprint-v1's edge pins flicker", "use axial"}},
    {"depth-7.5mm", {"rail.press_depth_mm = 7.5: must be <= 7"}},
    {"depth-7mm-jitter",
     {"rail.press_depth_jitter_mm = 0.5: the deepest press, rail.press_depth_mm + rail.press_depth_jitter_mm = 7 + 0.5 "
      "= 7.5 mm, is beyond the 7 mm a TacTip tolerates; use rail.press_depth_jitter_mm <= 0"}},
};

std::vector<std::string> RailKeys() {
  std::vector<std::string> keys;
  for (const auto& f : FindScenario("rail").Describe(ConfigSource{})) keys.push_back(f.key);
  return keys;
}

TEST(StabilitySuiteTest, CasesHaveUniqueNamesAndEveryRefusalIsClear) {
  // Every case either loads or is refused on one line naming a key and a safe value;
  // exactly the refusals listed above are refused.
  std::set<std::string> names, refused;
  const auto keys = RailKeys();
  for (const auto& c : StabilityCases()) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    const std::string msg = InputErrorOf([&] { RailFamily(FindScenario(c.scenario)).Resolve(StabilityCaseSource(c)); });
    if (msg.empty()) continue;
    refused.insert(c.name);
    EXPECT_TRUE(RefusalIsClear(msg, keys)) << c.name << ": " << msg;
  }
  std::set<std::string> expected;
  for (const auto& r : kRefusals) expected.insert(r.name);
  EXPECT_EQ(refused, expected);
}

TEST(StabilitySuiteTest, RefusalMessagesNameTheParameterAndASafeValue) {
  for (const auto& r : kRefusals) {
    const StabilityResult res = RunStabilityCase(FindStabilityCase(r.name));
    EXPECT_EQ(res.outcome, CaseOutcome::kRefused) << r.name << ": " << res.message;
    EXPECT_FALSE(res.run.has_value()) << r.name << " must not run";
    for (const auto& f : r.fragments) EXPECT_NE(res.message.find(f), std::string::npos) << r.name << ": " << res.message;
  }
}

TEST(StabilitySuiteTest, RefusalIsClearOnlyForOneLineNamingAKeyAndASafeValue) {
  const auto keys = RailKeys();
  EXPECT_TRUE(RefusalIsClear("sim.timestep_s = 0.004: unstable: ...; use sim.timestep_s <= 0.00255", keys));
  EXPECT_TRUE(RefusalIsClear("rail.press_depth_mm = 7.5: must be <= 7", keys));
  EXPECT_FALSE(RefusalIsClear("unstable: use a smaller step", keys)) << "names no key";
  EXPECT_FALSE(RefusalIsClear("rail.press_depth_mm = 7.5: too deep", keys)) << "names no safe value";
  EXPECT_FALSE(RefusalIsClear("rail.press_depth_mm = 7.5: must be <= 7\nmore", keys)) << "two lines";
}

TEST(StabilitySuiteTest, EmptyContactRunsWithoutTouchingAndLeavesTheObject) {
  const StabilityResult r = RunStabilityCase(FindStabilityCase("empty-contact"));
  ASSERT_TRUE(r.run.has_value()) << r.message;
  EXPECT_EQ(r.outcome, CaseOutcome::kHealthy) << r.message;
  EXPECT_FALSE(r.run->held);
  EXPECT_TRUE(std::isnan(r.run->gross_slip_onset_s));
}

TEST(StabilitySuiteTest, APressThatDoesNotMoveTowardsTheStimulusIsRefused) {
  RailScenarioConfig c;
  c.rail.press_depth_mm = -2.0;  // the default approach gap is 2 mm, jitter 0.1 mm
  EXPECT_EQ(InputErrorOf([&] { ValidateConfig(c); }),
            "rail.press_depth_mm = -2: the press would not move the sensor towards the stimulus (rail.approach_gap_mm "
            "+ press_depth_mm - press_depth_jitter_mm = -0.1 mm); use rail.press_depth_mm > -1.9");
  c.rail.press_depth_mm = -1.8;
  EXPECT_EQ(InputErrorOf([&] { ValidateConfig(c); }), "");
}

// --- the automatic timestep -------------------------------------------------------------

RailScenarioConfig Stiff() {
  RailScenarioConfig c;
  c.skin.gel_modulus_kpa = 10000.0;
  return c;
}

TEST(AutoTimestepTest, DefaultsKeepTheTwoMillisecondStep) {
  const TimestepChoice t = ChooseTimestep(RailScenarioConfig{});
  EXPECT_DOUBLE_EQ(t.timestep_s, 0.002);
  EXPECT_NE(t.binding.find("accuracy"), std::string::npos) << t.binding;
  EXPECT_NEAR(t.stable_s, 0.00255, 1e-5);
  EXPECT_NE(t.stable_mode.find("pin normal mode"), std::string::npos) << t.stable_mode;
}

TEST(AutoTimestepTest, StiffSkinGetsASmallerStableStepRefusedTenPercentAbove) {
  RailScenarioConfig c = Stiff();
  const TimestepChoice t = ChooseTimestep(c);
  EXPECT_LT(t.timestep_s, ChooseTimestep(RailScenarioConfig{}).timestep_s);
  EXPECT_EQ(t.binding, "stability");
  EXPECT_NE(t.stable_mode.find("the skin's pin normal mode"), std::string::npos) << t.stable_mode;
  // Stable: within the limit the check uses, and the config passes.
  c.sim.timestep_s = t.timestep_s;
  EXPECT_LE(t.timestep_s, RailStiffestMode(c.SceneSpec()).MaxTimestep());
  EXPECT_EQ(InputErrorOf([&] { ValidateConfig(c); }), "");
  // 10 % above the limit is refused.
  c.sim.timestep_s = 1.1 * t.bound_s;
  EXPECT_NE(InputErrorOf([&] { ValidateConfig(c); }).find("unstable: exceeds the limit"), std::string::npos);
  // A frame is a whole number of steps.
  const double steps = 0.01 / t.timestep_s;
  EXPECT_NEAR(steps, std::round(steps), 1e-9);
}

TEST(AutoTimestepTest, ContactTimeConstantAndFrameBoundTheStep) {
  RailScenarioConfig c;
  c.contact.timeconst_s = 0.003;  // dt <= 1.5 ms; 10 ms / 7 steps
  TimestepChoice t = ChooseTimestep(c);
  EXPECT_NE(t.binding.find("contact.timeconst_s"), std::string::npos) << t.binding;
  EXPECT_NEAR(t.timestep_s, 0.01 / 7, 1e-15);
  // The configured step is the cap: 5 ms asked for gives the stable limit, rounded to 10 ms / 4.
  c = RailScenarioConfig{};
  c.sim.timestep_s = 0.005;
  c.contact.timeconst_s = 0.01;
  t = ChooseTimestep(c);
  EXPECT_NE(t.binding.find("stability"), std::string::npos) << t.binding;
  EXPECT_DOUBLE_EQ(t.timestep_s, 0.0025);
}

TEST(AutoTimestepTest, ALightlyDampedShellGetsItsValidatedStepOnlyWithoutTheSlidingStep) {
  RailScenarioConfig c;
  c.skin.shell_damping = "gel";
  // The sliding step (1 ms) covers the gross slip: the held phase keeps the default step.
  TimestepChoice t = ChooseTimestep(c);
  EXPECT_NE(t.binding.find("accuracy"), std::string::npos) << t.binding;
  EXPECT_DOUBLE_EQ(t.timestep_s, 0.002);
  c.sim.sliding_timestep_s = 0.0015;  // slides at 2 ms / 2, as CheckTimestep accepts
  EXPECT_DOUBLE_EQ(ChooseTimestep(c).timestep_s, 0.002);
  c.sim.sliding_timestep_s = 0.0;  // without it the whole run needs the validated step
  t = ChooseTimestep(c);
  EXPECT_NE(t.binding.find("lightly damped shell"), std::string::npos) << t.binding;
  EXPECT_DOUBLE_EQ(t.timestep_s, kLightShellValidatedStepS);
  RailScenarioConfig picked = c;
  picked.sim.timestep_s = t.timestep_s;
  picked.ValidateRules();  // the step it picked passes
  c.skin.gel_loss_tangent = 1.0;  // a ratio of 0.5: not light
  EXPECT_DOUBLE_EQ(ChooseTimestep(c).timestep_s, 0.002);
}

TEST(AutoTimestepTest, MembraneSkinKeepsItsPhysicalDamping) {
  // fingerprint-v2: its stiff shear mode sets the step at which the model need not raise
  // the lattice's damping. The preset's 0.5 ms is below it, so the damping stays physical.
  RailScenarioConfig c = LoadConfig<RailScenarioConfig>("", SkinPresetOverrides("fingerprint-v2"));
  const PinLattice lattice = PinLattice::Build(c.skin);
  const SkinMechanics m = SkinMechanics::From(c.skin, lattice);
  TimestepChoice t = ChooseTimestep(c);
  EXPECT_EQ(t.binding, "accuracy (the configured sim.timestep_s)");
  EXPECT_DOUBLE_EQ(t.timestep_s, 0.0005);
  EXPECT_NEAR(m.TipDamping(t.timestep_s), m.tip_damping_Ns_m, 1e-12);
  // At the validated 1 ms the shear mode binds.
  c.sim.timestep_s = 0.001;
  t = ChooseTimestep(c);
  EXPECT_EQ(t.binding, "stability");
  EXPECT_NE(t.stable_mode.find("membrane lattice's shear mode"), std::string::npos) << t.stable_mode;
  EXPECT_GT(t.timestep_s, 0.0005);
  EXPECT_LT(t.timestep_s, 0.001);
  EXPECT_NEAR(m.TipDamping(t.timestep_s), m.tip_damping_Ns_m, 1e-12);
  EXPECT_NEAR(m.NormalDamping(t.timestep_s), m.pin_damping_Ns_m, 1e-12);
  EXPECT_GT(m.TipDamping(1.1 * t.bound_s), m.tip_damping_Ns_m) << "just above, the damping would be raised";
  EXPECT_GT(m.TipDamping(0.001), m.tip_damping_Ns_m) << "at 1 ms it is raised";
}

TEST(AutoTimestepTest, ShearDofSkinsGetTheirValidatedStepAndAreRefusedAboveIt) {
  // fingerprint-v1 carries the validated 1 ms step, fingerprint-v2 0.5 ms (its edge contacts
  // chatter at 1 ms); a higher friction shrinks the validated step.
  EXPECT_DOUBLE_EQ(LoadConfig<RailScenarioConfig>("", SkinPresetOverrides("fingerprint-v2")).sim.timestep_s, 0.0005);
  RailScenarioConfig c = LoadConfig<RailScenarioConfig>("", SkinPresetOverrides("fingerprint-v1"));
  EXPECT_DOUBLE_EQ(c.sim.timestep_s, 0.001);
  EXPECT_DOUBLE_EQ(ShearDofValidatedTimestep(c.skin, c.contact), 0.001);
  c.contact.friction = 2.0;
  const TimestepChoice t = ChooseTimestep(c);
  EXPECT_NE(t.binding.find("shear DOFs"), std::string::npos) << t.binding;
  EXPECT_DOUBLE_EQ(t.timestep_s, 0.0005);
  EXPECT_THROW(c.ValidateRules(), InputError) << "1 ms at mu = 2";
  c.sim.timestep_s = t.timestep_s;
  EXPECT_NO_THROW(c.ValidateRules());
  // The shell has no such limit; mu below 1 does not raise the step.
  RailScenarioConfig smooth;
  EXPECT_TRUE(std::isinf(ShearDofValidatedTimestep(smooth.skin, smooth.contact)));
  c.contact.friction = 0.1;
  EXPECT_DOUBLE_EQ(ShearDofValidatedTimestep(c.skin, c.contact), 0.001);
}

// --- the command line ---------------------------------------------------------------------

class StabilityCliTest : public testing::CliFolderTest {};

TEST_F(StabilityCliTest, OneHealthyAndOneRefusedCaseWithTheirOutcomes) {
  const CliResult r = Run("stability --case smooth-flat --case gel-x100 --quiet --out " + (dir_ / "out").string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("smooth-flat              healthy"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gel-x100                 refused"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("    sim.timestep_s = 0.002: unstable"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 case(s): 1 healthy, 1 refused, 0 FAILED"), std::string::npos) << r.out;
  const std::string csv = testing::Slurp(dir_ / "out" / "stability.csv");
  EXPECT_EQ(csv.rfind("case,scenario,sets,expect,outcome,", 0), 0u) << csv;
  EXPECT_NE(csv.find("\nsmooth-flat,rail,--skin smooth rail.stimulus=flat,any,healthy,0.002,1,"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\ngel-x100,rail,skin.gel_modulus_kpa=10000,any,refused,-,"), std::string::npos) << csv;
}

TEST_F(StabilityCliTest, SetReachesEveryCaseBeneathItsOwnKeysAndIsCheckedFirst) {
  // sim.timestep_s=0.001 moves smooth-flat off its 2 ms step; dt-2.5ms sets its own step,
  // which wins; the table and the CSV say what every case ran with.
  const CliResult r = Run("stability --case smooth-flat --case dt-2.5ms --set sim.timestep_s=0.001 --quiet --out " +
                          (dir_ / "out").string());
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.rfind("every case with --set sim.timestep_s=0.001 (after its skin preset, before its own keys)\n", 0),
            0u)
      << r.out;
  const std::string csv = testing::Slurp(dir_ / "out" / "stability.csv");
  EXPECT_NE(csv.find("\nsmooth-flat,rail,--skin smooth rail.stimulus=flat,any,healthy,0.001,"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\ndt-2.5ms,rail,sim.timestep_s=0.0025 contact.timeconst_s=0.005,held,healthy,0.0025,"),
            std::string::npos)
      << csv;
  int rows_with_sets = 0;  // every row ends with the suite's sets
  for (size_t at = csv.find(",sim.timestep_s=0.001\n"); at != std::string::npos;
       at = csv.find(",sim.timestep_s=0.001\n", at + 1)) {
    ++rows_with_sets;
  }
  EXPECT_EQ(rows_with_sets, 2) << csv;
  // Refused on the defaults: one line, exit code 2, before any case runs or any folder is made.
  for (const std::string bad : {"skin.bogus=1", "skin.gel_modulus_kpa=-1"}) {
    const CliResult b = Run("stability --case smooth-flat --set " + bad + " --out " + (dir_ / "refused").string());
    EXPECT_EQ(b.code, 2) << bad;
    EXPECT_EQ(b.err.rfind("tactip: --set: ", 0), 0u) << b.err;
    EXPECT_NE(b.err.find("(on the rail scenario's defaults)\n"), std::string::npos) << b.err;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
    EXPECT_FALSE(fs::exists(dir_ / "refused")) << bad;
  }
  // A malformed --set is the config's own one-line refusal, not a scenario's.
  const CliResult m = Run("stability --case smooth-flat --set foo");
  EXPECT_EQ(m.code, 2);
  EXPECT_EQ(m.err, "tactip: --set 'foo': expected key=value\n");
}

// The whole suite in two halves (each a test of its own, so neither runs past a minute): every
// case, retracting at 2 mm/s where a case does not set its own speed (the suite's short protocol
// retracts at 1 mm/s): half the simulated retraction. Each half must end healthy or refused,
// none FAILED.
class StabilityCliHalfTest : public StabilityCliTest {
 protected:
  void RunHalf(size_t half) {
    const auto& cases = StabilityCases();
    const size_t middle = cases.size() / 2;
    const size_t begin = half == 0 ? 0 : middle;
    const size_t end = half == 0 ? middle : cases.size();
    std::string args = "stability --quiet --set rail.retract_speed_mm_s=2 --out " + (dir_ / "out").string();
    for (size_t i = begin; i < end; ++i) args += " --case " + cases[i].name;
    const CliResult r = Run(args);
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find(fmt::format("{} case(s): ", end - begin)), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" refused, 0 FAILED"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("FAILED "), std::string::npos) << r.out;
  }
};

TEST_F(StabilityCliHalfTest, FirstHalfOfTheSuiteIsHealthyOrRefusedClearly) {
  TACTIP_LONG_EXPERIMENT();
  RunHalf(0);
}

TEST_F(StabilityCliHalfTest, SecondHalfOfTheSuiteIsHealthyOrRefusedClearly) {
  TACTIP_LONG_EXPERIMENT();
  RunHalf(1);
}

TEST_F(StabilityCliTest, ListNamesEveryCaseAndAnUnknownCaseIsExitCode2) {
  const CliResult l = Run("stability --list");
  ASSERT_EQ(l.code, 0) << l.err;
  for (const auto& c : StabilityCases()) EXPECT_NE(l.out.find(c.name + " "), std::string::npos) << c.name;
  const CliResult u = Run("stability --case nosuch");
  EXPECT_EQ(u.code, 2);
  EXPECT_EQ(u.err, "tactip: --case 'nosuch': unknown case ('tactip stability --list' lists them)\n");
  // --list runs nothing, so the options that shape a run are refused beside it, not ignored.
  for (const std::string& extra :
       std::vector<std::string>{"--set skin.membrane_links=central", "--case gel-x100", "--out " + P("o"), "--jobs 1"}) {
    const CliResult r = Run("stability --list " + extra);
    EXPECT_EQ(r.code, 2) << extra;
    const std::string name = extra.substr(0, extra.find(' '));
    EXPECT_EQ(r.err, "tactip: " + name + " excludes --list (see --help)\n") << extra;
    EXPECT_EQ(r.out, "") << extra;
  }
  EXPECT_FALSE(fs::exists(P("o")));
}

TEST_F(StabilityCliTest, EveryRefusalIsOneLineWithExitCode2FromGenerate) {
  for (const auto& r : kRefusals) {
    const StabilityCase& c = FindStabilityCase(r.name);
    std::string args = "generate rail --runs 1 --out " + (dir_ / "x.h5").string();
    for (const auto& s : StabilityCaseSource(c).overrides) args += " --set " + s;
    const CliResult g = Run(args);
    EXPECT_EQ(g.code, 2) << r.name << "\n" << g.err;
    EXPECT_EQ(std::count(g.err.begin(), g.err.end(), '\n'), 1) << r.name << "\n" << g.err;
    for (const auto& f : r.fragments) EXPECT_NE(g.err.find(f), std::string::npos) << r.name << "\n" << g.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.h5"));
  }
  const CliResult e = Run("generate rail --set rail.press_depth_mm=-2 --out " + (dir_ / "x.h5").string());
  EXPECT_EQ(e.code, 2);
  EXPECT_NE(e.err.find("use rail.press_depth_mm > -1.9"), std::string::npos) << e.err;
}

TEST_F(StabilityCliTest, AutoTimestepPrintsTheStepAndWhatBindsIt) {
  const CliResult r = Run("config rail --yaml --auto-timestep --set skin.gel_modulus_kpa=10000");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("auto-timestep: sim.timestep_s = 0.000714286 s (bound 0.000760583 s by stability; largest "
                       "stable step 0.000760583 s, set by the skin's pin normal mode"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("timestep_s: 0.000714285714"), std::string::npos) << r.out;
  // Without the flag the same config is refused, naming the safe step.
  const CliResult s = Run("config rail --yaml --set skin.gel_modulus_kpa=10000");
  EXPECT_EQ(s.code, 2);
  EXPECT_NE(s.err.find("use sim.timestep_s <= 0.00076"), std::string::npos) << s.err;
}

}  // namespace
}  // namespace tactip
