// The recorder: frames of several sensors' readings become one record in the dataset's
// layout, each sensor's arrays in its own group, frame after frame.

#include "sensors/run_recorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace tactip {
namespace {

// A reading of `n` pins whose every value is `v` (labels: pin 0 in contact, slipping when `slip`).
SensorReading Reading(int n, float v, bool slip, bool external) {
  const size_t pins = static_cast<size_t>(n);
  SensorReading r;
  r.pos_m.assign(3 * pins, v);
  r.pos_px.assign(2 * pins, v);
  r.valid.assign(pins, 1);
  if (external) {
    r.external_m.assign(3 * pins, -v);
    r.external_px.assign(2 * pins, -v);
  }
  r.normal_N.assign(pins, v);
  r.tangential_N.assign(2 * pins, v);
  r.pin_contact.assign(pins, 0);
  r.pin_slip.assign(pins, 0);
  r.pin_contact[0] = 1;
  r.pin_slip[0] = slip ? 1 : 0;
  r.incipient = 0;
  return r;
}

TEST(RunRecorderTest, FramesOfTwoSensorsFillOneGroupEachInFrameOrder) {
  RunRecord rec;
  rec.index = 99;
  rec.attrs["stale"] = 1.0;
  RunRecorder recorder(rec, 4, {{"left", 3}, {"right", 2}}, {"servo_x", "servo_z"}, 10);
  EXPECT_EQ(rec.index, 4);
  EXPECT_TRUE(rec.attrs.empty()) << "a new record starts empty";
  for (int f = 0; f < 3; ++f) {
    const float v = static_cast<float>(f);
    const SensorReading left = Reading(3, v, f == 2, true), right = Reading(2, 10.0f + v, false, true);
    recorder.Frame(0.01 * f, {&left, &right}, f == 2 ? 1 : 0, 0.001 * f, {1.0 + f, 2.0 + f});
  }
  EXPECT_EQ(rec.time, (std::vector<double>{0.0, 0.01, 0.02}));
  EXPECT_EQ(rec.object_height_m, (std::vector<double>{0.0, 0.001, 0.002}));
  EXPECT_EQ(rec.actions.actuators, (std::vector<std::string>{"servo_x", "servo_z"}));
  EXPECT_EQ(rec.actions.controls, (std::vector<double>{1, 2, 2, 3, 3, 4}));
  ASSERT_EQ(rec.sensors.size(), 2u);
  const SensorRecord& left = rec.sensors[0];
  const SensorRecord& right = rec.sensors[1];
  EXPECT_EQ(left.name, "left");
  EXPECT_EQ(right.n_pins, 2);
  // Frame f of the left sensor's (T,N,2) positions holds f; the right's 10 + f.
  ASSERT_EQ(left.pos_px.size(), 3u * 3 * 2);
  EXPECT_EQ(left.pos_px[2 * 3 * 2], 2.0f);
  EXPECT_EQ(right.pos_px[1 * 2 * 2], 11.0f);
  EXPECT_EQ(left.external_m[3 * 3 * 1], -1.0f);
  EXPECT_EQ(left.pin_slip, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(left.gross_slip, (std::vector<std::uint8_t>{0, 0, 1}));
  EXPECT_EQ(right.gross_slip, left.gross_slip) << "gross slip is the object's";
  EXPECT_NO_THROW(rec.CheckShapes());
}

TEST(RunRecorderTest, AReadingOrControlsThatDoNotFitTheRecordAreAProgrammingError) {
  RunRecord rec;
  RunRecorder recorder(rec, 0, {{"tactip", 3}}, {"servo_x"}, 1);
  const SensorReading three = Reading(3, 1.0f, false, false), two = Reading(2, 1.0f, false, false);
  EXPECT_THROW(recorder.Frame(0.0, {&two}, 0, 0.0, {0.0}), std::logic_error);
  EXPECT_THROW(recorder.Frame(0.0, {&three, &three}, 0, 0.0, {0.0}), std::logic_error);
  EXPECT_THROW(recorder.Frame(0.0, {&three}, 0, 0.0, {0.0, 1.0}), std::logic_error);
  recorder.Frame(0.0, {&three}, 0, 0.0, {0.0});
  EXPECT_EQ(rec.time.size(), 1u);
  EXPECT_NO_THROW(rec.CheckShapes());
  // First slips: one per pin of an existing sensor, or nothing is recorded.
  EXPECT_THROW(recorder.FirstSlips(0, {0.1, 0.2}), std::logic_error);
  EXPECT_THROW(recorder.FirstSlips(1, {0.1, 0.2, 0.3}), std::logic_error);
  EXPECT_TRUE(rec.sensors[0].pin_first_slip_s.empty());
  recorder.FirstSlips(0, {0.1, std::nan(""), 0.3});
  EXPECT_EQ(rec.sensors[0].pin_first_slip_s.size(), 3u);
  EXPECT_NO_THROW(rec.CheckShapes());
  rec.sensors[0].pin_first_slip_s.pop_back();
  EXPECT_THROW(rec.CheckShapes(), std::logic_error);  // not one per pin
}

}  // namespace
}  // namespace tactip
