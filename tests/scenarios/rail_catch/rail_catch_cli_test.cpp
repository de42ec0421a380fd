// `tactip run rail-catch` from the command line: outputs and refusals.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/scenarios/cli_helpers.h"

namespace tactip {
namespace {

class RailCatchCliTest : public testing::CliFolderTest {
 protected:
  // A threshold detector model file (the format Detector::Save writes).
  std::string ThresholdModel(double px) {
    const std::string path = P("thr.model");
    std::ofstream(path) << "tactip-detector threshold 1\nthreshold_px " << px << "\n";
    return path;
  }
  static std::string Slurp(const std::string& path) {
    std::stringstream s;
    s << std::ifstream(path).rdbuf();
    return s.str();
  }
};

TEST_F(RailCatchCliTest, WritesOneRowPerTrialTheSummaryAndTheTable) {
  // 0.8 px/frame: above the held frames' noise at 1-3 mm/s (at most 0.8), below the slip spike (1.4-1.8).
  const auto r = Run("run rail-catch --model " + ThresholdModel(0.8) +
                     " --trials 2 --speed-mm-s 3 --quiet --jobs 2 --out " + P("catch"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = Slurp(P("catch/trials.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);  // header + 2 trials
  EXPECT_NE(csv.find("\n0,flat,3,caught,"), std::string::npos) << csv;
  EXPECT_NE(Slurp(P("catch/summary.csv")).find("flat,3,2,100.0,0.0,0.0,"), std::string::npos);
  EXPECT_NE(r.out.find("100 %, 18.7 mm"), std::string::npos) << r.out;  // the hardware's row at 3 mm/s
}

TEST_F(RailCatchCliTest, RefusesBadOptionsInOneLineBeforeAnyTrial) {
  const std::string model = ThresholdModel(0.3);
  const struct {
    std::string args, message;
  } cases[] = {
      {"", "no detector model: 'bench-results/svm-rbf.model' does not exist"},
      {"--model " + model + " --speed-mm-s 30", "--speed-mm-s 30: must be in [0.1, 20] mm/s"},
      {"--model " + model + " --speed-mm-s 1,", "--speed-mm-s '1,': empty item in the list"},
      {"--model " + model + " --response 2Fr2Sen", "--response '2Fr2Sen'"},
      {"--model " + model + " --stimulus flat,nosuch", "rail.stimulus"},
      {"--model " + P("missing.model"), "missing.model"},
      {"--model " + model + " --catch-extra-mm 4",
       "--catch-extra-mm = 4: the catch would press rail.press_depth_mm + rail.press_depth_jitter_mm + 4 = 7.1 mm, "
       "beyond the 7 mm a TacTip tolerates; use --catch-extra-mm <= 3.9"},
      {"--model " + model + " --catch-extra-mm 1 --set rail.press_depth_mm=6.5",
       "--catch-extra-mm = 1: the catch would press rail.press_depth_mm + rail.press_depth_jitter_mm + 1 = 7.6 mm"},
  };
  for (const auto& c : cases) {
    const auto r = Run("run rail-catch --trials 1 --out " + P("out") + " " + c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(P("out"))) << c.args;
  }
}

}  // namespace
}  // namespace tactip
