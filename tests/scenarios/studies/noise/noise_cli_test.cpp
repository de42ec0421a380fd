// `tactip report noise` on the command line: a short rail run with each noise model, the
// table beside the real TacTip's figures and the CSV; bad input gives one line and exit 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/scenarios/cli_helpers.h"

namespace tactip {
namespace {

using testing::CliFolderTest;
using testing::CliResult;
using testing::Slurp;

// One rail run retracting fast. On the default 50 mm lift the skin has settled by the hold
// (after a 10 mm lift it still moves: the independent model's common mode reads 2.8x).
const std::string kQuickRail = "generate rail --quiet --runs 1 --speed-mm-s 5";

class NoiseCliTest : public CliFolderTest {};

// The value in the table's summary line that starts with `figure`.
double SummaryValue(const std::string& table, const std::string& figure) {
  const size_t at = table.find("\n" + figure);
  if (at == std::string::npos) return -1.0;
  return std::stod(table.substr(at + 1 + 30, 11));
}

TEST_F(NoiseCliTest, TheStructuredModelHasTheCommonModeTheIndependentOneLacks) {
  // The independent model of the legacy camera (f = 580 px, 0.28 px) and the default: the
  // structured model on the real 640x480 camera (outer ring 131 px, f = 377 px).
  ASSERT_EQ(Run(kQuickRail + " --camera legacy --out " + P("i.h5")).code, 0);
  ASSERT_EQ(Run(kQuickRail + " --out " + P("s.h5")).code, 0);
  const CliResult i = Run("report noise " + P("i.h5"));
  const CliResult s = Run("report noise " + P("s.h5") + " --csv " + P("s.csv"));
  ASSERT_EQ(i.code, 0) << i.err;
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_NE(s.out.find("real TacTip"), std::string::npos) << s.out;
  EXPECT_EQ(s.out.find("whole run"), std::string::npos) << s.out;  // the held window
  // Independent noise: the mean over the pins is independent noise's (ratio ~1), the fits
  // remove ~2 %; structured: several times more, most of the variance.
  EXPECT_LT(SummaryValue(i.out, "common mode / independent"), 1.6) << i.out;
  EXPECT_LT(SummaryValue(i.out, "similarity removes"), 0.1) << i.out;
  EXPECT_GT(SummaryValue(s.out, "common mode / independent"), 3.0) << s.out;
  EXPECT_GT(SummaryValue(s.out, "similarity removes"), 0.4) << s.out;
  // Both keep the hardware's static pin speed at W = 1 and W = 5.
  for (const std::string& out : {i.out, s.out}) {
    EXPECT_NEAR(SummaryValue(out, "pin speed W=1, px/frame"), 0.5, 0.1) << out;
    EXPECT_NEAR(SummaryValue(out, "pin speed W=5, px/frame"), 0.1, 0.03) << out;
  }
  const std::string csv = Slurp(P("s.csv"));
  EXPECT_EQ(csv.rfind("run,sensor,held,frames,pins,", 0), 0u) << csv;
  EXPECT_NE(csv.find("\n0,tactip,1,"), std::string::npos) << csv;
}

TEST_F(NoiseCliTest, BadInputIsOneLineAndExitCode2) {
  const CliResult missing = Run("report noise " + P("none.h5"));
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  const CliResult model = Run("config rail --set sensor.noise_model=gaussian");
  EXPECT_EQ(model.code, 2);
  EXPECT_NE(model.err.find("sensor.noise_model"), std::string::npos) << model.err;
  EXPECT_EQ(std::count(model.err.begin(), model.err.end(), '\n'), 1) << model.err;
}

}  // namespace
}  // namespace tactip
