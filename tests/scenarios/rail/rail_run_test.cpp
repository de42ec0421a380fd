// The rail run as a steppable loop with a controller in it.

#include "scenarios/rail/rail_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace tactip {
namespace {

// A short rail run: 20 mm lift, fast retraction.
RailScenarioConfig Short() {
  RailScenarioConfig c;
  c.rail.lift_mm = 20.0;
  c.rail.retract_speed_mm_s = 5.0;
  return c;
}

// Counts frames and keeps the arm pressed (never retracts) once it has seen `hold_after` frames.
class CountingController : public RailController {
 public:
  explicit CountingController(const RailSchedule& s) : schedule_(s) {}
  ArmTargets Targets(double t) override {
    if (t < schedule_.retract_start) return {schedule_.X(t), schedule_.Z(t)};
    return {schedule_.X(schedule_.retract_start), schedule_.Z(t)};
  }
  void OnFrame(const FrameInput& in) override {
    ++frames;
    n_pins = in.frames.at(0)->size();
    last_time_s = in.time_s;
  }
  bool Done(double t) const override { return t > schedule_.retract_start + 0.5; }
  int frames = 0, n_pins = 0;
  double last_time_s = -1.0;

 private:
  RailSchedule schedule_;
};

// Follows the schedule, remembers the targets in force at each frame, and reports one action.
class TargetsRecordingController : public RailController {
 public:
  explicit TargetsRecordingController(const RailSchedule& s) : schedule_(s) {}
  ArmTargets Targets(double t) override {
    last_ = {schedule_.X(t), schedule_.Z(t)};
    return last_;
  }
  void OnFrame(const FrameInput&) override {
    at_frames.push_back(last_.x_m);
    at_frames.push_back(last_.z_m);
  }
  bool Done(double t) const override { return t > schedule_.lift_end; }
  std::vector<ControllerAction> Actions() const override { return {{schedule_.lift_start, "lift"}}; }
  std::vector<double> at_frames;  // (T, 2): x, z at each frame

 private:
  RailSchedule schedule_;
  ArmTargets last_;
};

TEST(RailRunTest, TheRecordHoldsOneSensorTheServoTargetsAtEachFrameAndTheControllersActions) {
  const RailScenarioConfig c = Short();
  const RailScene ids(c, SceneOptions{});
  const RailSchedule schedule(c.rail, c.rail.press_depth_mm * 1e-3, c.rail.retract_speed_mm_s);
  TargetsRecordingController controller(schedule);
  RunRecord rec;
  RailRun(c, ids, 0, 5, controller).Execute(rec, nullptr);
  ASSERT_EQ(rec.sensors.size(), 1u);
  EXPECT_EQ(rec.sensors[0].name, "tactip");
  EXPECT_EQ(rec.sensors[0].n_pins, ids.scene.built.n_pins);
  EXPECT_EQ(rec.sensors[0].text_attrs.at("skin_pattern"), c.skin.pattern);
  EXPECT_EQ(rec.actions.actuators, (std::vector<std::string>{"servo_x", "servo_z"}));
  ASSERT_EQ(rec.actions.controls.size(), 2 * rec.frames());
  EXPECT_EQ(rec.actions.controls, controller.at_frames);
  EXPECT_GT(rec.actions.controls[2 * (rec.frames() - 1) + 1], 0.0);  // lifted by the end
  ASSERT_EQ(rec.actions.list.size(), 1u);
  EXPECT_EQ(rec.actions.list[0].what, "lift");
  EXPECT_EQ(rec.actions.list[0].time_s, schedule.lift_start);
}

TEST(RailRunTest, SteppingByHandRecordsWhatExecuteRecords) {
  const RailScenarioConfig c = Short();
  const RailScene ids(c, SceneOptions{});
  RunRecord whole, stepped;
  RailRun a(c, ids, 3, 11);
  const RailRunSummary sa = a.Execute(whole, nullptr);
  RailRun b(c, ids, 3, 11);
  int steps = 0;
  while (b.Step(stepped)) ++steps;
  const RailRunSummary sb = b.Finish(stepped);
  EXPECT_EQ(steps, sa.steps);
  EXPECT_EQ(stepped.time, whole.time);
  EXPECT_EQ(stepped.sensors[0].pos_px, whole.sensors[0].pos_px);
  EXPECT_EQ(stepped.sensors[0].pin_slip, whole.sensors[0].pin_slip);
  EXPECT_EQ(stepped.actions.controls, whole.actions.controls);
  EXPECT_EQ(sb.gross_slip_onset_s, sa.gross_slip_onset_s);
  EXPECT_FALSE(std::isnan(sa.gross_slip_onset_s));  // the object does slip at 5 mm/s
}

TEST(RailRunTest, AControllerSeesEveryFrameAndItsTargetsDriveTheArm) {
  const RailScenarioConfig c = Short();
  const RailScene ids(c, SceneOptions{});
  const RailSchedule schedule(c.rail, c.rail.press_depth_mm * 1e-3, c.rail.retract_speed_mm_s);
  CountingController controller(schedule);
  RunRecord rec;
  // No depth jitter draw matters here: the controller holds whatever depth the run pressed.
  RailRun run(c, ids, 0, 5, controller);
  const RailRunSummary s = run.Execute(rec, nullptr);
  EXPECT_EQ(controller.frames, static_cast<int>(rec.frames()));
  EXPECT_EQ(controller.n_pins, ids.scene.built.n_pins);
  EXPECT_EQ(controller.last_time_s, rec.time.back());
  // It never retracted, so the object is still held when the controller ends the run.
  EXPECT_TRUE(std::isnan(s.gross_slip_onset_s));
  EXPECT_TRUE(std::isnan(s.object_fall_s));
  EXPECT_LT(rec.time.back(), schedule.retract_start + 0.6);
}

}  // namespace
}  // namespace tactip
