// Option values refused before any work with one line and exit code 2 (seeds, non-finite
// numbers, empty text, unknown checks, outputs that are inputs, folders that take no
// files), failed commands leaving no folder of their own, and stale temporary files of
// killed runs removed on the next write.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "dead_pid.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;
using testing::Slurp;

class CliOptionsTest : public testing::CliFolderTest {
 protected:

  // Runs `args`; expects exit 2, one line on stderr holding every fragment, and no
  // file x.h5 written.
  void ExpectRefused(const std::string& args, const std::vector<std::string>& fragments) {
    const CliResult r = Run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << args << "\n" << r.err;
    for (const auto& f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(P("x.h5"))) << args;
  }

};

// Quick protocol: short lift, fast retraction.
const std::string kQuickOptionsRun = " --speed-mm-s 2 --set rail.lift_mm=10 --set rail.hold_s=0.1";
// The quick protocol with a step far beyond the stability limit and the guard off: the
// first run blows up (exit 3).
const std::string kBlowUp = kQuickOptionsRun +
                            " --set sim.check_stability=false --set sim.timestep_s=0.006"
                            " --set contact.timeconst_s=0.012";

TEST_F(CliOptionsTest, SeedsOutsideZeroTo2Pow64AreRefusedNotWrapped) {
  const std::string range = "must be a whole number from 0 to 18446744073709551615";
  for (const std::string seed : {"-1", "99999999999999999999999", "18446744073709551616", "1.5", "0x10"}) {
    for (const std::string& cmd : std::vector<std::string>{
             "generate rail --out " + P("x.h5"), "sweep rail --param rail.hold_s=0.1 --out " + P("s"),
          "accuracy rail --out " + P("a"), "bench --out " + P("b"), "train svm --data d.h5 --out " + P("x.h5")}) {
      ExpectRefused(cmd + " --seed " + seed, {"--seed: '" + seed + "': " + range});
    }
  }
  // The largest seed is taken as it is.
  const CliResult g = Run("generate rail --runs 1 --quiet --seed 18446744073709551615" + kQuickOptionsRun + " --out " + P("s.h5"));
  ASSERT_EQ(g.code, 0) << g.err;
  EXPECT_NE(Run("info " + P("s.h5")).out.find("seed 18446744073709551615)"), std::string::npos);
}

TEST_F(CliOptionsTest, NonFiniteNumbersAreRefusedForEveryRealOption) {
  for (const std::string v : {"nan", "inf", "-inf"}) {
    for (const std::string cmd : {"generate rail", "config rail", "export-mjcf rail", "validate contact", "bench",
                                  "sweep rail --param rail.hold_s=0.1", "accuracy rail"}) {
      ExpectRefused(cmd + " --speed-mm-s " + v, {"--speed-mm-s: '" + v + "': must be a finite number"});
    }
    for (const std::string& cmd : std::vector<std::string>{"train svm --data d.h5 --out " + P("x.h5"), "bench"}) {
      ExpectRefused(cmd + " --downsample " + v, {"--downsample: '" + v + "': must be a number in [1e-06, 1]"});
    }
    for (const std::string& cmd : std::vector<std::string>{"sweep rail --param rail.hold_s=0.1", "report incipient d.h5",
                                                           "detect incipient --data d.h5 --out " + P("x.h5")}) {
      ExpectRefused(cmd + " --speed-thr-px " + v, {"--speed-thr-px: '" + v + "': must be a number > 0"});
    }
  }
  // A sweep's detector threshold is refused before the sweep starts.
  const CliResult r = Run("sweep rail --param rail.hold_s=0.1 --runs 1 --speed-thr-px nan --out " + P("s"));
  EXPECT_EQ(r.err.find("sweeping"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(P("s")));
}

TEST_F(CliOptionsTest, RangeMessagesPrintReadableNumbers) {
  ExpectRefused("generate rail --speed-mm-s 1e-300 --out " + P("x.h5"),
                {"rail.retract_speed_mm_s = 1e-300: the retraction would take 1.01e+301 s of simulated time"});
  for (const std::string cmd : {"sweep rail --param rail.hold_s=0.1", "report incipient d.h5"}) {
    const CliResult r = Run(cmd + " --speed-thr-px 0");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "tactip: --speed-thr-px: '0': must be a number > 0 (see --help)\n") << cmd;
  }
  const CliResult d = Run("train svm --data d.h5 --downsample 2 --out " + P("m"));
  EXPECT_EQ(d.err, "tactip: --downsample: '2': must be a number in [1e-06, 1] (see --help)\n");
}

TEST_F(CliOptionsTest, ValidateRefusesAnUnknownCheckNamingTheKnownOnes) {
  for (const std::string args : {"validate contact nosuch", "validate nosuch"}) {
    const CliResult r = Run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, "tactip: what: unknown check 'nosuch'; the known checks are: contact, markers (see --help)\n") << args;
  }
}

