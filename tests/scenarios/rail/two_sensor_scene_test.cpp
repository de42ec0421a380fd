// A scene of several tactile sensors is a config change: the rail rig with two TacTips side
// by side (a `sensors` list in the config) builds two prefixed skins, holds the object with
// both and writes one sensor group per TacTip.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "tests/scenarios/cli_helpers.h"
#include "sensors/dataset.h"

namespace tactip {
namespace {

using testing::CliFolderTest;
using testing::CliResult;

// A short rail run: 20 mm lift, 2 mm/s retraction.
constexpr const char* kShortTwoSensorRun = "--runs 1 --seed 3 --set rail.lift_mm=20 --set rail.retract_speed_mm_s=2";

class TwoSensorSceneTest : public CliFolderTest {
 protected:
  // The shipped config file that puts two TacTips side by side, 50 mm apart.
  static std::string TwoSensorConfig() { return std::string(TACTIP_SOURCE_DIR) + "/assets/scenes/rail-two-tactips.yaml"; }
  // Frames in which sensor `s` has a pin in contact.
  static int FramesInContact(const SensorRecord& s) {
    int frames = 0;
    const size_t n = static_cast<size_t>(s.n_pins);
    for (size_t f = 0; f * n < s.pin_contact.size(); ++f) {
      frames += std::any_of(s.pin_contact.begin() + f * n, s.pin_contact.begin() + (f + 1) * n, [](auto c) { return c; });
    }
    return frames;
  }
};

TEST_F(TwoSensorSceneTest, TwoTacTipsSideBySideWriteTwoSensorGroupsAndHoldTheObjectTogether) {
  const std::string config = TwoSensorConfig();
  const CliResult two = Run(std::string("generate rail ") + kShortTwoSensorRun + " --config " + config + " --out " + P("two.h5"));
  ASSERT_EQ(two.code, 0) << two.err;
  const CliResult one = Run(std::string("generate rail ") + kShortTwoSensorRun + " --out " + P("one.h5"));
  ASSERT_EQ(one.code, 0) << one.err;

  const RunRecord run = DatasetReader(P("two.h5")).ReadRun(0);
  ASSERT_EQ(run.sensors.size(), 2u);
  EXPECT_EQ(run.sensors[0].name, "left");
  EXPECT_EQ(run.sensors[1].name, "right");
  const size_t frames = run.frames();
  for (const SensorRecord& s : run.sensors) {
    EXPECT_EQ(s.n_pins, 127) << s.name;
    EXPECT_EQ(s.pos_px.size(), frames * 127 * 2) << s.name;
    // Each presses the plate from the press to the fall: well over a second of frames.
    EXPECT_GT(FramesInContact(s), 200) << s.name;
    EXPECT_EQ(s.gross_slip, run.sensors[0].gross_slip) << "gross slip is the object's, one label for both";
  }
  EXPECT_NE(run.sensors[0].pos_px, run.sensors[1].pos_px) << "each sensor has its own camera noise";

  // Twice the normal force holds the object longer under the same retraction; the onset
  // stays where Coulomb's law over both skins puts it.
  const RunRecord single = DatasetReader(P("one.h5")).ReadRun(0);
  ASSERT_EQ(single.sensors.size(), 1u);
  EXPECT_EQ(single.sensors[0].name, "tactip");
  const double onset_two = run.attrs.at("gross_slip_onset_s"), onset_one = single.attrs.at("gross_slip_onset_s");
  EXPECT_GT(onset_two, onset_one + 0.1);
  EXPECT_LT(std::abs(onset_two - run.attrs.at("predicted_onset_s")), 0.01);
  EXPECT_EQ(run.attrs.at("health_ok"), 1.0);
}

TEST_F(TwoSensorSceneTest, EachSensorsElementsCarryItsNameInTheMjcf) {
  const CliResult r = Run("export-mjcf rail --config " + TwoSensorConfig() + " --out " + P("two.xml"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string xml = testing::Slurp(P("two.xml"));
  for (const std::string name : {"left/mount", "right/mount", "left/pin0_pad", "right/pin126", "right/skin_shell"}) {
    EXPECT_NE(xml.find("name=\"" + name + "\""), std::string::npos) << name;
  }
  EXPECT_EQ(xml.find("name=\"tactip/"), std::string::npos);
}

TEST_F(TwoSensorSceneTest, ASensorListThatCannotBeBuiltIsRefusedNamingTheKey) {
  const std::string two = " --set sensors.1.offset_y_mm=50";
  const std::pair<std::string, std::string> cases[] = {
      {"--set sensors.1.name=tactip" + two,
       "sensors.1.name = 'tactip': sensors.0.name is the same; each sensor needs its own name"},
      {"--set sensors.1.name=right --set sensors.1.offset_y_mm=20",
       "sensors.1.offset_y_mm = 20: 20 mm from sensors.0 ('tactip'): their housings (46 mm across) overlap; place the "
       "sensors at least 46 mm apart"},
      {"--set sensors.0.name=1st",
       "sensors.0.name = '1st': a sensor name is 1-32 letters, digits, '_' or '-', starting with a letter"},
      {"--set sensors.0.name=a/b",
       "sensors.0.name = 'a/b': a sensor name is 1-32 letters, digits, '_' or '-', starting with a letter"},
      {"--set sensors.2.name=third", "sensors.2.name: the list 'sensors' has 1 entry; add sensors.1 first"},
  };
  for (const auto& [args, message] : cases) {
    const CliResult r = Run("generate rail --runs 1 " + args + " --out " + P("x.h5"));
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, "tactip: " + message + "\n") << args;
    EXPECT_FALSE(std::filesystem::exists(P("x.h5")));
  }
}

}  // namespace
}  // namespace tactip
