// The online incipient stop: step-wise retraction, the stop, and the scoring.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scenarios/incipient_stop/stop_trials.h"
#include "sim/base/nan.h"
#include "tests/input_error.h"

namespace tactip {
namespace {

RailRunSummary Summary(double stop_s, double onset_s, double fall_s) {
  RailRunSummary s;
  if (!std::isnan(stop_s)) s.actions = {{stop_s, "stop"}};
  s.gross_slip_onset_s = onset_s;
  s.object_fall_s = fall_s;
  s.incipient_onset_s = kNaN;
  return s;
}

TEST(ScoreStopTrialTest, StoppedHeldStoppedLateAndMissed) {
  const StopTrial held = ScoreStopTrial(Summary(5.0, kNaN, kNaN), 0);
  EXPECT_EQ(held.outcome, StopOutcome::kStopped);
  EXPECT_TRUE(held.before_gross);
  const StopTrial late = ScoreStopTrial(Summary(5.0, 5.5, 5.6), 1);
  EXPECT_EQ(late.outcome, StopOutcome::kStoppedLate);
  EXPECT_TRUE(late.before_gross);
  EXPECT_NEAR(late.lead_s, 0.5, 1e-12);
  const StopTrial missed = ScoreStopTrial(Summary(5.7, 5.5, 5.6), 2);
  EXPECT_EQ(missed.outcome, StopOutcome::kMissed);
  EXPECT_FALSE(missed.before_gross);
  EXPECT_EQ(ScoreStopTrial(Summary(kNaN, 5.5, 5.6), 3).outcome, StopOutcome::kMissed);
}

TEST(FormatStopTableTest, MeanLeadCountsOnlyTheStopsBeforeAnOnsetThatCame) {
  // Two trials held to the end (no onset, no lead) and one stopped 0.5 s before an onset.
  std::vector<StopTrial> trials = {ScoreStopTrial(Summary(5.0, kNaN, kNaN), 0),
                                   ScoreStopTrial(Summary(5.0, kNaN, kNaN), 1),
                                   ScoreStopTrial(Summary(5.0, 5.5, 5.6), 2)};
  for (StopTrial& t : trials) t.skin = "fingerprint-v2";
  const std::string table = FormatStopTable(trials);
  EXPECT_NE(table.find("fingerprint-v2         3         2 ( 67%)             3 (100%)     0.50 s"), std::string::npos)
      << table;
  // Every object held: no lead to average.
  trials.pop_back();
  EXPECT_NE(FormatStopTable(trials).find("2 (100%)        - s"), std::string::npos) << FormatStopTable(trials);
}

TEST(StopControllerTest, RetractsInStepsWithPausesAndHoldsOnceStopped) {
  RailConfig rail;
  rail.retract_speed_mm_s = 1.0;
  const RailSchedule schedule(rail, 3e-3, rail.retract_speed_mm_s);
  StopOptions o;
  o.step_mm = 0.2;
  o.pause_s = 0.3;
  StopController c(schedule, o);
  const double t0 = schedule.retract_start, move = 0.2;  // 0.2 mm at 1 mm/s
  EXPECT_NEAR(c.Targets(t0).x_m, schedule.press_dist, 1e-12);
  EXPECT_NEAR(c.Targets(t0 + move).x_m, schedule.press_dist - 0.2e-3, 1e-12);
  // Still through the pause, then the next step.
  EXPECT_NEAR(c.Targets(t0 + move + 0.29).x_m, schedule.press_dist - 0.2e-3, 1e-12);
  EXPECT_NEAR(c.Targets(t0 + 2 * (move + 0.3)).x_m, schedule.press_dist - 0.4e-3, 1e-12);
  // A slower retraction than the constant-speed protocol's: the run may last longer.
  EXPECT_GT(c.GiveUpTime(schedule), schedule.give_up);
  EXPECT_FALSE(c.Done(1e9));  // never stopped: the run decides when it ends
}

TEST(StopOptionsTest, EveryRefusalNamesTheOption) {
  StopOptions o;
  o.step_mm = 0.0;
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("--step-mm = 0: must be in [0.01, 2]"), std::string::npos);
  o = StopOptions{};
  o.markers = "both";
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("--markers 'both'"), std::string::npos);
  o = StopOptions{};
  o.detector.window = 0;
  EXPECT_NE(InputErrorOf([&] { o.Validate(); }).find("window = 0"), std::string::npos);
  o = StopOptions{};
  o.markers = "external";
  RailScenarioConfig no_external;
  StopTrialOptions t;
  t.loop = o;
  EXPECT_NE(InputErrorOf([&] { RunStopTrials(no_external, t); }).find("no external camera"), std::string::npos);
}

TEST(IncipientStopTest, AHairTriggerStopsTheArmBeforeSlipAndTheObjectStaysHeld) {
  // The smooth skin on the rail (fast to simulate): a detector that fires on noise stops
  // the arm at the first frames of the retraction, long before the grip can fail.
  RailScenarioConfig cfg;
  cfg.rail.lift_mm = 10.0;
  cfg.rail.retract_speed_mm_s = 2.0;
  StopTrialOptions o;
  o.loop.detector.speed_thr_px = 1e-6;
  o.loop.detector.count_thr = 1;
  o.loop.hold_s = 0.5;
  o.trials = 1;
  const std::vector<StopTrial> trials = RunStopTrials(cfg, o);
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].outcome, StopOutcome::kStopped);
  EXPECT_TRUE(std::isnan(trials[0].onset_s));
  EXPECT_TRUE(std::isnan(trials[0].fall_s));
}

TEST(IncipientStopTest, ADetectorThatNeverFiresMissesAndTheObjectFalls) {
  RailScenarioConfig cfg;
  cfg.rail.lift_mm = 10.0;
  cfg.rail.retract_speed_mm_s = 5.0;
  StopTrialOptions o;
  o.loop.detector.speed_thr_px = 1e6;
  o.loop.pause_s = 0.0;
  o.trials = 1;
  const std::vector<StopTrial> trials = RunStopTrials(cfg, o);
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].outcome, StopOutcome::kMissed);
  EXPECT_FALSE(std::isnan(trials[0].fall_s));
}

}  // namespace
}  // namespace tactip
