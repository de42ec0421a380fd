// `tactip accuracy` end to end: one CSV row per setting with the reference first and its
// errors zero, the error-against-run-time plot, the same numbers again from the same seed
// (apart from wall time), and bad scenes or settings refused before anything runs.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "tests/scenarios/png_check.h"
#include "scenarios/studies/accuracy/compare.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::ReadPngInfo;
using testing::RunTactip;
using testing::Slurp;

class AccuracyCliTest : public testing::CliFolderTest {};

// A short protocol: fast retraction, short lift.
const std::string kQuickAccuracyRun = " --set rail.retract_speed_mm_s=1 --set rail.lift_mm=10 --runs 1 --quiet";

std::vector<std::vector<std::string>> CsvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST_F(AccuracyCliTest, OneRowPerSettingReferenceFirstPlotAndReproducibleNumbers) {
  const std::string args = "accuracy rail --setting dt=1ms --setting default" + kQuickAccuracyRun;
  const CliResult r = Run(args + " --out " + (dir_ / "a").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("reference"), std::string::npos) << r.out;
  const auto rows = CsvRows(Slurp(dir_ / "a" / "accuracy.csv"));
  ASSERT_EQ(rows.size(), 4u);  // header, reference, dt=1ms, default
  const auto& head = rows[0];
  const auto col = [&](const std::string& name) {
    for (size_t i = 0; i < head.size(); ++i) {
      if (head[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return size_t{0};
  };
  EXPECT_EQ(rows[1][col("setting")], "reference");
  EXPECT_EQ(rows[1][col("is_reference")], "1");
  EXPECT_EQ(rows[1][col("onset_error_ms")], "0");
  EXPECT_EQ(rows[1][col("traj_rms_px")], "0");
  // Zero because the reference is compared with itself; every other setting is compared with
  // the reference, and its marker trajectories differ from it.
  for (size_t k : {2, 3}) EXPECT_GT(std::stod(rows[k][col("traj_rms_px")]), 0.0) << rows[k][0];
  EXPECT_EQ(rows[3][col("is_default")], "1");
  EXPECT_GT(std::stod(rows[3][col("wall_s_per_sim_s")]), 0.0);
  // The finer step is slower than the default.
  EXPECT_GT(std::stod(rows[2][col("wall_s_per_sim_s")]), std::stod(rows[3][col("wall_s_per_sim_s")]));
  const auto png = ReadPngInfo(dir_ / "a" / "accuracy.png");
  EXPECT_GT(png.width, 400u);
  EXPECT_GT(png.bytes, 10000u);
  // The same seed gives the same errors (only the wall times differ).
  ASSERT_EQ(Run(args + " --out " + (dir_ / "b").string() + " --no-plots").code, 0);
  const auto again = CsvRows(Slurp(dir_ / "b" / "accuracy.csv"));
  ASSERT_EQ(again.size(), rows.size());
  for (size_t k = 1; k < rows.size(); ++k) {
    for (const char* c : {"onset_error_ms", "traj_rms_px", "creep_um", "label_disagreement_pct", "coulomb_error_ms"}) {
      EXPECT_EQ(again[k][col(c)], rows[k][col(c)]) << c << " of " << rows[k][0];
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "b" / "accuracy.png"));
}

TEST_F(AccuracyCliTest, BadSceneOrSettingIsRefusedWithOneLine) {
  CliResult r = Run("accuracy hand");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "tactip: accuracy: unknown scene 'hand' (known: rail, incipient, domes)\n");
  r = Run("accuracy rail --setting dt=9ms");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("tactip: unknown accuracy setting 'dt=9ms' (known: reference, default, dt=1ms"),
            std::string::npos)
      << r.err;
  r = Run("accuracy domes --list");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("reference"), std::string::npos);
  EXPECT_NE(r.out.find("[default]"), std::string::npos);
}

TEST_F(AccuracyCliTest, TimestepsAreSweptAroundTheScenesOwnDefaultStep) {
  // The rail scene's smooth skin runs at 2 ms, the incipient scene's fingerprint-v2 at 0.5 ms:
  // each reference is a quarter of that, each sweep half, three quarters and 1.25 times it.
  CliResult r = Run("accuracy rail --list");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("sim.timestep_s=0.0005 sim.iterations=100"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dt=2.5ms             sim.timestep_s=0.0025 contact.timeconst_s=0.005"), std::string::npos)
      << r.out;
  r = Run("accuracy incipient --list");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("sim.timestep_s=0.000125 sim.iterations=100"), std::string::npos) << r.out;
  for (const char* s : {"dt=0.25ms ", "dt=0.375ms ", "dt=0.625ms "}) EXPECT_NE(r.out.find(s), std::string::npos) << s;
  EXPECT_EQ(r.out.find("dt=0.5ms "), std::string::npos) << "the default step is not swept twice";
  // 4 ms is at least two 0.625 ms steps, so the time constant stays.
  EXPECT_NE(r.out.find("dt=0.625ms           sim.timestep_s=0.000625\n"), std::string::npos) << r.out;
}

TEST(CompareRunsTest, IdenticalRunsDifferByNothingAndAMissedOnsetIsInfinite) {
  RunRecord a;
  a.sensors.emplace_back().n_pins = 1;
  a.time = {0.0, 0.01};
  a.sensors[0].pos_px = {1, 1, 2, 2};
  a.sensors[0].pin_contact = {1, 1};
  a.sensors[0].pin_slip = {0, 1};
  a.attrs["gross_slip_onset_s"] = 0.02;
  RunRecord b = a;
  RunDifference d = CompareRuns(a, b);
  EXPECT_EQ(d.onset_error_s, 0.0);
  EXPECT_EQ(d.traj_rms_px, 0.0);
  EXPECT_EQ(d.label_disagreement, 0.0);
  b.sensors[0].pos_px = {1, 4, 2, 2};  // 3 px off in one of two frames
  b.sensors[0].pin_slip = {1, 1};      // one label of two differs
  b.attrs["gross_slip_onset_s"] = std::nan("");
  d = CompareRuns(a, b);
  EXPECT_TRUE(std::isinf(d.onset_error_s));
  EXPECT_NEAR(d.traj_rms_px, std::sqrt(9.0 / 2.0), 1e-12);
  EXPECT_NEAR(d.label_disagreement, 0.5, 1e-12);
}

}  // namespace
}  // namespace tactip
