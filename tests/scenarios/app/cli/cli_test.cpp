// The command-line program end to end: listing, generation, info, export, and the
// one-line errors with exit code 2 for bad input.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "small_tmpfs.h"
#include "sim/simulation.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;
using testing::Slurp;

class CliTest : public testing::CliFolderTest {
 protected:
  // Files in the test folder other than the ones named.
  size_t FileCount() const {
    size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++n;
    return n;
  }
  std::string P(const std::string& name) const { return (dir_ / name).string(); }

};

// Quick protocol: short lift, fast retraction, two runs.
const char* kQuickCliRun = "--runs 2 --speed-mm-s 2 --set rail.lift_mm=10 --set rail.hold_s=0.1";

using testing::LineCount;

TEST_F(CliTest, ScenariosListsRail) {
  const CliResult r = Run("scenarios");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("rail ", 0), 0u) << r.out;
}

TEST_F(CliTest, GenerateWritesDatasetAndInfoSummarisesIt) {
  const CliResult g = Run(std::string("generate rail ") + kQuickCliRun + " --seed 7 --out " + P("a.h5"));
  ASSERT_EQ(g.code, 0) << g.err;
  EXPECT_NE(g.err.find("[2/2] run 1"), std::string::npos) << "progress lines expected: " << g.err;
  ASSERT_TRUE(fs::exists(P("a.h5")));
  EXPECT_EQ(FileCount(), 1u) << "no temporary files left behind";
  const CliResult i = Run("info " + P("a.h5"));
  ASSERT_EQ(i.code, 0) << i.err;
  EXPECT_NE(i.out.find("runs         2"), std::string::npos) << i.out;
  EXPECT_NE(i.out.find("gross slip in 2 of 2 runs"), std::string::npos) << i.out;
  EXPECT_NE(i.out.find("retract_speed_mm_s: 2"), std::string::npos) << "config printed: " << i.out;
}

TEST_F(CliTest, SameSeedGivesBitIdenticalDatasetWhateverTheThreadCount) {
  ASSERT_EQ(Run(std::string("generate rail ") + kQuickCliRun + " --seed 3 --jobs 1 --quiet --out " + P("a.h5")).code, 0);
  ASSERT_EQ(Run(std::string("generate rail ") + kQuickCliRun + " --seed 3 --jobs 2 --quiet --out " + P("b.h5")).code, 0);
  ASSERT_EQ(Run(std::string("generate rail ") + kQuickCliRun + " --seed 4 --jobs 2 --quiet --out " + P("c.h5")).code, 0);
  EXPECT_EQ(Slurp(P("a.h5")), Slurp(P("b.h5")));
  EXPECT_NE(Slurp(P("a.h5")), Slurp(P("c.h5")));
}

