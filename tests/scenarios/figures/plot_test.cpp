// The plotting layer: the matplotlib script run from C++ (heatmap, pareto), its Pareto
// front against a hand-computed answer, and CheckPlotting's messages when a piece is missing.

#include "scenarios/figures/plot.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "detectors/scratch.h"
#include "input_error.h"
#include "tests/scenarios/png_check.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;
using testing::ReadPngInfo;
using testing::TempPath;
using testing::WriteFile;

/// Sets an environment variable for one scope, restoring the old value after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

/// An accuracy table worked by hand (x = run time, smaller is better in both):
///  - err_a front: coarse (1, 5), default and tie (2, 2; equal, so neither dominates), fine
///    (5, 0.5), ref (10, 0); slow_bad (4, 3) is beaten by default; fast_unhealthy beats
///    everything but is unhealthy; nan_x has no run time.
///  - err_b front: coarse, default (2, 1), slow_bad (4, 0.5), ref (10, 0); tie (2, 3) is
///    beaten by default at the same run time; fine has no value.
constexpr const char* kAccuracyCsv =
    "setting,wall_s_per_sim_s,err_a,err_b,is_default,is_reference,healthy\n"
    "ref,10,0,0,0,1,1\n"
    "fine,5,0.5,,0,0,1\n"
    "default,2,2,1,1,0,1\n"
    "tie,2,2,3,0,0,1\n"
    "slow_bad,4,3,0.5,0,0,1\n"
    "fast_unhealthy,0.5,0.1,0.1,0,0,0\n"
    "coarse,1,5,5,0,0,1\n"
    "nan_x,nan,1,1,0,0,1\n";

ParetoPlot AccuracyPlot(const std::string& csv) {
  ParetoPlot p;
  p.csv = csv;
  p.y_columns = {"err_a", "err_b"};
  p.title = "test accuracy";
  return p;
}

TEST(ParetoFrontTest, MatchesTheHandComputedFront) {
  const std::string csv = TempPath("accuracy.csv");
  WriteFile(csv, kAccuracyCsv);
  using Fronts = std::vector<std::pair<std::string, std::vector<std::string>>>;
  const Fronts expected = {{"err_a", {"coarse", "default", "tie", "fine", "ref"}},
                           {"err_b", {"coarse", "default", "slow_bad", "ref"}}};
  EXPECT_EQ(ParetoFronts(AccuracyPlot(csv)), expected);
}

TEST(PlotTest, ParetoPlotWritesAPng) {
  const std::string csv = TempPath("accuracy.csv");
  WriteFile(csv, kAccuracyCsv);
  ParetoPlot p = AccuracyPlot(csv);
  p.out_png = TempPath("pareto.png");
  PlotPareto(p);
  const auto png = ReadPngInfo(p.out_png);
  EXPECT_GT(png.bytes, 10000u);
  EXPECT_GE(png.width, 600u);
  EXPECT_GE(png.height, 400u);
  EXPECT_EQ(testing::TempFilesIn(fs::path(p.out_png).parent_path()), 0);
}

TEST(PlotTest, HeatmapsOfOneAndTwoKeysWritePngs) {
  const std::string csv = TempPath("designs.csv");
  WriteFile(csv, "design,a.x_mm,b.y,f1\n0,1,p,0.5\n1,1,q,nan\n2,2,p,0.75\n3,2,q,1\n");
  const std::vector<HeatmapPlot> plots = {{csv, "b.y", "a.x_mm", "f1", "F1 by design", "", TempPath("two.png")},
                                          {csv, "design", "", "f1", "F1", "1", TempPath("one.png")}};
  for (const HeatmapPlot& p : plots) {
    PlotHeatmap(p);
    const auto png = ReadPngInfo(p.out_png);
    EXPECT_GT(png.bytes, 5000u) << p.out_png;
    EXPECT_GE(png.width, 400u) << p.out_png;
  }
}

TEST(PlotTest, AFailedPlotNamesTheProblemAndWritesNothing) {
  const std::string csv = TempPath("designs.csv");
  WriteFile(csv, "design,a,f1\n0,1,0.5\n");
  const std::string out = TempPath("none.png");
  try {
    PlotHeatmap({csv, "a", "", "no_such_metric", "t", "", out});
    FAIL() << "a missing column was accepted";
  } catch (const PlotError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("plot '" + out + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no column 'no_such_metric'"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(testing::TempFilesIn(fs::path(out).parent_path()), 0);
}

TEST(CheckPlottingTest, PassesHere) { EXPECT_NO_THROW(CheckPlotting()); }

TEST(CheckPlottingTest, NamesAnInterpreterThatDoesNotExist) {
  const ScopedEnv env("TACTIP_PYTHON", "/nonexistent/python3");
  EXPECT_EQ(PlotPython(), "/nonexistent/python3");
  const std::string msg = InputErrorOf([] { CheckPlotting(); });
  EXPECT_NE(msg.find("plots need python3 with matplotlib"), std::string::npos) << msg;
  EXPECT_NE(msg.find("TACTIP_PYTHON=/nonexistent/python3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
  EXPECT_NE(msg.find("apt-get install python3-matplotlib"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--no-plots"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

TEST(CheckPlottingTest, NamesAnInterpreterWithoutMatplotlib) {
  // The same python without its site packages (-S) cannot import matplotlib.
  const std::string wrapper = TempPath("python-bare");
  WriteFile(wrapper, "#!/bin/sh\nexec '" + PlotPython() + "' -S \"$@\"\n");
  ::chmod(wrapper.c_str(), 0755);
  const ScopedEnv env("TACTIP_PYTHON", wrapper);
  const std::string msg = InputErrorOf([] { CheckPlotting(); });
  EXPECT_NE(msg.find("TACTIP_PYTHON=" + wrapper + " cannot draw"), std::string::npos) << msg;
  EXPECT_NE(msg.find("No module named 'matplotlib'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("apt-get install python3-matplotlib"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

TEST(CheckPlottingTest, NamesAMissingScript) {
  const ScopedEnv env("TACTIP_SCRIPTS_DIR", "/nonexistent/scripts");
  EXPECT_EQ(PlotScript(), "/nonexistent/scripts/plots/tactip_plot.py");
  const std::string msg = InputErrorOf([] { CheckPlotting(); });
  EXPECT_NE(msg.find("'/nonexistent/scripts/plots/tactip_plot.py'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("set TACTIP_SCRIPTS_DIR"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--no-plots"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tactip
