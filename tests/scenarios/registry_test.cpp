// The scenario registry: the listed scenarios, the refusal of an unknown name, the rail
// protocol's config through its typed accessor, and a scenario of another config type
// (defined here) that the generic operations handle and the accessor refuses.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "input_error.h"
#include "scenarios/registry.h"

namespace tactip {
namespace {

// A config of another shape than the rail protocol's: one section, one field.
struct GripConfig {
  double force_N = 2.0;
  template <class V>
  void Visit(V& v) {
    v("force_N", force_N, "N", "Grip force.", Bounds::Closed(0.1, 20.0));
  }
};

struct HandConfig {
  GripConfig grip;
  template <class V>
  void Visit(V& v) {
    v.Section("grip", grip);
  }
  void ValidateRules() const {}
};

// A scenario owning HandConfig; its scene and dataset are stand-ins that show the config
// they were given.
class HandScenario final : public ConfiguredScenario<HandConfig> {
 public:
  HandScenario() : ConfiguredScenario("hand", "a hand scene", HandConfig{}) {}
  std::string SceneMjcf(const HandConfig& cfg) const override {
    return "<mujoco model=\"hand " + std::to_string(cfg.grip.force_N) + "\"/>";
  }
  GenerateResult GenerateDataset(const HandConfig& cfg, const GenerateOptions& opts) const override {
    GenerateResult r;
    r.runs = opts.runs;
    r.sim_time_s = cfg.grip.force_N;
    return r;
  }
};

std::vector<std::string> RegisteredNames() {
  std::vector<std::string> names;
  for (const auto& s : Scenarios()) names.push_back(s->name());
  return names;
}

TEST(RegistryTest, ListsTheRailScenariosInOrder) {
  EXPECT_EQ(RegisteredNames(), (std::vector<std::string>{"rail", "incipient"}));
  for (const auto& s : Scenarios()) EXPECT_FALSE(s->description().empty()) << s->name();
  EXPECT_EQ(&FindScenario("incipient"), Scenarios()[1].get());
}

TEST(RegistryTest, UnknownNameIsRefusedListingTheKnownOnes) {
  EXPECT_EQ(InputErrorOf([] { FindScenario("hand"); }), "unknown scenario 'hand' (known: rail, incipient)");
}

TEST(RegistryTest, RailConfigIsReachedThroughTheTypedAccessorWithTheScenariosOwnDefaults) {
  const RailFamilyScenario& rail = RailFamily(FindScenario("rail"));
  const RailFamilyScenario& incipient = RailFamily(FindScenario("incipient"));
  EXPECT_EQ(rail.name(), "rail");
  EXPECT_EQ(rail.Load({}).rail.stimulus, RailScenarioConfig{}.rail.stimulus);
  const RailScenarioConfig inc = incipient.Load({});
  EXPECT_EQ(inc.rail.stimulus, "acrylic");
  EXPECT_TRUE(inc.external.enabled);
  EXPECT_EQ(inc.rail.retract_speed_mm_s, IncipientDefaults().rail.retract_speed_mm_s);
  EXPECT_NE(inc.rail.stimulus, rail.Load({}).rail.stimulus);
  // The overrides go on top of the scenario's defaults.
  const RailScenarioConfig set = incipient.Load({"", {"rail.retract_speed_mm_s=2"}});
  EXPECT_EQ(set.rail.retract_speed_mm_s, 2.0);
  EXPECT_EQ(set.rail.stimulus, "acrylic");
}

TEST(RegistryTest, AutoTimestepIsTheStepTheLoadedConfigHolds) {
  const Scenario& rail = FindScenario("rail");
  const ConfigSource src{"", {"skin.pattern=fingerprint-v1"}, true};
  const std::optional<TimestepChoice> choice = rail.Check(src);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(RailFamily(rail).Load(src).sim.timestep_s, choice->timestep_s);
  EXPECT_FALSE(rail.Check({}).has_value()) << "no step is chosen unless asked for";
}

TEST(RegistryTest, AScenarioOfAnotherConfigTypeRunsTheGenericOperations) {
  const HandScenario hand;
  const Scenario& generic = hand;
  const ConfigSource src{"", {"grip.force_N=3"}};
  const std::vector<FieldDoc> fields = generic.Describe(src);
  ASSERT_EQ(fields.size(), 1u);
  EXPECT_EQ(fields[0].key, "grip.force_N");
  EXPECT_EQ(fields[0].value, "3");
  EXPECT_EQ(generic.ExportMjcf(src), "<mujoco model=\"hand 3.000000\"/>");
  GenerateOptions opts;
  opts.runs = 5;
  const GenerateResult r = generic.Generate(src, opts);
  EXPECT_EQ(r.runs, 5);
  EXPECT_EQ(r.sim_time_s, 3.0);
  EXPECT_NE(InputErrorOf([&] { generic.Check({"", {"grip.force_N=50"}}); }).find("grip.force_N"), std::string::npos);
  EXPECT_NE(InputErrorOf([&] { generic.Check({"", {"rail.lift_mm=5"}}); }).find("unknown config key 'rail.lift_mm'"),
            std::string::npos);
  EXPECT_EQ(InputErrorOf([&] { generic.Check({"", {}, true}); }),
            "--auto-timestep: scenario 'hand' has no timestep rule; set its step in the config");
}

TEST(RegistryTest, TheRailAccessorRefusesAScenarioOfAnotherConfigType) {
  const HandScenario hand;
  EXPECT_EQ(InputErrorOf([&] { RailFamily(hand); }), "scenario 'hand' has no rail protocol");
  EXPECT_EQ(ConfiguredAs<HandConfig>(hand), &hand);
  EXPECT_EQ(ConfiguredAs<HandConfig>(FindScenario("rail")), nullptr);
}

}  // namespace
}  // namespace tactip