TEST_F(CliTest, BadInputGetsOneLineAndExitCode2) {
  std::ofstream(P("bad.yaml")) << "rail:\n  retract_speed_mm_s: [1,\n";
  std::ofstream(P("text.h5")) << "not hdf5\n";
  struct BadCase {
    std::string args, fragment;
  } cases[] = {
      {"generate rail --set rail.nope=1", "unknown config key 'rail.nope'"},
      {"generate rail --set rail.retract_speed_mm_s=-1", "rail.retract_speed_mm_s = -1: must be > 0"},
      {"generate rail --set sensor.pixel_noise_px=abc", "sensor.pixel_noise_px = 'abc': not a number"},
      {"generate rail --set rail.stimulus=cube", "rail.stimulus = 'cube': must be one of flat, acrylic, curved80"},
      {"generate rail --set novalue", "expected key=value"},
      {"generate rail --config " + P("bad.yaml"), "malformed YAML at line"},
      {"generate rail --config " + P("missing.yaml"), "missing.yaml"},
      {"generate nosuch", "unknown scenario 'nosuch' (known: rail, incipient)"},
      {"generate incipient --skin fingerprint-v3", "--skin 'fingerprint-v3': unknown skin"},
      {"generate rail --set external.enabled=true", "external.enabled = 1: the external camera sees the skin only"},
      {"generate rail --runs 0", "--runs"},
      {"generate rail --bogus", "bogus"},
      {"generate rail --speed-mm-s 1e-9", "the retraction would take"},
      {"export-mjcf rail --out /nonexistent/rail.xml", "folder '/nonexistent' does not exist"},
      {"bench --runs 3", "--runs"},
      {"info " + P("missing.h5"), "missing.h5"},
      {"info " + P("text.h5"), "not an HDF5 file"},
      {"validate contact --set skin.thicknes=1", "unknown config key 'skin.thicknes'"},
      {"validate contact --set skin.thickness_mm=9", "skin.thickness_mm = 9: must be <= 5"},
      {"validate contact --set skin.gel_shear_modulus_kpa=0.1",
       "the continuum-regime dome needs a membrane coupling length of"},
      {"validate contact --skin smooth", "needs the membrane-coupled lattice"},
      {"generate rail --set skin.rim=glued", "skin.rim = 'glued': must be one of free, clamped"},
      {"generate rail --set skin.rim=clamped --set skin.rings=10",
       "the pattern's edge (31.5 mm of arc) must lie inside the clamped rim"},
  };
  for (const auto& c : cases) {
    const bool gen = c.args.rfind("generate", 0) == 0 || c.args.rfind("bench", 0) == 0;
    const CliResult r = Run(c.args + (gen ? " --out " + P("x.h5") : std::string()));
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(LineCount(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(P("x.h5"))) << c.args;
  }
}

TEST_F(CliTest, FailedRunLeavesNoPartialDatasetAndKeepsTheOldOne) {
  std::ofstream(P("keep.h5")) << "previous contents";
  // Timestep far beyond the stability limit, with the guard switched off: the run
  // blows up mid-way and must not leave a dataset.
  const CliResult r = Run(std::string("generate rail ") + kQuickCliRun +
                          " --set sim.check_stability=false --set sim.timestep_s=0.006 --set contact.timeconst_s=0.012"
                          " --out " + P("keep.h5"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("stopped at t = "), std::string::npos) << r.err;
  EXPECT_EQ(Slurp(P("keep.h5")), "previous contents");
  EXPECT_EQ(FileCount(), 1u) << "only keep.h5: no temporary files left";
}

TEST_F(CliTest, FullDiskGetsOneLineExitCode2AndLeavesNoFile) {
  // A file system too small for one run's dataset (root only: it is a tmpfs).
  const testing::SmallTmpfs full(dir_ / "full", "200k");
  if (!full.mounted()) GTEST_SKIP() << full.reason();
  const std::string out = (full.dir() / "x.h5").string();
  const CliResult r = Run("generate rail --runs 1 --speed-mm-s 2 --set rail.lift_mm=10 --set rail.hold_s=0.1 --quiet --out " +
                          out);
  EXPECT_EQ(r.code, 2) << r.err;  // was a crash at exit (HDF5 closing a file whose close had failed)
  EXPECT_EQ(LineCount(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("tactip: cannot write dataset '" + out + "': ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(full.dir())) << "no partial or temporary file";
}

TEST_F(CliTest, ExportMjcfWritesTheCompilableScene) {
  const CliResult r = Run("export-mjcf rail --stimulus curved40 --out " + P("rail.xml"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string xml = Slurp(P("rail.xml"));
  EXPECT_NE(xml.find("name=\"tactip/pin126\""), std::string::npos);
  EXPECT_NE(xml.find("type=\"sphere\""), std::string::npos) << "curved stimulus is a sphere cap";
  const CompiledModel m = CompiledModel::FromXml(xml);
  EXPECT_GE(m.nv(), 127 + 2 + 2 + 1);
}

TEST_F(CliTest, ConfigListsEveryKeyTheIssueNames) {
  const CliResult r = Run("config rail");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* key : {"object.mass_kg", "contact.friction", "rail.retract_speed_mm_s", "rail.press_depth_mm",
                          "sensor.frame_rate_hz", "sensor.pixel_noise_px", "sim.timestep_s"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  }
}

TEST_F(CliTest, ShippedSceneYamlsEqualTheBuiltInDefaults) {
  for (const std::string name : {"rail", "incipient"}) {
    const CliResult a = Run("config " + name + " --yaml");
    const CliResult b =
        Run("config " + name + " --yaml --config " + TACTIP_SOURCE_DIR + "/assets/scenes/" + name + ".yaml");
    ASSERT_EQ(a.code, 0) << name;
    ASSERT_EQ(b.code, 0) << name << b.err;
    EXPECT_EQ(a.out, b.out) << name;
    // The shipped file is the commented dump of the defaults, so it documents every key.
    const CliResult c = Run("config " + name + " --yaml --comments");
    ASSERT_EQ(c.code, 0) << name;
    std::ifstream f(std::string(TACTIP_SOURCE_DIR) + "/assets/scenes/" + name + ".yaml");
    const std::string shipped((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_EQ(c.out, shipped) << name << ": regenerate with 'tactip config " << name << " --yaml --comments'";
  }
}

TEST_F(CliTest, SoftGelMaterialsFragmentChangesOnlyTheGelShearAndSkinModuli) {
  const std::string fragment = std::string(TACTIP_SOURCE_DIR) + "/assets/materials/soft-gel.yaml";
  for (const std::string name : {"rail", "incipient"}) {
    const CliResult a = Run("config " + name + " --yaml");
    const CliResult b = Run("config " + name + " --yaml --config " + fragment);
    ASSERT_EQ(a.code, 0) << name;
    ASSERT_EQ(b.code, 0) << name << b.err;
    std::istringstream da(a.out), db(b.out);
    std::vector<std::string> changed;
    for (std::string la, lb; std::getline(da, la) && std::getline(db, lb);) {
      if (la != lb) changed.push_back(lb);
    }
    // The incipient scenario's default skin, the fingerprint-v2 preset, already carries them.
    const auto expected = name == "rail"
                              ? std::vector<std::string>{"  gel_shear_modulus_kpa: 6.67", "  skin_modulus_mpa: 0.4"}
                              : std::vector<std::string>{};
    EXPECT_EQ(changed, expected) << name;
  }
}

}  // namespace
}  // namespace tactip
