// The online rail catch: trials scored as on hardware, and the closed loop's physics.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "detectors/threshold.h"
#include "scenarios/rail_catch/catch_report.h"
#include "scenarios/rail_catch/catch_trials.h"
#include "sim/base/nan.h"
#include "tests/input_error.h"

namespace tactip {
namespace {

// A record of `frames` frames at 100 fps whose object height follows `height(t)`.
template <class F>
RunRecord Heights(int frames, F height) {
  RunRecord rec;
  for (int k = 0; k < frames; ++k) {
    rec.time.push_back(k * 0.01);
    rec.object_height_m.push_back(height(k * 0.01));
  }
  return rec;
}

RailRunSummary Summary(double onset_s, double declared_s) {
  RailRunSummary s;
  s.gross_slip_onset_s = onset_s;
  if (!std::isnan(declared_s)) s.actions = {{declared_s, "slip_declared"}, {declared_s + 0.013, "catch"}};
  return s;
}

TEST(ScoreCatchTrialTest, DeclaredAfterOnsetAndAtRestClearOfTheStopIsCaught) {
  // Slides 12 mm from 1.0 s to 1.2 s, then stays at 38 mm.
  const RunRecord rec = Heights(200, [](double t) { return 0.05 - 0.06 * std::clamp(t - 1.0, 0.0, 0.2); });
  const CatchTrial t = ScoreCatchTrial(Summary(1.0, 1.02), rec, 5.0);
  EXPECT_EQ(t.outcome, CatchOutcome::kCaught);
  EXPECT_NEAR(t.slip_distance_mm, 12.0, 1e-9);
  EXPECT_NEAR(t.delay_ms, 20.0, 1e-9);
}

TEST(ScoreCatchTrialTest, ActingBeforeTheOnsetIsAFalsePositive) {
  const RunRecord rec = Heights(200, [](double) { return 0.05; });
  EXPECT_EQ(ScoreCatchTrial(Summary(kNaN, 1.5), rec, 0.0).outcome, CatchOutcome::kFalsePositive);
  EXPECT_EQ(ScoreCatchTrial(Summary(1.6, 1.5), rec, 0.0).outcome, CatchOutcome::kFalsePositive);
}

TEST(ScoreCatchTrialTest, NoDeclarationOrAnObjectOnTheStopOrStillSlidingIsDropped) {
  const RunRecord on_stop = Heights(200, [](double t) { return std::max(0.0, 0.05 - 0.5 * std::max(0.0, t - 1.0)); });
  EXPECT_EQ(ScoreCatchTrial(Summary(1.0, kNaN), on_stop, 0.0).outcome, CatchOutcome::kDropped);
  EXPECT_EQ(ScoreCatchTrial(Summary(1.0, 1.02), on_stop, 0.0).outcome, CatchOutcome::kDropped);
  const RunRecord sliding = Heights(200, [](double t) { return 0.05 - 0.01 * std::max(0.0, t - 1.0); });
  EXPECT_EQ(ScoreCatchTrial(Summary(1.0, 1.02), sliding, 0.0).outcome, CatchOutcome::kDropped);
}

TEST(CatchReportTest, SummaryGroupsByStimulusAndSpeedWithTheHardwareBeside) {
  std::vector<CatchTrial> trials(4);
  for (int i = 0; i < 4; ++i) {
    trials[i].trial = i;
    trials[i].stimulus = "flat";
    trials[i].speed_mm_s = i < 2 ? 1.0 : 10.0;
    trials[i].slip_distance_mm = 10.0 + i;
  }
  trials[0].outcome = trials[1].outcome = trials[2].outcome = CatchOutcome::kCaught;
  trials[3].outcome = CatchOutcome::kFalsePositive;
  const auto rows = SummariseCatch(trials);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].caught_pct, 100.0);
  EXPECT_EQ(rows[0].mean_distance_mm, 10.5);
  EXPECT_EQ(rows[0].hardware, "100 %, 17.6 mm");
  EXPECT_EQ(rows[1].caught_pct, 50.0);
  EXPECT_EQ(rows[1].false_positive_pct, 50.0);
  EXPECT_EQ(rows[1].hardware, "80 %, 24.8 mm");
  const std::string csv = CatchTrialsCsv(trials);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "trial,stimulus,speed_mm_s,outcome,slip_distance_mm,onset_s,declared_s,delay_ms,classify_us");
  EXPECT_NE(csv.find("\n3,flat,10,false_positive,13.000,"), std::string::npos);
}

// Trials of the rail at 1 mm/s with a threshold detector of `threshold_px` in the loop.
class RailCatchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = std::filesystem::temp_directory_path() / ("tactip_catch_" + std::to_string(::getpid()) + ".model");
  }
  void TearDown() override { std::filesystem::remove(model_); }
  std::vector<CatchTrial> Trials(double threshold_px, const CatchOptions& loop, int trials = 2) {
    ThresholdDetector(threshold_px).Save(model_.string());
    RailScenarioConfig cfg;
    cfg.rail.retract_speed_mm_s = 1.0;
    CatchTrialOptions o;
    o.model_path = model_.string();
    o.loop = loop;
    o.trials = trials;
    o.seed = 3;
    return RunCatchTrials(cfg, o);
  }
  std::filesystem::path model_;
};

TEST_F(RailCatchTest, ADetectorThatFiresOnSlipCatchesAndALongerLoopLetsTheObjectSlideFurther) {
  CatchOptions quick, slow;
  slow.arm_response_ms = 80.0;
  // 0.8 px/frame: above the held frames' |mean pin velocity| at 1-3 mm/s (at most 0.8 on the
  // default camera and noise), below the slip spike (1.4-1.8).
  const auto fast_trials = Trials(0.8, quick), slow_trials = Trials(0.8, slow);
  double fast_mm = 0.0, slow_mm = 0.0;
  for (const CatchTrial& t : fast_trials) {
    EXPECT_EQ(t.outcome, CatchOutcome::kCaught) << "trial " << t.trial;
    EXPECT_GT(t.delay_ms, 0.0);  // declared after the onset
    fast_mm += t.slip_distance_mm;
  }
  for (const CatchTrial& t : slow_trials) slow_mm += t.slip_distance_mm;
  EXPECT_GT(fast_mm, 0.0);
  EXPECT_GT(slow_mm, fast_mm + 1.0);
}

TEST_F(RailCatchTest, ADetectorThatNeverFiresDropsAndAHairTriggerActsBeforeSlip) {
  for (const CatchTrial& t : Trials(1e6, CatchOptions{}, 1)) {
    EXPECT_EQ(t.outcome, CatchOutcome::kDropped);
    EXPECT_TRUE(std::isnan(t.declared_s));
  }
  for (const CatchTrial& t : Trials(0.0, CatchOptions{}, 1)) EXPECT_EQ(t.outcome, CatchOutcome::kFalsePositive);
}

TEST(CatchOptionsTest, EveryRefusalNamesTheOption) {
  CatchOptions o;
  o.response = "2Fr2Sen";
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("--response '2Fr2Sen'"), std::string::npos);
  o = CatchOptions{};
  o.classify_ms = -1.0;
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("--classify-ms = -1: must be in [0, 1000]"), std::string::npos);
  o = CatchOptions{};
  o.catch_speed_mm_s = 0.0;
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("--catch-speed-mm-s"), std::string::npos);
  o = CatchOptions{};
  o.catch_extra_mm = 5.0;
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("--catch-extra-mm = 5: must be in [0, 4]"), std::string::npos);
}

}  // namespace
}  // namespace tactip
