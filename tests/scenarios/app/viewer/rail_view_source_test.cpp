// The viewer's rail run: on the scene with the visual parts it records exactly what
// `generate` records for the same config, run and seed, its pins are coloured by the run's
// contact labels, and it ends where the run ends.

#include "scenarios/app/viewer/rail_view_source.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>

#include "mujoco_warning_guard.h"
#include "scenarios/registry.h"

namespace tactip {
namespace {

// A scenario's config with a 5 mm lift and a 5 mm/s retraction: the object falls about
// 4 s in. Hold from about 3.1 s to 3.6 s.
RailScenarioConfig ShortRun(const std::string& scenario) {
  return RailFamily(FindScenario(scenario)).Load({"", {"rail.lift_mm=5", "rail.retract_speed_mm_s=5"}});
}
constexpr double kHoldTimeS = 3.4;

// How many pins are drawn in each colour.
struct ColourCounts {
  int stick = 0, slip = 0, no_contact = 0;
};

// Checks that every pin with a contact geom is coloured by its labels now; counts them.
ColourCounts ExpectColoursFollowLabels(const RailViewSource& view) {
  std::map<int, Rgba> colour_of;
  for (const GeomColour& c : view.Colours()) colour_of[c.geom] = c.rgba;
  const TactileSensor& s = view.sensor();
  ColourCounts counts;
  for (int i = 0; i < s.n_pins(); ++i) {
    const int g = s.ids().pin_geom[i];
    if (g < 0) continue;
    const bool slip = s.pin_slip()[i], contact = s.pin_contact()[i];
    EXPECT_EQ(colour_of.at(g), slip ? PinColours::kSlip : (contact ? PinColours::kStick : PinColours::kNoContact))
        << "pin " << i;
    (slip ? counts.slip : (contact ? counts.stick : counts.no_contact)) += 1;
  }
  EXPECT_EQ(colour_of.size(), view.pin_geoms().size());
  return counts;
}

class RailViewSourceTest : public testing::MujocoWarningGuard {
 protected:
  // Runs `scenario`'s short run `index` with master seed `seed` to its end in the viewer and
  // through the scenario (as `generate` does); both records must be the same.
  static void ExpectViewerRecordsWhatGenerateRecords(const std::string& scenario, int index, std::uint64_t seed) {
    const RailScenarioConfig cfg = ShortRun(scenario);
    RailViewSource view(cfg, index, seed);
    while (view.Step()) {
    }
    RunRecord generated;
    const RailRunSummary s = RailScenario(cfg).Run(index, seed, generated);
    ASSERT_GT(generated.frames(), 100u);
    EXPECT_EQ(view.record().index, index);
    EXPECT_EQ(view.record().time, generated.time);
    ASSERT_EQ(view.record().sensors.size(), generated.sensors.size());
    for (size_t k = 0; k < generated.sensors.size(); ++k) {
      const SensorRecord& shown = view.record().sensors[k];
      const SensorRecord& kept = generated.sensors[k];
      EXPECT_EQ(shown.name, kept.name);
      EXPECT_EQ(shown.pos_px, kept.pos_px);
      EXPECT_EQ(shown.pin_contact, kept.pin_contact);
      EXPECT_EQ(shown.pin_slip, kept.pin_slip);
      EXPECT_EQ(shown.normal_N, kept.normal_N);
    }
    EXPECT_EQ(view.record().attrs.at("gross_slip_onset_s"), s.gross_slip_onset_s);
  }
};

TEST_F(RailViewSourceTest, TheVisualPartsChangeNothingTheRailRunRecords) {
  ExpectViewerRecordsWhatGenerateRecords("rail", 1, 7);
}

TEST_F(RailViewSourceTest, TheVisualPartsChangeNothingTheIncipientRunRecords) {
  ExpectViewerRecordsWhatGenerateRecords("incipient", 0, 3);
}

TEST_F(RailViewSourceTest, PinsAreColouredByTheRunsLastContactLabels) {
  RailViewSource view(ShortRun("rail"), 0, 1);
  const ColourCounts start = ExpectColoursFollowLabels(view);
  EXPECT_EQ(start.stick + start.slip, 0);
  ASSERT_TRUE(view.AdvanceTo(kHoldTimeS));
  EXPECT_EQ(view.Status(), "run 0 (seed 1): hold");
  EXPECT_GT(ExpectColoursFollowLabels(view).stick, 0);
  // On to the first step at which pins slide (the gross slip during the retraction).
  while (view.sensor().labels().n_slip == 0 && view.Step()) {
  }
  EXPECT_EQ(ExpectColoursFollowLabels(view).slip, view.sensor().labels().n_slip);
  EXPECT_GT(view.sensor().labels().n_slip, 0);
}

TEST_F(RailViewSourceTest, TheRunEndsAfterTheObjectHasFallen) {
  RailViewSource view(ShortRun("rail"), 0, 1);
  EXPECT_FALSE(view.AdvanceTo(view.give_up_s()));
  EXPECT_TRUE(view.finished());
  EXPECT_LT(view.time(), view.give_up_s());
  EXPECT_FALSE(view.Step());
  EXPECT_EQ(view.Status(), "run 0 (seed 1): ended");
  EXPECT_GE(view.time(), view.record().attrs.at("object_fall_s"));
}

}  // namespace
}  // namespace tactip
