// `tactip report signatures` on the command line: a small generated rail dataset gives the
// gross-slip table, n/a for the incipient figures and one CSV row per run; bad input
// gives one line, exit code 2 and no file.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"

namespace tactip {
namespace {

using testing::CliFolderTest;
using testing::CliResult;
using testing::Slurp;

namespace fs = std::filesystem;

// Two short rail runs: fast retraction, short lift and hold (a few seconds in all).
const std::string kQuickSignatureRail = "generate rail --quiet --speed-mm-s 2 --set rail.lift_mm=10 --set rail.hold_s=0.1";

/// A test of `tactip report signatures` in its own folder.
class SignatureCliTest : public CliFolderTest {};

// Number of comma-separated fields of one CSV line.
size_t Fields(const std::string& line) { return static_cast<size_t>(std::count(line.begin(), line.end(), ',')) + 1; }

TEST_F(SignatureCliTest, ReportSignaturesPrintsTheGrossSlipFiguresAndOneCsvRowPerRun) {
  ASSERT_EQ(Run(kQuickSignatureRail + " --runs 2 --out " + P("d.h5")).code, 0);
  const CliResult r = Run("report signatures " + P("d.h5") + " --csv " + P("s.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("gross slip: 2 of 2 runs have an onset; noise over the 0.1 s before the retraction"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("spike width, frames "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(">= 15 in >= 80 % of runs: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("incipient slip: n/a (no fingerprint-skin run with a fall"), std::string::npos) << r.out;
  // Header and two rows of the same width; the smooth skin's incipient cells are n/a.
  std::ifstream csv(P("s.csv"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].substr(0, 36), "run,speed_mm_s,skin,incipient_onset,");
  for (const std::string& row : {lines[1], lines[2]}) {
    EXPECT_EQ(Fields(row), Fields(lines[0])) << row;
    EXPECT_NE(row.find(",2,smooth,0,"), std::string::npos) << row;
    EXPECT_NE(row.find(",n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,"), std::string::npos) << row;
    // The last four cells: the pattern's step at gross slip (px), its W5 speed after it, the
    // camera's first-moving sector and the best pin's excess (n/a, n/a: no incipient
    // signature on the smooth skin).
    const size_t last = row.rfind(',', row.rfind(',') - 1);
    EXPECT_EQ(row.substr(last), ",n/a,n/a") << row;
    const size_t after = row.rfind(',', last - 1);
    const size_t step = row.rfind(',', after - 1);
    EXPECT_GT(std::stod(row.substr(step + 1, after - step - 1)), 1.0) << row;
    EXPECT_LT(std::stod(row.substr(after + 1, last - after - 1)), 1.0) << row;
  }
}

TEST_F(SignatureCliTest, ReportSignaturesRefusesBadInputInOneLineAndWritesNothing) {
  ASSERT_EQ(Run(kQuickSignatureRail + " --runs 1 --out " + P("d.h5")).code, 0);
  std::ofstream(P("text.h5")) << "not hdf5\n";
  const struct {
    std::string args, message;
  } cases[] = {
      {"report signatures " + P("none.h5") + " --csv " + P("x.csv"),
       "cannot open dataset '" + P("none.h5") + "': no such file"},
      {"report signatures " + P("text.h5") + " --csv " + P("x.csv"),
       "cannot open dataset '" + P("text.h5") + "': not an HDF5 file"},
      {"report signatures " + P("d.h5") + " --sensor left --csv " + P("x.csv"),
       "--sensor 'left': dataset '" + P("d.h5") + "' has no such sensor (its sensors: tactip)"},
      {"report signatures " + P("d.h5") + " --csv " + P("d.h5"),
       "--csv '" + P("d.h5") + "' is the same file as FILE '" + P("d.h5") +
           "': the output would overwrite the input; write it to another file"},
      {"report signature " + P("d.h5"), "what: signature not in {incipient,signatures,tracking,noise} (see --help)"},
  };
  const auto size_before = fs::file_size(P("d.h5"));
  for (const auto& c : cases) {
    const CliResult r = Run(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.err, "tactip: " + c.message + "\n") << c.args;
    EXPECT_EQ(r.out, "") << c.args;
    EXPECT_FALSE(fs::exists(P("x.csv"))) << c.args;
  }
  EXPECT_EQ(fs::file_size(P("d.h5")), size_before);
}

}  // namespace
}  // namespace tactip
