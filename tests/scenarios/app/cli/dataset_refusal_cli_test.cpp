// Every command that reads a dataset refuses a damaged one in one line naming the file, the
// run and the array (exit code 2, no output written): bad frame times, non-finite pin
// positions, a run without frames, no runs, a /runs member that is not a run.

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "sensors/dataset.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;

class DatasetRefusalCliTest : public testing::CliFolderTest {
 protected:
  void SetUp() override {
    CliFolderTest::SetUp();
    std::ofstream(P("t.model")) << "tactip-detector threshold 1\nthreshold_px 0.5\n";
  }

  /// Writes a two-run dataset (runs 0 and 1, four frames of two pins) to `path`, then
  /// lets `edit` change the open file.
  void WriteDataset(const std::string& path, const std::function<void(hid_t)>& edit) const {
    {
      DatasetHeader h;
      h.tactip_version = "0.1.0";
      h.scenario = "rail";
      h.config_yaml = "rail: {}\n";
      DatasetWriter w(path, h);
      for (int index : {0, 1}) w.WriteRun(FourFrameRun(index));
      w.Commit();
    }
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    edit(file);
    H5Fclose(file);
  }

  /// Four frames of two pins, slipping from frame 2.
  static RunRecord FourFrameRun(int index) {
    RunRecord r;
    r.index = index;
    SensorRecord& s = r.sensors.emplace_back();
    s.n_pins = 2;
    r.time = {0.0, 0.01, 0.02, 0.03};
    for (int k = 0; k < 16; ++k) s.pos_px.push_back(100.0f + static_cast<float>(k));
    s.valid.assign(8, 1);
    s.pos_m.assign(24, 0.01f);
    s.gross_slip = {0, 0, 1, 1};
    s.pin_slip.assign(8, 0);
    s.pin_contact.assign(8, 1);
    s.incipient.assign(4, 0);
    s.pin_first_slip_s = {0.02, std::numeric_limits<double>::quiet_NaN()};  // NaN: never slipped
    s.normal_N.assign(8, 0.5f);
    s.tangential_N.assign(16, 0.1f);
    r.object_height_m = {0.05, 0.05, 0.049, 0.048};
    r.attrs["retract_start_s"] = 0.0;
    r.attrs["gross_slip_onset_s"] = 0.02;
    r.text_attrs["stimulus"] = "flat";
    return r;
  }
};

