// The checks a run read from a dataset file must pass: frames, frame times, finite values.

#include "sensors/run_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "input_error.h"
#include "sim/base/nan.h"

namespace tactip {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Three frames of sensor "tactip" with two pins and the arm's two controls, every value
/// finite.
RunRecord GoodRun() {
  RunRecord r;
  r.index = 5;
  SensorRecord& s = r.sensors.emplace_back();
  s.n_pins = 2;
  r.time = {0.0, 0.01, 0.02};
  s.pos_px.assign(12, 1.5f);
  s.valid.assign(6, 1);
  s.pos_m.assign(18, 0.01f);
  s.normal_N.assign(6, 0.5f);
  s.tangential_N.assign(12, 0.1f);
  r.object_height_m = {0.05, 0.049, 0.048};
  r.actions.actuators = {"servo_x", "servo_z"};
  r.actions.controls.assign(6, 0.001);
  r.actions.list = {{0.01, "stop"}};
  return r;
}

/// GoodRun() with a second sensor "left" of three pins after "tactip".
RunRecord TwoSensorRun() {
  RunRecord r = GoodRun();
  SensorRecord& s = r.sensors.emplace_back();
  s.name = "left";
  s.n_pins = 3;
  s.pos_px.assign(18, 2.5f);
  s.valid.assign(9, 1);
  s.pos_m.assign(27, 0.02f);
  s.normal_N.assign(9, 0.25f);
  s.tangential_N.assign(18, 0.05f);
  return r;
}

const std::string kSource = "dataset 'd.h5'";

std::string TimesError(const RunRecord& r) {
  return InputErrorOf([&] { CheckRunTimes(r, kSource); });
}
std::string ValuesError(const RunRecord& r, int layout_version = kDatasetLayoutVersion) {
  return InputErrorOf([&] { CheckRunValues(r, kSource, layout_version); });
}

TEST(RunChecksTest, AGoodRunPasses) {
  EXPECT_EQ(TimesError(GoodRun()), "");
  EXPECT_EQ(ValuesError(GoodRun()), "");
  RunRecord one = GoodRun();
  one.time = {0.5};  // one frame: nothing to compare
  EXPECT_EQ(TimesError(one), "");
}

TEST(RunChecksTest, FrameTimesMustExistBeFiniteAndIncrease) {
  const struct {
    std::vector<double> time;
    std::string message;
  } cases[] = {
      {{}, "dataset 'd.h5': run_0005/time has no frames (a run needs at least one)"},
      {{0.0, kNaN, 0.02}, "dataset 'd.h5': run_0005/time is nan at frame 1 (must be a finite number)"},
      {{kNaN, kNaN, kNaN}, "dataset 'd.h5': run_0005/time is nan at frame 0 (must be a finite number)"},
      {{0.0, 0.01, kInf}, "dataset 'd.h5': run_0005/time is inf at frame 2 (must be a finite number)"},
      {{0.0, 0.02, 0.01},
       "dataset 'd.h5': run_0005/time is not increasing: frame 2 at 0.01 s is not after frame 1 at 0.02 s"},
      {{0.25, 0.25, 0.25},
       "dataset 'd.h5': run_0005/time is not increasing: frame 1 at 0.25 s is not after frame 0 at 0.25 s"},
  };
  for (const auto& c : cases) {
    RunRecord r = GoodRun();
    r.time = c.time;
    EXPECT_EQ(TimesError(r), c.message);
  }
}

TEST(RunChecksTest, ArraysMustBeFiniteAndFlagsZeroOrOne) {
  const float nan_f = std::numeric_limits<float>::quiet_NaN();
  const float inf_f = std::numeric_limits<float>::infinity();
  struct Case {
    void (*edit)(RunRecord&, float, float);
    std::string message;
  };
  const Case cases[] = {
      // pos_px (T, N, 2): value 7 is frame 1, pin 1, v.
      {[](RunRecord& r, float nan, float) { r.sensors[0].pos_px[7] = nan; },
       "dataset 'd.h5': run_0005/sensors/tactip/pins/pos_px is nan at frame 1, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float, float inf) { r.sensors[0].pos_px[0] = -inf; },
       "dataset 'd.h5': run_0005/sensors/tactip/pins/pos_px is -inf at frame 0, pin 0 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) { r.sensors[0].pos_m[17] = nan; },
       "dataset 'd.h5': run_0005/sensors/tactip/pins/pos_m is nan at frame 2, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float, float inf) { r.sensors[0].normal_N[3] = inf; },
       "dataset 'd.h5': run_0005/sensors/tactip/contact/normal_N is inf at frame 1, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) { r.sensors[0].tangential_N[4] = nan; },
       "dataset 'd.h5': run_0005/sensors/tactip/contact/tangential_N is nan at frame 1, pin 0 (must be a finite "
       "number)"},
      {[](RunRecord& r, float nan, float) { r.object_height_m[2] = nan; },
       "dataset 'd.h5': run_0005/object/height_m is nan at frame 2 (must be a finite number)"},
      {[](RunRecord& r, float nan, float) {
         r.sensors[0].external_px.assign(12, 0.0f);
         r.sensors[0].external_px[5] = nan;
       },
       "dataset 'd.h5': run_0005/sensors/tactip/external/pos_px is nan at frame 1, pin 0 (must be a finite number)"},
      {[](RunRecord& r, float, float inf) {
         r.sensors[0].external_m.assign(18, 0.0f);
         r.sensors[0].external_m[3] = inf;
       },
       "dataset 'd.h5': run_0005/sensors/tactip/external/pos_m is inf at frame 0, pin 1 (must be a finite number)"},
      {[](RunRecord& r, float, float) { r.sensors[0].valid[4] = 2; },
       "dataset 'd.h5': run_0005/sensors/tactip/pins/valid is 2 at frame 2, pin 0 (must be 0 or 1)"},
      // The controls (T, U): value 3 is frame 1, actuator servo_z; the action times (A).
      {[](RunRecord& r, float nan, float) { r.actions.controls[3] = nan; },
       "dataset 'd.h5': run_0005/actions/controls is nan at frame 1, actuator servo_z (must be a finite number)"},
      {[](RunRecord& r, float, float inf) { r.actions.list[0].time_s = inf; },
       "dataset 'd.h5': run_0005/actions/time is inf at action 0 (must be a finite number)"},
  };
  for (const auto& c : cases) {
    RunRecord r = GoodRun();
    c.edit(r, nan_f, inf_f);
    EXPECT_EQ(ValuesError(r), c.message);
  }
}

TEST(RunChecksTest, EachSensorIsCheckedAndNamedByItsPathInTheFile) {
  // Value 10 of the second sensor's pos_px (T, 3, 2): frame 1, pin 2, u.
  RunRecord two = TwoSensorRun();
  EXPECT_EQ(ValuesError(two), "");
  two.sensors[1].pos_px[10] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(ValuesError(two), "dataset 'd.h5': run_0005/sensors/left/pins/pos_px is nan at frame 1, pin 2 (must be a "
                              "finite number)");
  two = TwoSensorRun();
  two.sensors[1].valid[8] = 3;
  EXPECT_EQ(ValuesError(two),
            "dataset 'd.h5': run_0005/sensors/left/pins/valid is 3 at frame 2, pin 2 (must be 0 or 1)");
}

TEST(RunChecksTest, ALayoutOneRunNamesTheArraysUnderTheRun) {
  RunRecord r = GoodRun();
  r.sensors[0].normal_N[3] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(ValuesError(r, 1), "dataset 'd.h5': run_0005/contact/normal_N is inf at frame 1, pin 1 (must be a finite "
                               "number)");
}

}  // namespace
}  // namespace tactip
