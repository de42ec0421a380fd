// Datasets of several sensors on the command line: info lists every sensor, --sensor picks
// the one whose pins train, evaluate, detect, report and bench read, and an unknown name
// gets one line naming the sensors the dataset has.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "sensors/dataset.h"

namespace tactip {
namespace {

using testing::CliFolderTest;
using testing::CliResult;
using testing::Slurp;

namespace fs = std::filesystem;

constexpr int kSensorOptionFrames = 60;

/// Sensor `name` of `n` pins over kSensorOptionFrames frames: its pins stand still, or (with
/// `drift_px` > 0) move by that much per frame from frame 30 on.
SensorRecord Sensor(const std::string& name, int n, float drift_px) {
  SensorRecord s;
  s.name = name;
  s.n_pins = n;
  for (int f = 0; f < kSensorOptionFrames; ++f) {
    const float shift = f < 30 ? 0.0f : drift_px * static_cast<float>(f - 30);
    for (int i = 0; i < n; ++i) {
      s.pos_px.push_back(100.0f + 10.0f * static_cast<float>(i));
      s.pos_px.push_back(200.0f + shift);
    }
    s.gross_slip.push_back(f >= 30 ? 1 : 0);
    s.incipient.push_back(0);
  }
  const size_t tn = static_cast<size_t>(kSensorOptionFrames * n);
  s.valid.assign(tn, 1);
  s.pos_m.assign(3 * tn, 0.01f);
  s.pin_slip.assign(tn, 0);
  s.pin_contact.assign(tn, 1);
  s.normal_N.assign(tn, 0.5f);
  s.tangential_N.assign(2 * tn, 0.1f);
  return s;
}

/// A dataset of two runs, each with a still sensor "tactip" of two pins and a sensor
/// "left" of three pins that slips from frame 30 (0.3 s).
void WriteTwoSensorDataset(const std::string& path) {
  DatasetHeader h;
  h.tactip_version = "0.1.0";
  h.scenario = "rail";
  h.config_yaml = "rail: {}\n";
  DatasetWriter w(path, h);
  for (int index = 0; index < 2; ++index) {
    RunRecord r;
    r.index = index;
    for (int f = 0; f < kSensorOptionFrames; ++f) r.time.push_back(0.01 * f);
    r.object_height_m.assign(kSensorOptionFrames, 0.05);
    r.sensors = {Sensor("tactip", 2, 0.0f), Sensor("left", 3, 2.0f)};
    r.sensors[1].text_attrs["skin_pattern"] = "fingerprint-v2";
    r.attrs["retract_start_s"] = 0.1;
    r.attrs["gross_slip_onset_s"] = 0.3;
    w.WriteRun(r);
  }
  w.Commit();
}

class SensorOptionCliTest : public CliFolderTest {
 protected:
  void SetUp() override {
    CliFolderTest::SetUp();
    WriteTwoSensorDataset(P("d.h5"));
  }
};

TEST_F(SensorOptionCliTest, InfoListsEverySensorWithItsPins) {
  const CliResult r = Run("info " + P("d.h5"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("sensors      tactip: 2 pins; left: 3 pins, skin_pattern fingerprint-v2\n"), std::string::npos)
      << r.out;
}

TEST_F(SensorOptionCliTest, SensorPicksWhosePinsADetectorSees) {
  // The contact measure (mean pin displacement from the first frame) is 0 for the still
  // sensor, the default, and grows for "left".
  ASSERT_EQ(Run("detect incipient --data " + P("d.h5") + " --runs 0 --contact-measure --out " + P("a.csv")).code, 0);
  const CliResult left =
      Run("detect incipient --data " + P("d.h5") + " --runs 0 --sensor left --contact-measure --out " + P("b.csv"));
  ASSERT_EQ(left.code, 0) << left.err;
  const std::string a = Slurp(P("a.csv")), b = Slurp(P("b.csv"));
  const std::string last_a = a.substr(a.rfind(',') + 1), last_b = b.substr(b.rfind(',') + 1);
  EXPECT_EQ(last_a, "0\n") << a;
  EXPECT_EQ(last_b, "58\n") << b;  // frame 59: 29 frames of 2 px
  EXPECT_EQ(Run("detect incipient --data " + P("d.h5") + " --runs 0 --sensor tactip --contact-measure --out " +
                P("c.csv"))
                .code,
            0);
  EXPECT_EQ(Slurp(P("c.csv")), a);
  // Training reads the named sensor's pins too.
  const CliResult t = Run("train threshold --data " + P("d.h5") + " --sensor left --out " + P("left.model"));
  EXPECT_EQ(t.code, 0) << t.err;
  const CliResult e = Run("evaluate --model " + P("left.model") + " --data " + P("d.h5") + " --sensor left");
  EXPECT_EQ(e.code, 0) << e.err;
  const CliResult report = Run("report incipient " + P("d.h5") + " --sensor left");
  EXPECT_EQ(report.code, 0) << report.err;
  // The signatures of "left": its pins move 2 px/frame from frame 31, after the onset at frame 30.
  const CliResult signatures = Run("report signatures " + P("d.h5") + " --sensor left");
  EXPECT_EQ(signatures.code, 0) << signatures.err;
  EXPECT_NE(signatures.out.find("spike width, frames             29 [29, 29] (2 of 2 runs)"), std::string::npos)
      << signatures.out;
}

TEST_F(SensorOptionCliTest, AnUnknownSensorGetsOneLineNamingTheKnownOnesAndWritesNothing) {
  ASSERT_EQ(Run("train threshold --data " + P("d.h5") + " --sensor left --out " + P("t.model")).code, 0);
  const std::string expected = "tactip: --sensor 'right': dataset '" + P("d.h5") +
                               "' has no such sensor (its sensors: tactip, left)\n";
  const std::vector<std::string> commands = {
      "train threshold --data " + P("d.h5") + " --sensor right --out " + P("x.model"),
      "evaluate --model " + P("t.model") + " --data " + P("d.h5") + " --sensor right",
      "detect --model " + P("t.model") + " --data " + P("d.h5") + " --sensor right --out " + P("x.csv"),
      "detect incipient --data " + P("d.h5") + " --sensor right --out " + P("x.csv"),
      "report incipient " + P("d.h5") + " --sensor right --csv " + P("x.csv"),
      "report signatures " + P("d.h5") + " --sensor right --csv " + P("x.csv"),
      "bench --dataset " + P("d.h5") + " --sensor right --out " + P("bench"),
  };
  for (const std::string& args : commands) {
    const CliResult r = Run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, expected) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_FALSE(fs::exists(P("x.model")) || fs::exists(P("x.csv")) || fs::exists(P("bench"))) << args;
  }
}

TEST_F(SensorOptionCliTest, SensorIsRefusedWhereThereIsNoDatasetToPickFrom) {
  std::ofstream(P("rec.csv")) << "frame,time_s,pin,x_px,y_px\n0,0,0,1,2\n1,0.01,0,1,2\n";
  const CliResult csv = Run("detect incipient --data " + P("rec.csv") + " --sensor left --out " + P("x.csv"));
  EXPECT_EQ(csv.code, 2);
  EXPECT_EQ(csv.err, "tactip: --sensor 'left': '" + P("rec.csv") +
                         "' is a CSV recording of one sensor; --sensor picks a sensor of an HDF5 dataset\n");
  const CliResult bench = Run("bench --sensor left --out " + P("bench"));
  EXPECT_EQ(bench.code, 2);
  EXPECT_EQ(bench.err, "tactip: --sensor requires --dataset (see --help)\n");
  EXPECT_FALSE(fs::exists(P("x.csv")) || fs::exists(P("bench")));
}

}  // namespace
}  // namespace tactip
