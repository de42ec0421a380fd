// Test support: synthetic run records (every value distinct where possible) and a
// field-by-field comparison of two records.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "sensors/dataset.h"

namespace tactip {

/// Recording of sensor `name` over `t` frames of `n` pins; `salt` shifts every value so
/// two sensors differ. With `external`, the external camera's arrays too.
inline SensorRecord MakeSensor(const std::string& name, int t, int n, float salt = 0.0f, bool external = false) {
  SensorRecord s;
  s.name = name;
  s.n_pins = n;
  const auto tn = static_cast<size_t>(t * n);
  for (int i = 0; i < t; ++i) {
    s.gross_slip.push_back(static_cast<std::uint8_t>(i % 2));
    s.incipient.push_back(static_cast<std::uint8_t>(i % 3 == 1));
  }
  for (size_t k = 0; k < tn * 2; ++k) s.pos_px.push_back(100.25f + 0.5f * static_cast<float>(k) + salt);
  for (size_t k = 0; k < tn * 3; ++k) s.pos_m.push_back(1e-3f * static_cast<float>(k) - 0.004f + salt);
  for (size_t k = 0; k < tn * 2; ++k) s.tangential_N.push_back(-0.01f * static_cast<float>(k) - salt);
  for (size_t k = 0; k < tn; ++k) {
    s.valid.push_back(k % 5 == 0 ? 0 : 1);
    s.pin_slip.push_back(k % 3 == 0 ? 1 : 0);
    s.pin_contact.push_back(k % 2 == 0 ? 1 : 0);
    s.normal_N.push_back(0.02f * static_cast<float>(k) + salt);
  }
  // First slips: every other pin never slipped (NaN).
  for (int i = 0; i < n; ++i) {
    s.pin_first_slip_s.push_back(i % 2 == 0 ? 0.5 + 0.01 * i + salt : std::numeric_limits<double>::quiet_NaN());
  }
  if (external) {
    for (size_t k = 0; k < tn * 2; ++k) s.external_px.push_back(200.5f + 0.25f * static_cast<float>(k) + salt);
    for (size_t k = 0; k < tn * 3; ++k) s.external_m.push_back(2e-3f * static_cast<float>(k) + salt);
  }
  return s;
}

/// Synthetic run with `t` frames of one sensor "tactip" with `n` pins, the arm's two
/// controls and two controller actions.
inline RunRecord MakeRun(int index, int t, int n) {
  RunRecord r;
  r.index = index;
  for (int i = 0; i < t; ++i) {
    r.time.push_back(0.01 * i + index);
    r.object_height_m.push_back(0.1 - 1e-4 * i);
    r.actions.controls.push_back(1e-4 * i);
    r.actions.controls.push_back(-2e-4 * i);
  }
  r.sensors.push_back(MakeSensor("tactip", t, n));
  r.sensors[0].text_attrs["skin_pattern"] = "smooth";
  r.actions.actuators = {"servo_x", "servo_z"};
  r.actions.list = {{index + 0.015, "slip_declared"}, {index + 0.02, "stop ✓"}};
  r.attrs["friction_coefficient"] = 0.6;
  r.attrs["gross_slip_onset_s"] = 0.123456789;
  r.attrs["object_fall_s"] = std::numeric_limits<double>::quiet_NaN();
  r.text_attrs["stimulus"] = "flat";
  r.text_attrs["comment"] = "";
  return r;
}

/// Numeric attributes equal, NaN ("did not happen") equal to NaN.
inline void ExpectSameAttrs(const std::map<std::string, double>& a, const std::map<std::string, double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [key, value] : a) {
    SCOPED_TRACE(key);
    ASSERT_EQ(b.count(key), 1u);
    if (std::isnan(value)) {
      EXPECT_TRUE(std::isnan(b.at(key)));
    } else {
      EXPECT_EQ(b.at(key), value);
    }
  }
}

/// Equal element by element, NaN equal to NaN.
inline void ExpectSameTimes(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i])) {
      EXPECT_TRUE(std::isnan(b[i])) << "element " << i;
    } else {
      EXPECT_EQ(a[i], b[i]) << "element " << i;
    }
  }
}

/// Every field of `a` and `b` equal, sensor by sensor in order.
inline void ExpectSameRun(const RunRecord& a, const RunRecord& b) {
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.object_height_m, b.object_height_m);
  ExpectSameAttrs(a.attrs, b.attrs);
  EXPECT_EQ(a.text_attrs, b.text_attrs);
  EXPECT_EQ(a.actions.actuators, b.actions.actuators);
  EXPECT_EQ(a.actions.controls, b.actions.controls);
  ASSERT_EQ(a.actions.list.size(), b.actions.list.size());
  for (size_t k = 0; k < a.actions.list.size(); ++k) {
    EXPECT_EQ(a.actions.list[k].time_s, b.actions.list[k].time_s);
    EXPECT_EQ(a.actions.list[k].what, b.actions.list[k].what);
  }
  ASSERT_EQ(a.sensors.size(), b.sensors.size());
  for (size_t k = 0; k < a.sensors.size(); ++k) {
    const SensorRecord &x = a.sensors[k], &y = b.sensors[k];
    SCOPED_TRACE("sensor " + x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.n_pins, y.n_pins);
    EXPECT_EQ(x.pos_px, y.pos_px);
    EXPECT_EQ(x.valid, y.valid);
    EXPECT_EQ(x.pos_m, y.pos_m);
    EXPECT_EQ(x.gross_slip, y.gross_slip);
    EXPECT_EQ(x.pin_slip, y.pin_slip);
    EXPECT_EQ(x.pin_contact, y.pin_contact);
    EXPECT_EQ(x.incipient, y.incipient);
    ExpectSameTimes(x.pin_first_slip_s, y.pin_first_slip_s);
    EXPECT_EQ(x.external_px, y.external_px);
    EXPECT_EQ(x.external_m, y.external_m);
    EXPECT_EQ(x.normal_N, y.normal_N);
    EXPECT_EQ(x.tangential_N, y.tangential_N);
    ExpectSameAttrs(x.attrs, y.attrs);
    EXPECT_EQ(x.text_attrs, y.text_attrs);
  }
}

}  // namespace tactip