/// Overwrites the whole array at `path_in_file` with `values`.
template <class T>
void Overwrite(hid_t file, const char* path_in_file, hid_t mem_type, const std::vector<T>& values) {
  const hid_t d = H5Dopen2(file, path_in_file, H5P_DEFAULT);
  ASSERT_GE(d, 0);
  EXPECT_GE(H5Dwrite(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(d);
}

/// Replaces array `path_in_file` by an empty one of `rank` with trailing dimensions `tail`.
void MakeEmpty(hid_t file, const char* path_in_file, hid_t type, std::vector<hsize_t> shape) {
  ASSERT_GE(H5Ldelete(file, path_in_file, H5P_DEFAULT), 0);
  const hid_t space = H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr);
  const hid_t d = H5Dcreate2(file, path_in_file, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(d, 0);
  H5Dclose(d);
  H5Sclose(space);
}

/// One way to damage the two-run dataset, and the refusal every reader gives for it.
struct Damage {
  const char* name;
  std::function<void(hid_t)> edit;
  std::string message;  // after "dataset '<file>'"
  bool seen_by_info;    // info reads frame times, not positions
};

/// Bad frame times, non-finite pin positions and first-slip times, a run without frames, no
/// runs, a /runs member that is not a run.
std::vector<Damage> Damages(const RunRecord& run_1) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  return {
      {"nan-time", [=](hid_t f) { Overwrite(f, "/runs/run_0001/time", H5T_NATIVE_DOUBLE, std::vector{0.0, 0.01, nan, 0.03}); },
       ": run_0001/time is nan at frame 2 (must be a finite number)", true},
      {"swapped-time",
       [](hid_t f) { Overwrite(f, "/runs/run_0001/time", H5T_NATIVE_DOUBLE, std::vector{0.0, 0.02, 0.01, 0.03}); },
       ": run_0001/time is not increasing: frame 2 at 0.01 s is not after frame 1 at 0.02 s", true},
      {"all-nan-time", [=](hid_t f) { Overwrite(f, "/runs/run_0001/time", H5T_NATIVE_DOUBLE, std::vector(4, nan)); },
       ": run_0001/time is nan at frame 0 (must be a finite number)", true},
      {"constant-time", [](hid_t f) { Overwrite(f, "/runs/run_0001/time", H5T_NATIVE_DOUBLE, std::vector(4, 0.5)); },
       ": run_0001/time is not increasing: frame 1 at 0.5 s is not after frame 0 at 0.5 s", true},
      {"inf-position",
       [=](hid_t f) {
         std::vector<float> px = run_1.sensors[0].pos_px;
         px[2 * (2 * 3 + 1)] = -inf;  // frame 3, pin 1, u
         Overwrite(f, "/runs/run_0001/sensors/tactip/pins/pos_px", H5T_NATIVE_FLOAT, px);
       },
       ": run_0001/sensors/tactip/pins/pos_px is -inf at frame 3, pin 1 (must be a finite number)", false},
      {"inf-first-slip",
       [](hid_t f) {
         Overwrite(f, "/runs/run_0001/sensors/tactip/labels/pin_first_slip_s", H5T_NATIVE_DOUBLE,
                   std::vector{0.02, std::numeric_limits<double>::infinity()});
       },
       ": run_0001/sensors/tactip/labels/pin_first_slip_s is inf at pin 1 (must be a finite time or NaN)", false},
      {"no-frames",
       [](hid_t f) {
         MakeEmpty(f, "/runs/run_0001/time", H5T_IEEE_F64LE, {0});
         MakeEmpty(f, "/runs/run_0001/sensors/tactip/pins/valid", H5T_STD_U8LE, {0, 2});
       },
       ": run_0001/time has no frames (a run needs at least one)", true},
      {"no-runs",
       [](hid_t f) {
         ASSERT_GE(H5Ldelete(f, "/runs/run_0000", H5P_DEFAULT), 0);
         ASSERT_GE(H5Ldelete(f, "/runs/run_0001", H5P_DEFAULT), 0);
       },
       " has no runs (/runs is empty)", true},
      {"huge-run-number",
       [](hid_t f) {
         ASSERT_GE(H5Lmove(f, "/runs/run_0001", f, "/runs/run_99999999999", H5P_DEFAULT, H5P_DEFAULT), 0);
       },
       ": /runs/run_99999999999 is not a run (runs are named run_NNNN, NNNN from 0000 to 2147483647)", true},
  };
}

TEST_F(DatasetRefusalCliTest, EveryReadingCommandRefusesADamagedDataset) {
  for (const Damage& d : Damages(FourFrameRun(1))) {
    const std::string data = P(std::string(d.name) + ".h5");
    WriteDataset(data, d.edit);
    const std::string expected = "tactip: dataset '" + data + "'" + d.message + "\n";
    const std::string commands[] = {
        "info " + data,
        "train threshold --data " + data + " --out " + P("x.model"),
        "train logreg --data " + data + " --out " + P("x.model"),
        "evaluate --model " + P("t.model") + " --data " + data,
        "detect --model " + P("t.model") + " --data " + data + " --out " + P("x.csv"),
        "detect incipient --data " + data + " --out " + P("x.csv"),
        "report incipient " + data + " --csv " + P("x.csv"),
        "report signatures " + data + " --csv " + P("x.csv"),
    };
    for (const std::string& args : commands) {
      if (!d.seen_by_info && args.rfind("info ", 0) == 0) continue;
      const CliResult r = Run(args);
      EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
      EXPECT_EQ(r.err, expected) << args;
      EXPECT_EQ(r.out, "") << args;
      EXPECT_FALSE(fs::exists(P("x.model")) || fs::exists(P("x.csv"))) << args;
    }
  }
}

TEST_F(DatasetRefusalCliTest, TheUndamagedDatasetPassesTheSameReaders) {
  WriteDataset(P("good.h5"), [](hid_t) {});
  EXPECT_EQ(Run("info " + P("good.h5")).code, 0);
  const CliResult detect = Run("detect incipient --data " + P("good.h5") + " --out " + P("x.csv"));
  EXPECT_EQ(detect.code, 0) << detect.err;
  const CliResult report = Run("report incipient " + P("good.h5"));
  EXPECT_EQ(report.code, 0) << report.err;
}

}  // namespace
}  // namespace tactip