TEST_F(CliOptionsTest, EmptyValuesAndOddListsAreRefused) {
  const std::string out = " --out " + P("x.h5");
  ExpectRefused("generate rail --stimulus ''" + out, {"--stimulus: empty; give one of flat, acrylic"});
  ExpectRefused("generate rail --skin ''" + out, {"--skin: empty; give one of smooth, fingerprint-v1"});
  ExpectRefused("generate rail --out ''", {"--out: empty; give a file name"});
  ExpectRefused("export-mjcf rail --out ''", {"--out: empty; give a file name"});
  ExpectRefused("sweep rail --param rail.hold_s=0.1 --out ''", {"--out: empty; give a folder"});
  ExpectRefused("bench --out ''", {"--out: empty; give a folder"});
  ExpectRefused("train svm --data d.h5 --runs ''" + out, {"--runs: empty; give runs"});
  ExpectRefused("train svm --data d.h5 --c-grid ''" + out, {"--c-grid: empty; give positive numbers"});
  ExpectRefused("generate rail --shard ''" + out, {"--shard: empty; give i/n"});
  ExpectRefused("evaluate --model m --data d.h5 --response ''", {"--response: empty; give a response strategy"});
  // A trailing comma is a missing value, not the end of the list (checked before the data is read).
  ExpectRefused("train logreg --data missing.h5 --c-grid 1,10," + out,
                {"--c-grid '1,10,': a value is missing after the last comma"});
  ExpectRefused("bench --jobs -1", {"--jobs: Value -1 not in range 0 to 256"});
}

TEST_F(CliOptionsTest, OutputThatIsAnInputIsRefusedThroughLinksToo) {
  const std::string yaml = "rail:\n  hold_s: 0.1\n";
  std::ofstream(P("c.yaml")) << yaml;
  fs::create_symlink(P("c.yaml"), P("sym.yaml"));
  fs::create_hard_link(P("c.yaml"), P("hard.yaml"));
  const std::string same = "is the same file as --config";
  ExpectRefused("generate rail --config " + P("c.yaml") + " --out " + P("c.yaml"), {"--out '" + P("c.yaml") + "' " + same});
  ExpectRefused("generate rail --config " + P("sym.yaml") + " --out " + P("c.yaml"), {same});
  ExpectRefused("export-mjcf rail --config " + P("c.yaml") + " --out " + P("hard.yaml"), {same});
  // Commands writing into a folder: an input among the files they write there.
  fs::create_directories(P("o"));
  for (const std::string name : {"designs.csv", "accuracy.csv", "bench.json"}) std::ofstream(P("o/" + name)) << yaml;
  ExpectRefused("sweep rail --param rail.hold_s=0.1 --config " + P("o/designs.csv") + " --out " + P("o"),
                {"--out '" + P("o/designs.csv") + "' " + same});
  ExpectRefused("accuracy rail --config " + P("o/accuracy.csv") + " --out " + P("o"), {same});
  ExpectRefused("bench --config " + P("o/bench.json") + " --out " + P("o"), {same});
  EXPECT_EQ(Slurp(P("c.yaml")), yaml);
  EXPECT_EQ(Slurp(P("o/designs.csv")), yaml);
}

TEST_F(CliOptionsTest, FolderThatTakesNoFilesIsRefusedBeforeTheRunsWithTheSystemsReason) {
  const CliResult r = Run("generate rail --runs 1" + kQuickOptionsRun + " --out /proc/x.h5");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("tactip: cannot write '/proc/x.h5': cannot create a file in folder '/proc' (", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST_F(CliOptionsTest, FailedBenchOrSweepLeavesNoFolderItCreated) {
  const CliResult b = Run("bench --runs 4" + kBlowUp + " --out " + P("new/bench"));
  EXPECT_EQ(b.code, 3) << b.err;
  EXPECT_FALSE(fs::exists(P("new"))) << "the whole created part of the path is gone";
  const CliResult s = Run("sweep rail --param rail.hold_s=0.1 --runs 1 --no-plots" + kBlowUp + " --out " + P("sweep"));
  EXPECT_EQ(s.code, 3) << s.err;
  EXPECT_FALSE(fs::exists(P("sweep")));
  // A folder that was there before stays.
  fs::create_directories(P("old"));
  EXPECT_EQ(Run("sweep rail --param rail.hold_s=0.1 --runs 1 --no-plots" + kBlowUp + " --out " + P("old")).code, 3);
  EXPECT_TRUE(fs::is_directory(P("old")));
}

using testing::DeadPid;

TEST_F(CliOptionsTest, StaleTempFileOfAKilledRunIsRemovedAndNamedOnTheNextRun) {
  const std::string stale = P("x.h5.tmp." + std::to_string(DeadPid()) + ".0");
  const std::string live = P("x.h5.tmp." + std::to_string(::getpid()) + ".0");  // a running writer's
  std::ofstream(stale) << "partial";
  std::ofstream(live) << "in progress";
  const CliResult r = Run("generate rail --runs 1 --quiet" + kQuickOptionsRun + " --out " + P("x.h5"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  const std::string line = "removed 1 stale temporary file(s) of processes no longer running: " + stale + "\n";
  ASSERT_NE(r.err.find(line), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("stale", r.err.find(line) + line.size()), std::string::npos) << "reported once: " << r.err;
}

}  // namespace
}  // namespace tactip
