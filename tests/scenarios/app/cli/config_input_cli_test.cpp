// Config input through the command line: YAML files that are refused (alias bombs,
// duplicate keys, a second document), values that would break the one-line message, and
// parameter combinations refused before anything runs. Each refusal is one line on stderr
// with exit code 2 and leaves no file.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/scenarios/cli_helpers.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;

class ConfigInputCliTest : public testing::CliFolderTest {
 protected:

  // `generate` with these arguments must be refused on one line naming `fragment`,
  // with exit code 2 and no dataset.
  void ExpectRefused(const std::string& args, const std::string& fragment) {
    const CliResult r = Run("generate " + args + " --runs 1 --out " + P("x.h5"));
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << args << ": not one line\n" << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(P("x.h5"))) << args;
  }

};

TEST_F(ConfigInputCliTest, YamlAliasBombDuplicateKeysAndASecondDocumentAreRefused) {
  std::string bomb = "sim: &l0 {a: x, b: x, c: x, d: x, e: x, f: x, g: x, h: x, i: x, j: x}\n";
  for (int level = 1; level <= 8; ++level) {
    const std::string prev = "*l" + std::to_string(level - 1);
    bomb += "x" + std::to_string(level) + ": &l" + std::to_string(level) + " {";
    for (char k = 'a'; k <= 'j'; ++k) bomb += std::string(k == 'a' ? "" : ", ") + k + ": " + prev;
    bomb += "}\n";
  }
  std::ofstream(P("bomb.yaml")) << bomb;
  std::ofstream(P("dup.yaml")) << "sim:\n  iterations: 50\n  iterations: 60\n";
  std::ofstream(P("two.yaml")) << "sim:\n  iterations: 50\n---\nsim:\n  iterations: 60\n";
  ExpectRefused("rail --config " + P("bomb.yaml"), "bomb.yaml: expands to more than 10000 YAML nodes");
  ExpectRefused("rail --config " + P("dup.yaml"), "dup.yaml: key 'sim.iterations' appears twice (line 3)");
  ExpectRefused("rail --config " + P("two.yaml"), "two.yaml: holds 2 YAML documents");
}

TEST_F(ConfigInputCliTest, LineBreakInASetValueIsRefusedOnOneLine) {
  // /bin/sh has no $'...': printf makes the line break.
  ExpectRefused("rail --set \"$(printf 'sim.iterations=5\\nx')\"", "--set 'sim.iterations=5\\nx': holds a line break");
}

// The value printed after `marker` in `text` (up to the next space or semicolon).
std::string ValueAfter(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return "";
  const auto begin = at + marker.size();
  return text.substr(begin, text.find_first_of(" ;\n", begin) - begin);
}

TEST_F(ConfigInputCliTest, TheSuggestedTimestepIsAcceptedAsPrinted) {
  const std::string cases[] = {
      "rail --set contact.timeconst_s=0.0062 --set sim.timestep_s=0.003",  // default skin, limit 2.5487 ms
      "rail --set skin.gel_modulus_kpa=10000",
      "rail --set skin.thickness_mm=5",
      "rail --set skin.pin_mass_g=0.01",
      "rail --skin fingerprint-v2 --set contact.friction=2.9",  // the shear-DOF skin's validated step
  };
  for (const std::string& c : cases) {
    const CliResult refused = Run("config " + c);
    EXPECT_EQ(refused.code, 2) << c << "\n" << refused.err;
    const std::string safe = ValueAfter(refused.err, "use sim.timestep_s <= ");
    ASSERT_FALSE(safe.empty()) << c << "\n" << refused.err;
    const CliResult again = Run("config " + c + " --set sim.timestep_s=" + safe);
    EXPECT_EQ(again.code, 0) << c << " --set sim.timestep_s=" << safe << "\n" << again.err;
  }
  // A skin whose stable step lies below the shortest allowed one (4.2 us against 10 us) gets no
  // step to try, but what to change.
  const CliResult none =
      Run("config rail --set skin.skin_modulus_mpa=100 --set skin.thickness_mm=5 --set skin.pin_mass_g=0.01");
  EXPECT_EQ(none.code, 2) << none.err;
  EXPECT_NE(none.err.find("no sim.timestep_s >= 1e-05 is stable: use other values of the keys that set it"),
            std::string::npos)
      << none.err;
  EXPECT_EQ(none.err.find("use sim.timestep_s <="), std::string::npos) << none.err;
}

