// Offline evaluation on hand-built runs with scripted decisions (every count is known), and
// the timing of decisions that take a known least time.

#include "detectors/metrics.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace tactip {
namespace {

constexpr double kTol = 1e-12;

/// Replays fixed decisions: run r (counted by Reset calls) declares slip in the listed frames.
class ScriptedDetector : public Detector {
 public:
  explicit ScriptedDetector(std::vector<std::vector<int>> slip_frames) : slip_frames_(std::move(slip_frames)) {}
  std::string name() const override { return "scripted"; }
  void Reset() override {
    ++run_;
    frame_ = 0;
  }
  Decision Update(const PinFrame&) override {
    Decision d;
    for (int k : slip_frames_.at(run_)) d.slip = d.slip || k == frame_;
    ++frame_;
    return d;
  }
  void Save(const std::string&) const override {}

 private:
  std::vector<std::vector<int>> slip_frames_;
  int run_ = -1;
  int frame_ = 0;
};

/// A run of `n` one-pin frames (contents do not matter to the scripted detector).
LabeledRun MakeRun(int index, int n, int first, int onset, double rate_hz) {
  LabeledRun r;
  r.run = index;
  r.first_frame = first;
  r.onset_frame = onset;
  r.frame_rate_hz = rate_hz;
  for (int k = 0; k < n; ++k) {
    PinFrame f;
    f.time_s = k / rate_hz;
    f.pos_px = Eigen::Matrix<float, Eigen::Dynamic, 2>::Zero(1, 2);
    f.valid = {1};
    r.frames.push_back(f);
  }
  return r;
}

TEST(ConfusionTest, RatiosAreZeroWhenUndefined) {
  const Confusion c;
  EXPECT_EQ(c.Precision(), 0.0);
  EXPECT_EQ(c.Recall(), 0.0);
  EXPECT_EQ(c.F1(), 0.0);
  EXPECT_EQ(c.Accuracy(), 0.0);
}

TEST(ConfusionTest, RatiosFollowTheirDefinitions) {
  const Confusion c{2, 3, 22, 6};
  EXPECT_NEAR(c.Precision(), 2.0 / 5.0, kTol);
  EXPECT_NEAR(c.Recall(), 2.0 / 8.0, kTol);
  EXPECT_NEAR(c.F1(), 4.0 / 13.0, kTol);
  EXPECT_NEAR(c.Accuracy(), 24.0 / 33.0, kTol);
  EXPECT_EQ(FormatConfusion(c), "TP 2 FP 3 TN 22 FN 6 | precision 0.4000 recall 0.2500 F1 0.3077 accuracy 0.7273");
}

TEST(EvaluateTest, HandBuiltRunsGiveExactCountsDelayAndFalsePositiveRate) {
  // Run 0 (100 Hz): scored static frames 2..11, slip frames 12..15; slip declared at 5 (FP),
  //   14, 15 (TP) and 17 (streamed, not scored). Detection 14: delay 2 frames = 20 ms.
  // Run 1 (50 Hz): no onset, all 10 frames static; slip at 3 and 4 (FP).
  // Run 2 (100 Hz): onset 5, never detected; frames 0..4 TN, 5..8 FN, 9 unscored.
  const std::vector<LabeledRun> runs = {MakeRun(0, 20, 2, 12, 100.0), MakeRun(1, 10, 0, -1, 50.0),
                                        MakeRun(2, 10, 0, 5, 100.0)};
  ScriptedDetector det({{5, 14, 15, 17}, {3, 4}, {}});
  const Evaluation ev = Evaluate(det, runs, 4);

  EXPECT_EQ(ev.detector, "scripted");
  EXPECT_EQ(ev.confusion.tp, 2);
  EXPECT_EQ(ev.confusion.fp, 3);
  EXPECT_EQ(ev.confusion.tn, 22);
  EXPECT_EQ(ev.confusion.fn, 6);
  EXPECT_EQ(ev.frames_scored, 33);
  EXPECT_NEAR(ev.confusion.F1(), 4.0 / 13.0, kTol);

  ASSERT_EQ(ev.runs.size(), 3u);
  const RunEvaluation& r0 = ev.runs[0];
  EXPECT_EQ(r0.run, 0);
  EXPECT_EQ(r0.onset_frame, 12);
  EXPECT_EQ(r0.detection_frame, 14);
  EXPECT_EQ(r0.delay_frames, 2.0);
  EXPECT_EQ(r0.static_frames, 10);
  EXPECT_EQ(r0.false_positive_frames, 1);
  EXPECT_EQ(r0.confusion.tp, 2);
  EXPECT_EQ(r0.confusion.fn, 2);
  EXPECT_EQ(ev.runs[1].detection_frame, -1);
  EXPECT_TRUE(std::isnan(ev.runs[1].delay_frames));
  EXPECT_EQ(ev.runs[1].static_frames, 10);
  EXPECT_EQ(ev.runs[1].false_positive_frames, 2);
  EXPECT_EQ(ev.runs[2].detection_frame, -1);
  EXPECT_TRUE(std::isnan(ev.runs[2].delay_frames));
  EXPECT_EQ(ev.runs[2].confusion.fn, 4);

  EXPECT_EQ(ev.delay_frames_mean, 2.0);
  EXPECT_NEAR(ev.delay_ms_mean, 20.0, kTol);
  EXPECT_NEAR(ev.detected_fraction, 0.5, kTol);
  // Static data: 10/100 + 10/50 + 5/100 s = 0.35 s; 3 false positives.
  EXPECT_NEAR(ev.fp_per_min, 3.0 / (0.35 / 60.0), 1e-9);
}

/// Takes at least 1 ms over every decision, and 20 ms more over the one in frame `slow_frame`.
class SlowDetector : public Detector {
 public:
  explicit SlowDetector(int slow_frame) : slow_frame_(slow_frame) {}
  std::string name() const override { return "slow"; }
  void Reset() override { frame_ = 0; }
  Decision Update(const PinFrame&) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(frame_ == slow_frame_ ? 21 : 1));
    ++frame_;
    return Decision{};
  }
  void Save(const std::string&) const override {}

 private:
  int slow_frame_;
  int frame_ = 0;
};

