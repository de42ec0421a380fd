// The dataset writer as the last line of defence: a run whose arrays hold a non-finite value
// (an infinite pixel position, a NaN force) is refused with a message naming the array, the
// frame and the pin, and nothing of it reaches a file.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "input_error.h"
#include "sensors/dataset.h"
#include "temp_dir.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

class DatasetFiniteTest : public ::testing::Test {
 protected:
  tactip::testing::TestTempDir temp_{"dataset_finite"};
  std::string Path(const std::string& name) const { return temp_.File(name); }
  bool Empty() const { return fs::directory_iterator(temp_.path()) == fs::directory_iterator(); }
};

DatasetHeader Header() {
  DatasetHeader h;
  h.tactip_version = "0.1.0";
  h.scenario = "rail";
  h.config_yaml = "rail: {}\n";
  return h;
}

// A finite run of `t` frames of `n` pins, with an external camera.
RunRecord FiniteRun(int index, int t, int n) {
  RunRecord r;
  r.index = index;
  SensorRecord& s = r.sensors.emplace_back();
  s.n_pins = n;
  const auto tn = static_cast<size_t>(t) * static_cast<size_t>(n);
  for (int i = 0; i < t; ++i) {
    r.time.push_back(0.01 * i);
    s.gross_slip.push_back(0);
    s.incipient.push_back(0);
    r.object_height_m.push_back(0.1);
  }
  s.pos_px.assign(2 * tn, 320.0f);
  s.external_px.assign(2 * tn, 240.0f);
  s.pos_m.assign(3 * tn, 0.01f);
  s.external_m.assign(3 * tn, 0.02f);
  s.tangential_N.assign(2 * tn, 0.0f);
  s.normal_N.assign(tn, 0.1f);
  s.valid.assign(tn, 1);
  s.pin_slip.assign(tn, 0);
  s.pin_contact.assign(tn, 1);
  r.actions.actuators = {"servo_x", "servo_z"};
  r.actions.controls.assign(2 * static_cast<size_t>(t), 0.001);
  r.actions.list = {{0.02, "stop"}};
  r.attrs["object_fall_s"] = std::numeric_limits<double>::quiet_NaN();  // "did not happen": kept
  return r;
}

TEST_F(DatasetFiniteTest, ANonFiniteArrayValueIsRefusedNamingArrayFrameAndPinAndNothingIsLeft) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Case {
    const char* what;
    void (*spoil)(RunRecord&, float, float);
    std::string message;
  } cases[] = {
      {"pos_px", [](RunRecord& r, float i, float) { r.sensors[0].pos_px[2 * (2 * 3 + 1) + 1] = i; },
       "/runs/run_0007/sensors/tactip/pins/pos_px would hold a non-finite value (frame 2, pin 1); the run is not "
       "written"},
      {"external_px", [](RunRecord& r, float i, float) { r.sensors[0].external_px[0] = -i; },
       "/runs/run_0007/sensors/tactip/external/pos_px would hold a non-finite value (frame 0, pin 0); the run is not "
       "written"},
      {"normal_N", [](RunRecord& r, float, float n) { r.sensors[0].normal_N[3 * 3 + 2] = n; },
       "/runs/run_0007/sensors/tactip/contact/normal_N would hold a non-finite value (frame 3, pin 2); the run is not "
       "written"},
      {"height", [](RunRecord& r, float i, float) { r.object_height_m[4] = i; },
       "/runs/run_0007/object/height_m would hold a non-finite value (frame 4); the run is not written"},
      {"controls", [](RunRecord& r, float, float n) { r.actions.controls[2 * 3 + 1] = n; },
       "/runs/run_0007/actions/controls would hold a non-finite value (frame 3); the run is not written"},
      {"action time", [](RunRecord& r, float i, float) { r.actions.list[0].time_s = i; },
       "/runs/run_0007/actions/time would hold a non-finite value (action 0); the run is not written"},
      {"first slip", [](RunRecord& r, float i, float n) { r.sensors[0].pin_first_slip_s = {n, n, i}; },
       "/runs/run_0007/sensors/tactip/labels/pin_first_slip_s would hold a non-finite value (pin 2); the run is not "
       "written"},
  };
  for (const Case& c : cases) {
    const std::string path = Path("x.h5");
    {
      DatasetWriter w(path, Header());
      w.WriteRun(FiniteRun(6, 5, 3));  // a good run first: the bad one must not take it along either
      RunRecord bad = FiniteRun(7, 5, 3);
      c.spoil(bad, inf, nan);
      EXPECT_EQ(InputErrorOf([&] { w.WriteRun(bad); }), "cannot write dataset '" + path + "': " + c.message)
          << c.what;
      // The writer is dropped uncommitted, as a failed generation drops it.
    }
    EXPECT_TRUE(Empty()) << c.what << ": a file was left behind";
  }
}

TEST_F(DatasetFiniteTest, FiniteRunsWithNaNAttributesAreWritten) {
  const std::string path = Path("ok.h5");
  {
    DatasetWriter w(path, Header());
    w.WriteRun(FiniteRun(0, 5, 3));
    w.Commit();
  }
  DatasetReader r(path);
  ASSERT_EQ(r.run_indices(), std::vector<int>{0});
  EXPECT_TRUE(std::isnan(r.ReadRunSummary(0).attrs.at("object_fall_s")));
}

}  // namespace
}  // namespace tactip
