#include "sim/viewer_controls.h"

#include <gtest/gtest.h>

#include <string>

namespace tactip {
namespace {

constexpr double kDt = 0.001;  // physics step of the test source (s)

// A free-falling body stepped at kDt that finishes after `max_steps` steps.
class CountingSource : public ViewSource {
 public:
  explicit CountingSource(int max_steps) : max_steps_(max_steps) {}
  bool Step() override {
    if (steps >= max_steps_) return false;
    sim_.Step();
    ++steps;
    return true;
  }
  const Simulation& sim() const override { return sim_; }
  std::vector<GeomColour> Colours() const override { return {}; }
  double time() const override { return sim_.time(); }

  int steps = 0;

 private:
  int max_steps_;
  CompiledModel model_ = CompiledModel::FromXml(
      "<mujoco><option timestep='0.001'/><worldbody><body><freejoint/>"
      "<geom type='sphere' size='0.01'/></body></worldbody></mujoco>");
  Simulation sim_{model_};
};

TEST(ViewerControlsTest, RunningAdvancesBySimulatedTimeEqualToWallTime) {
  CountingSource source(1000);
  ViewerControls c;
  EXPECT_EQ(c.Advance(source, 0.02), 20);
  EXPECT_EQ(c.Advance(source, 0.01), 10);
  EXPECT_NEAR(source.time(), 0.03, 1e-9);
}

TEST(ViewerControlsTest, SlowMotionHalvesTheSimulatedTimePerFrame) {
  CountingSource source(1000);
  ViewerControls c;
  c.Apply(ViewerCommand::kSlower);
  c.Apply(ViewerCommand::kSlower);
  EXPECT_DOUBLE_EQ(c.speed(), 0.25);
  // 4 frames of 20 ms at a quarter of real time: 20 ms simulated in all.
  int steps = 0;
  for (int i = 0; i < 4; ++i) steps += c.Advance(source, 0.02);
  EXPECT_EQ(steps, 20);
}

TEST(ViewerControlsTest, SpeedStaysBetweenTheSlowestMotionAndRealTime) {
  ViewerControls c;
  c.Apply(ViewerCommand::kFaster);
  EXPECT_DOUBLE_EQ(c.speed(), 1.0);
  for (int i = 0; i < 20; ++i) c.Apply(ViewerCommand::kSlower);
  EXPECT_DOUBLE_EQ(c.speed(), ViewerControls::kMinSpeed);
  c.Apply(ViewerCommand::kFaster);
  EXPECT_DOUBLE_EQ(c.speed(), 2.0 * ViewerControls::kMinSpeed);
}

TEST(ViewerControlsTest, PausedStepsOnlyOnceForEachSingleStepRequest) {
  CountingSource source(1000);
  ViewerControls c;
  c.Apply(ViewerCommand::kPauseResume);
  EXPECT_EQ(c.Advance(source, 0.02), 0);
  c.Apply(ViewerCommand::kSingleStep);
  EXPECT_EQ(c.Advance(source, 0.02), 1);
  EXPECT_EQ(c.Advance(source, 0.02), 0);
  EXPECT_EQ(source.steps, 1);
}

TEST(ViewerControlsTest, SingleStepWhileRunningIsIgnored) {
  CountingSource source(1000);
  ViewerControls c;
  c.Apply(ViewerCommand::kSingleStep);
  c.Apply(ViewerCommand::kPauseResume);
  EXPECT_EQ(c.Advance(source, 0.02), 0);
}

TEST(ViewerControlsTest, ResumingDoesNotCatchUpOnThePausedTime) {
  CountingSource source(1000);
  ViewerControls c;
  c.Advance(source, 0.01);
  c.Apply(ViewerCommand::kPauseResume);
  for (int i = 0; i < 10; ++i) c.Advance(source, 0.02);
  c.Apply(ViewerCommand::kPauseResume);
  EXPECT_EQ(c.Advance(source, 0.01), 10);
}

TEST(ViewerControlsTest, ALongFrameCountsAsTheLongestFrame) {
  CountingSource source(100000);
  ViewerControls c;
  const int steps = c.Advance(source, 5.0);
  EXPECT_NEAR(steps * kDt, ViewerControls::kMaxFrameS, kDt);
}

TEST(ViewerControlsTest, AFinishedSourceIsNotSteppedAgain) {
  CountingSource source(5);
  ViewerControls c;
  EXPECT_EQ(c.Advance(source, 0.02), 5);
  EXPECT_TRUE(c.finished());
  c.Apply(ViewerCommand::kPauseResume);
  c.Apply(ViewerCommand::kSingleStep);
  EXPECT_EQ(c.Advance(source, 0.02), 0);
  EXPECT_EQ(source.steps, 5);
}

TEST(ViewerControlsTest, ForcesToggleAndQuit) {
  ViewerControls c;
  EXPECT_FALSE(c.show_forces());
  c.Apply(ViewerCommand::kToggleForces);
  EXPECT_TRUE(c.show_forces());
  c.Apply(ViewerCommand::kToggleForces);
  EXPECT_FALSE(c.show_forces());
  EXPECT_FALSE(c.quit());
  c.Apply(ViewerCommand::kQuit);
  EXPECT_TRUE(c.quit());
}

TEST(ViewerControlsTest, StatusNamesTimeSpeedAndState) {
  ViewerControls c;
  EXPECT_EQ(c.Status(1.5), "t = 1.500 s   real time");
  c.Apply(ViewerCommand::kSlower);
  c.Apply(ViewerCommand::kSlower);
  c.Apply(ViewerCommand::kToggleForces);
  c.Apply(ViewerCommand::kPauseResume);
  EXPECT_EQ(c.Status(0.25), "t = 0.250 s   1/4 of real time   forces  PAUSED (space: resume, right arrow: step)");
}

}  // namespace
}  // namespace tactip