TEST(EvaluateTest, TimingIsTheWallTimeOfEachDecisionInMicroseconds) {
  // 50 decisions of >= 1 ms, one of them >= 21 ms: the mean is >= 1.4 ms, and the 99th
  // percentile (nearest rank: the 50th smallest of 50) is the slow one.
  const std::vector<LabeledRun> runs = {MakeRun(0, 50, 0, 30, 100.0)};
  SlowDetector det(17);
  const Evaluation ev = Evaluate(det, runs, 4);
  EXPECT_GE(ev.us_per_frame_mean, 1400.0);
  EXPECT_GE(ev.us_per_frame_p99, 21000.0);
}

TEST(EvaluateTest, DetectionIsSearchedToTheEndOfTheRun) {
  // Onset 3, scored slip frames 3..6 all missed; the first slip decision comes at frame 10.
  const std::vector<LabeledRun> runs = {MakeRun(0, 12, 0, 3, 100.0)};
  ScriptedDetector det({{1, 10}});
  const Evaluation ev = Evaluate(det, runs, 4);
  EXPECT_EQ(ev.runs[0].detection_frame, 10);
  EXPECT_EQ(ev.runs[0].delay_frames, 7.0);
  EXPECT_EQ(ev.confusion.fn, 4);
  EXPECT_EQ(ev.confusion.fp, 1);  // frame 1, before the onset
  EXPECT_NEAR(ev.delay_ms_mean, 70.0, kTol);
  EXPECT_NEAR(ev.detected_fraction, 1.0, kTol);
}

TEST(EvaluateTest, AggregatesWithoutDataAreNaN) {
  // One run without onset and without false positives: no delay, no detections to count.
  const std::vector<LabeledRun> runs = {MakeRun(0, 5, 0, -1, 100.0)};
  ScriptedDetector det(std::vector<std::vector<int>>(1));
  const Evaluation ev = Evaluate(det, runs, 4);
  EXPECT_TRUE(std::isnan(ev.delay_frames_mean));
  EXPECT_TRUE(std::isnan(ev.delay_ms_mean));
  EXPECT_TRUE(std::isnan(ev.detected_fraction));
  EXPECT_EQ(ev.fp_per_min, 0.0);
  EXPECT_EQ(ev.confusion.tn, 5);
}

TEST(EvaluateTest, RejectsBadSlipWindowAndFrameRate) {
  ScriptedDetector det(std::vector<std::vector<int>>(2));
  EXPECT_THROW(Evaluate(det, {MakeRun(0, 5, 0, 2, 100.0)}, 0), InputError);
  EXPECT_THROW(Evaluate(det, {MakeRun(0, 5, 0, 2, 0.0)}, 4), InputError);
}

}  // namespace
}  // namespace tactip