TEST_F(ConfigInputCliTest, TooFewSolverIterationsAreRefused) {
  ExpectRefused("rail --set sim.iterations=2", "sim.iterations = 2: must be >= 20");
  EXPECT_EQ(Run("config rail --set sim.iterations=20").code, 0);
}

TEST_F(ConfigInputCliTest, ASpeedRangeMustStartAtTheRetractionSpeed) {
  ExpectRefused("rail --set rail.retract_speed_max_mm_s=0.05",
                "rail.retract_speed_max_mm_s = 0.05: must be 0 (one speed) or at least rail.retract_speed_mm_s = 0.1 mm/s");
  EXPECT_EQ(Run("config rail --set rail.retract_speed_max_mm_s=5").code, 0);
}

TEST_F(ConfigInputCliTest, AnUnknownCameraPresetIsRefused) {
  ExpectRefused("rail --camera gopro", "--camera");
}

TEST_F(ConfigInputCliTest, CameraIntrinsicsMustFitTheImage) {
  ExpectRefused("rail --set sensor.fx_px=1e40", "sensor.fx_px = 1e+40: must be <= 163840");
  ExpectRefused("rail --set sensor.cx_px=1e308", "sensor.cx_px = 1e+308: must be <= 8192");
  ExpectRefused("incipient --set external.f_px=1e308", "external.f_px = 1e+308: must be <= 163840");
  ExpectRefused("rail --set sensor.fx_px=20000",
                "sensor.fx_px = 20000: must be 0.1 to 20 x sensor.width_px (64 to 12800 px for 640 px");
  ExpectRefused("rail --set sensor.height_px=200",
                "sensor.cy_px = 240: must be inside the image, 0 to sensor.height_px = 200 px");
  ExpectRefused("incipient --set external.cx_px=700",
                "external.cx_px = 700: must be inside the image, 0 to sensor.width_px = 640 px");
}

TEST_F(ConfigInputCliTest, SkinsThatCannotBeBuiltAreRefusedNamingTheParameter) {
  ExpectRefused("rail --set skin.rings=0", "skin.rings = 0: must be >= 1");
  const std::string big = "incipient --set skin.pins_per_ring=24 --set skin.ridge_spacing_mm=1";
  ExpectRefused(big, "skin.pins_per_ring = 24: the skin has 4105 pins (1873 can touch the stimulus), for which MuJoCo "
                     "would reserve");
  const CliResult refused = Run("config " + big);
  const std::string safe = ValueAfter(refused.err, "use skin.pins_per_ring <= ");
  ASSERT_FALSE(safe.empty()) << refused.err;
  EXPECT_EQ(Run("config " + big + " --set skin.pins_per_ring=" + safe).code, 0) << safe;
  EXPECT_EQ(Run("config " + big + " --set skin.pins_per_ring=" + std::to_string(std::stoi(safe) + 1)).code, 2) << safe;
}

TEST_F(ConfigInputCliTest, APressBeyondWhatTheSkinToleratesNamesBothKeysAndTheLimit) {
  ExpectRefused("rail --set rail.press_depth_mm=7 --set rail.press_depth_jitter_mm=2",
                "rail.press_depth_jitter_mm = 2: the deepest press, rail.press_depth_mm + rail.press_depth_jitter_mm "
                "= 7 + 2 = 9 mm, is beyond the 7 mm a TacTip tolerates; use rail.press_depth_jitter_mm <= 0");
}

}  // namespace
}  // namespace tactip
