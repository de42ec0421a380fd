// `tactip plot FILE.h5 --run K --out DIR` end to end on small generated datasets: the
// figures are real PNGs, the CSVs hold the dataset's values, bad input is refused in one
// line with nothing written.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "tests/scenarios/csv_table.h"
#include "tests/scenarios/png_check.h"
#include "sensors/dataset.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::Num;
using testing::ParseCsv;
using testing::ReadPngInfo;
using testing::RunTactip;
using testing::Slurp;

/// A short rail run (2 mm/s, 10 mm lift, 0.1 s hold: about a second of wall time).
const std::string kQuickPlotRail =
    "generate rail --runs 1 --quiet --speed-mm-s 2 --set rail.lift_mm=10 --set rail.hold_s=0.1";
/// CSV cells carry 9 significant digits (px values of a few hundred).
constexpr double kPlotCellTol = 1e-5;

/// Two datasets made once for the suite: a smooth-skin rail run, and the same on the acrylic
/// plate with external markers.
class PlotRunCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("tactip_PlotRunCliTest_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    ASSERT_EQ(RunTactip(kQuickPlotRail + " --out " + (dir_ / "rail.h5").string(), dir_).code, 0);
    ASSERT_EQ(RunTactip(kQuickPlotRail + " --stimulus acrylic --set external.enabled=true --out " +
                            (dir_ / "acrylic.h5").string(),
                        dir_)
                  .code,
              0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string P(const std::string& name) { return (dir_ / name).string(); }
  static CliResult Run(const std::string& args) { return RunTactip(args, dir_); }

  /// `args` fails with exit code 2 and exactly one line on stderr holding `message`, and
  /// creates no folder `out`.
  static void ExpectRefused(const std::string& args, const std::string& message, const std::string& out) {
    SCOPED_TRACE(args);
    const CliResult r = Run(args);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::is_directory(out)) << out;
  }

  static fs::path dir_;
};

fs::path PlotRunCliTest::dir_;

TEST_F(PlotRunCliTest, ARunWithExternalMarkersGivesFourValidPngsAndTheirCsvs) {
  const CliResult r = Run("plot " + P("acrylic.h5") + " --run 0 --sensor tactip --out " + P("figs/acrylic"));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"motion", "quiver", "markers", "indentation"}) {
    SCOPED_TRACE(name);
    const auto png = ReadPngInfo(dir_ / "figs/acrylic" / (std::string(name) + ".png"));
    EXPECT_GT(png.width, 0u);
    EXPECT_GT(png.height, 0u);
    EXPECT_TRUE(fs::is_regular_file(dir_ / "figs/acrylic" / (std::string(name) + ".csv")));
    EXPECT_NE(r.out.find("wrote " + P("figs/acrylic/") + name + ".png"), std::string::npos) << r.out;
  }
  EXPECT_EQ(r.out.find("note:"), std::string::npos) << r.out;
  EXPECT_EQ(testing::TempFilesIn(dir_ / "figs/acrylic"), 0);
}

TEST_F(PlotRunCliTest, ARunWithoutExternalMarkersHasNoMarkersFigureAndSaysSo) {
  const CliResult r = Run("plot " + P("rail.h5") + " --run 0 --no-plots --out " + P("rail"));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"events", "motion", "quiver", "indentation"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "rail" / (std::string(name) + ".csv"))) << name;
  }
  EXPECT_FALSE(fs::exists(dir_ / "rail/markers.csv"));
  EXPECT_NE(r.out.find("note: run 0 has no external markers: no markers.csv or markers.png"), std::string::npos)
      << r.out;
}

