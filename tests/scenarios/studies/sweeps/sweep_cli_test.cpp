// `tactip sweep` end to end: one CSV row per design, PNG heatmaps, exact reproduction with
// the same seed, --no-plots, and bad grids or a missing plotting tool rejected before
// anything runs.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/long_experiment.h"
#include "tests/scenarios/cli_helpers.h"
#include "tests/scenarios/png_check.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::ReadPngInfo;
using testing::RunTactip;
using testing::Slurp;

class SweepCliTest : public testing::CliFolderTest {};

/// The metrics drawn as heatmaps (`<metric>.png`).
constexpr const char* kMetrics[] = {"lead_gross_mean_s",    "lead_gross_std_s",     "pre_slip_fraction",
                                    "peak_speed_px",        "detector_lead_fall_s", "detector_miss_rate"};

using testing::SplitLines;

// Drops the last `n` comma-separated columns (timings) of every line.
std::string WithoutLastColumns(const std::string& csv, int n) {
  std::string out;
  for (std::string line : SplitLines(csv)) {
    for (int k = 0; k < n; ++k) line = line.substr(0, line.rfind(','));
    out += line + "\n";
  }
  return out;
}

// The sweep's mechanics are under test, not its figures: the runs use the membrane skin's
// validated 1 ms step, half the cost of the scene's 0.5 ms, and a short protocol (10 mm lift,
// 1 mm/s retraction: a third of the scenario's simulated time).
constexpr const char* kValidatedStep =
    " --set sim.timestep_s=0.001 --set rail.lift_mm=10 --set rail.retract_speed_mm_s=1";

TEST_F(SweepCliTest, GridGivesOneRowPerDesignPngHeatmapsAndReproducesExactly) {
  TACTIP_LONG_EXPERIMENT();
  const std::string args = std::string("sweep incipient --param skin.thickness_mm=0.5,1 --param skin.ridge_spacing_mm=3,4") +
                           kValidatedStep + " --runs 1 --quiet --out ";
  const CliResult a = Run(args + (dir_ / "a").string());
  ASSERT_EQ(a.code, 0) << a.err;
  const std::string csv = Slurp(dir_ / "a" / "designs.csv");
  const auto rows = SplitLines(csv);
  ASSERT_EQ(rows.size(), 5u) << csv;  // header + 2 x 2 designs, first key slowest
  EXPECT_EQ(rows[0].rfind("design,skin.thickness_mm,skin.ridge_spacing_mm,n_pins,", 0), 0u) << rows[0];
  EXPECT_EQ(rows[1].rfind("0,0.5,3,127,", 0), 0u) << rows[1];
  EXPECT_EQ(rows[2].rfind("1,0.5,4,61,", 0), 0u) << rows[2];
  EXPECT_EQ(rows[4].rfind("3,1,4,61,", 0), 0u) << rows[4];
  EXPECT_EQ(SplitLines(Slurp(dir_ / "a" / "runs.csv")).size(), 5u);
  // Where the slip starts: run counts per design (before the timings), the order per run.
  EXPECT_NE(rows[0].find(",shear_relaxation_s,east_west_first,south_before_north,hardware_order,sim_time_s,"
                         "wall_time_s"),
            std::string::npos)
      << rows[0];
  EXPECT_NE(SplitLines(Slurp(dir_ / "a" / "runs.csv"))[0].find(",sector_order,east_west_first,south_before_north,"
                                                          "hardware_order"),
            std::string::npos);
  for (const char* m : kMetrics) {
    const auto png = ReadPngInfo(dir_ / "a" / (std::string(m) + ".png"));
    EXPECT_GT(png.bytes, 5000u) << m << ": not a PNG or trivially small";
    EXPECT_GE(png.width, 400u) << m;
  }
  EXPECT_EQ(testing::TempFilesIn(dir_ / "a"), 0);
  // Same seed: identical figures (only the timing columns may differ).
  const CliResult b = Run(args + (dir_ / "b").string() + " --jobs 1");
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(WithoutLastColumns(csv, 2), WithoutLastColumns(Slurp(dir_ / "b" / "designs.csv"), 2));
  EXPECT_EQ(Slurp(dir_ / "a" / "runs.csv"), Slurp(dir_ / "b" / "runs.csv"));
}

TEST_F(SweepCliTest, NoPlotsWritesTheCsvsOnly) {
  // Plotting is not even checked: a missing interpreter does not matter.
  ::setenv("TACTIP_PYTHON", "/nonexistent/python3", 1);
  const CliResult r = Run(std::string("sweep incipient --param skin.thickness_mm=1 --runs 1 --quiet --no-plots") +
                          kValidatedStep + " --out " + (dir_ / "c").string());
  ::unsetenv("TACTIP_PYTHON");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(SplitLines(Slurp(dir_ / "c" / "designs.csv")).size(), 2u);
  for (const char* m : kMetrics) EXPECT_FALSE(fs::exists(dir_ / "c" / (std::string(m) + ".png"))) << m;
}

TEST_F(SweepCliTest, MissingMatplotlibFailsBeforeAnythingRuns) {
  ::setenv("TACTIP_PYTHON", "/nonexistent/python3", 1);
  const CliResult r = Run("sweep incipient --param skin.thickness_mm=1 --runs 1 --out " + (dir_ / "d").string());
  ::unsetenv("TACTIP_PYTHON");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("plots need python3 with matplotlib"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--no-plots"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_EQ(r.err.find("sweeping"), std::string::npos) << "runs started: " << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "d" / "designs.csv"));
}

TEST_F(SweepCliTest, InvalidDesignIsRejectedBeforeAnythingRuns) {
  // The second value breaks the v2 pin rule (pin longer than ridge + skin).
  const CliResult r = Run("sweep incipient --param skin.pin_length_mm=1,4 --runs 1 --out " + (dir_ / "bad").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("design skin.pin_length_mm=4"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad" / "designs.csv"));
  const CliResult k = Run("sweep incipient --param skin.nope=1,2 --runs 1 --out " + (dir_ / "bad").string());
  EXPECT_EQ(k.code, 2);
  EXPECT_NE(k.err.find("unknown config key 'skin.nope'"), std::string::npos) << k.err;
  const CliResult s = Run("sweep incipient --param skin.thickness_mm=1:0:1 --out " + (dir_ / "bad").string());
  EXPECT_EQ(s.code, 2);
  EXPECT_NE(s.err.find("stop < start"), std::string::npos) << s.err;
}

}  // namespace
}  // namespace tactip