TEST_F(PlotRunCliTest, TheCsvsHoldTheDatasetsValues) {
  const CliResult r = Run("plot " + P("acrylic.h5") + " --run 0 --no-plots --out " + P("csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "csv/motion.png"));
  const RunRecord run = DatasetReader(P("acrylic.h5")).ReadRun(0);
  const SensorRecord& s = run.sensors.at(0);
  const auto n = static_cast<size_t>(s.n_pins);
  auto px = [&](const std::vector<float>& a, size_t f, size_t i, int c) { return double{a[(f * n + i) * 2 + c]}; };

  // Events: the run's onset time.
  const auto events = ParseCsv(Slurp(dir_ / "csv/events.csv"));
  ASSERT_EQ(events.size(), 3u);
  EXPECT_NEAR(Num(events[0], "time_s"), run.attrs.at("gross_slip_onset_s"), kPlotCellTol);
  // Motion: frame 100's mean displacement from frame 0 over all pins.
  const auto motion = ParseCsv(Slurp(dir_ / "csv/motion.csv"));
  ASSERT_EQ(motion.size(), run.frames());
  double mean = 0.0;
  for (size_t i = 0; i < n; ++i) mean += std::hypot(px(s.pos_px, 100, i, 0) - px(s.pos_px, 0, i, 0),
                                                   px(s.pos_px, 100, i, 1) - px(s.pos_px, 0, i, 1));
  EXPECT_NEAR(Num(motion[100], "mean_disp_px"), mean / static_cast<double>(n), kPlotCellTol);
  // Quiver: every row's velocity is its frame's position minus the previous frame's.
  for (const auto& row : ParseCsv(Slurp(dir_ / "csv/quiver.csv"))) {
    const auto f = static_cast<size_t>(Num(row, "frame")), i = static_cast<size_t>(Num(row, "pin"));
    ASSERT_GT(f, 0u);
    EXPECT_NEAR(Num(row, "du_px"), px(s.pos_px, f, i, 0) - px(s.pos_px, f - 1, i, 0), kPlotCellTol);
    EXPECT_NEAR(Num(row, "dv_px"), px(s.pos_px, f, i, 1) - px(s.pos_px, f - 1, i, 1), kPlotCellTol);
    EXPECT_EQ(Num(row, "contact"), s.pin_contact[f * n + i]);
  }
  // Markers: the external markers' mean speed at frame 100.
  const auto markers = ParseCsv(Slurp(dir_ / "csv/markers.csv"));
  double ext = 0.0;
  for (size_t i = 0; i < n; ++i) ext += std::hypot(px(s.external_px, 100, i, 0) - px(s.external_px, 99, i, 0),
                                                  px(s.external_px, 100, i, 1) - px(s.external_px, 99, i, 1));
  EXPECT_NEAR(Num(markers[100], "external_speed_px_frame"), ext / static_cast<double>(n), kPlotCellTol);
  // Indentation: the centre pin is pressed in along the axis, contacts as stored.
  const auto indent = ParseCsv(Slurp(dir_ / "csv/indentation.csv"));
  ASSERT_EQ(indent.size(), n);
  EXPECT_GT(Num(indent[0], "axial_in_mm"), 1.0);  // the run presses ~3 mm
  EXPECT_EQ(Num(indent[0], "contact"), 1.0);
}

TEST_F(PlotRunCliTest, BadInputIsRefusedInOneLineWithNothingWritten) {
  const std::string out = P("refused");
  ExpectRefused("plot " + P("missing.h5") + " --run 0 --out " + out, "cannot open dataset", out);
  ExpectRefused("plot " + P("rail.h5") + " --run 7 --out " + out, "--run 7: " + P("rail.h5") + " has no run 7 (it has run 0)",
                out);
  ExpectRefused("plot " + P("rail.h5") + " --run 0 --sensor left --out " + out,
                "--sensor 'left': dataset '" + P("rail.h5") + "' has no such sensor (its sensors: tactip)", out);
  ExpectRefused("plot " + P("rail.h5") + " --run 0 --out " + P("rail.h5"),
                "--out '" + P("rail.h5") + "' is the input dataset FILE: give a folder for the figures", out);
  ExpectRefused("plot " + P("rail.h5") + " --run 0 --out " + P("acrylic.h5"),
                "--out '" + P("acrylic.h5") + "' is an existing file, not a folder", out);
  ExpectRefused("plot " + P("rail.h5") + " --run 0 --out " + P("acrylic.h5") + "/figures",
                "cannot create output folder '" + P("acrylic.h5") + "/figures': Not a directory", out);
  ExpectRefused("plot " + P("rail.h5") + " --run -1 --out " + out, "--run: Value -1 not in range", out);
  ExpectRefused("plot " + P("rail.h5") + " --run 0 --out ''", "--out: empty; give a folder", out);
}

}  // namespace
}  // namespace tactip
