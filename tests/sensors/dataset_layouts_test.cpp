// Reading both dataset layouts: files of layout 1 (one sensor's arrays directly under the
// run, event times among the run's attributes, no root attribute layout_version) as one
// sensor "tactip", and the refusals of a layout-2 file whose sensors/ or actions/ are wrong.

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "input_error.h"
#include "run_records.h"
#include "sensors/dataset.h"
#include "temp_dir.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

/// Fresh empty folder per test, removed afterwards.
class DatasetLayoutsTest : public ::testing::Test {
 protected:
  tactip::testing::TestTempDir temp_{"layouts_test"};
  std::string Path(const std::string& name) const { return temp_.File(name); }

};

/// Writes string attribute `name` = `value` on `obj`, as the layout-1 writer did.
void StringAttr(hid_t obj, const char* name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  const char* text = value.c_str();
  H5Awrite(attr, type, &text);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

/// Writes array `path` of shape `shape` (element types as the layout-1 writer stored them).
template <class T>
void Array(hid_t file, const std::string& path, std::vector<hsize_t> shape, hid_t file_type, hid_t mem_type,
           const std::vector<T>& data) {
  const hid_t space = H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t dset = H5Dcreate2(file, path.c_str(), file_type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  StringAttr(dset, "units", "1");
  H5Dclose(dset);
  H5Pclose(lcpl);
  H5Sclose(space);
}

/// Writes `run` (its one sensor) to a new file at `path` in layout 1: the sensor's arrays
/// under the run, every attribute (events and skin_pattern included) on the run, no
/// actions, no root attribute layout_version. Without `incipient`, no labels/incipient
/// (files from before partial-slip labels existed).
void WriteLayoutOne(const std::string& path, const RunRecord& run, bool incipient = true) {
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  StringAttr(f, "tactip_version", "0.1.0");
  StringAttr(f, "scenario", "rail");
  StringAttr(f, "config_yaml", "rail: {}\n");
  const std::uint64_t seed = 3;
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const hid_t seed_attr = H5Acreate2(f, "seed", H5T_STD_U64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(seed_attr, H5T_NATIVE_UINT64, &seed);
  H5Aclose(seed_attr);
  const std::string at = "/runs/" + RunGroupName(run.index) + "/";
  const SensorRecord& s = run.sensors.at(0);
  const hsize_t t = run.frames(), n = static_cast<hsize_t>(s.n_pins);
  const hid_t f64 = H5T_IEEE_F64LE, f32 = H5T_IEEE_F32LE, u8 = H5T_STD_U8LE;
  Array(f, at + "time", {t}, f64, H5T_NATIVE_DOUBLE, run.time);
  Array(f, at + "pins/pos_px", {t, n, 2}, f32, H5T_NATIVE_FLOAT, s.pos_px);
  Array(f, at + "pins/valid", {t, n}, u8, H5T_NATIVE_UINT8, s.valid);
  Array(f, at + "pins/pos_m", {t, n, 3}, f32, H5T_NATIVE_FLOAT, s.pos_m);
  Array(f, at + "labels/gross_slip", {t}, u8, H5T_NATIVE_UINT8, s.gross_slip);
  Array(f, at + "labels/pin_slip", {t, n}, u8, H5T_NATIVE_UINT8, s.pin_slip);
  Array(f, at + "labels/pin_contact", {t, n}, u8, H5T_NATIVE_UINT8, s.pin_contact);
  if (incipient) Array(f, at + "labels/incipient", {t}, u8, H5T_NATIVE_UINT8, s.incipient);
  if (!s.external_px.empty()) {
    Array(f, at + "external/pos_px", {t, n, 2}, f32, H5T_NATIVE_FLOAT, s.external_px);
    Array(f, at + "external/pos_m", {t, n, 3}, f32, H5T_NATIVE_FLOAT, s.external_m);
  }
  Array(f, at + "contact/normal_N", {t, n}, f32, H5T_NATIVE_FLOAT, s.normal_N);
  Array(f, at + "contact/tangential_N", {t, n, 2}, f32, H5T_NATIVE_FLOAT, s.tangential_N);
  Array(f, at + "object/height_m", {t}, f64, H5T_NATIVE_DOUBLE, run.object_height_m);
  // Every attribute on the run group, the sensor's among them.
  const hid_t g = H5Gopen2(f, at.c_str(), H5P_DEFAULT);
  for (const auto& [key, value] : run.attrs) {
    const hid_t a = H5Acreate2(g, key.c_str(), H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, &value);
    H5Aclose(a);
  }
  for (const auto& [key, value] : run.text_attrs) StringAttr(g, key.c_str(), value);
  for (const auto& [key, value] : s.text_attrs) StringAttr(g, key.c_str(), value);
  H5Gclose(g);
  H5Sclose(scalar);
  H5Fclose(f);
}

/// `run` as layout 1 can hold it: no controller record and no first slips (both came
/// later).
RunRecord AsLayoutOne(RunRecord run) {
  run.actions = {};
  for (SensorRecord& s : run.sensors) s.pin_first_slip_s.clear();
  return run;
}

TEST_F(DatasetLayoutsTest, ALayoutOneFileReadsAsTheSameRunWithOneSensorNamedTactip) {
  RunRecord run = MakeRun(2, 6, 4);
  run.sensors[0] = MakeSensor("tactip", 6, 4, 0.5f, /*external=*/true);
  run.sensors[0].text_attrs["skin_pattern"] = "fingerprint-v1";
  run.attrs["retract_start_s"] = 2.03;
  const std::string path = Path("old.h5");
  WriteLayoutOne(path, run);

  const DatasetReader reader(path);
  EXPECT_EQ(reader.header().layout_version, 1);
  EXPECT_EQ(reader.run_indices(), std::vector<int>{2});
  // Events land among the run's attributes, skin_pattern on the sensor: the same record.
  ExpectSameRun(reader.ReadRun(2), AsLayoutOne(run));
  const RunRecord summary = reader.ReadRunSummary(2);
  ASSERT_EQ(summary.sensors.size(), 1u);
  EXPECT_EQ(summary.sensors[0].name, "tactip");
  EXPECT_EQ(summary.sensors[0].n_pins, 4);
  EXPECT_EQ(summary.sensors[0].text_attrs.at("skin_pattern"), "fingerprint-v1");
  EXPECT_EQ(summary.attrs.at("retract_start_s"), 2.03);
}

TEST_F(DatasetLayoutsTest, ALayoutOneFileReadBackWritesTheSameRunInLayoutTwo) {
  const RunRecord run = AsLayoutOne(MakeRun(0, 5, 3));
  const std::string old_path = Path("old.h5"), new_path = Path("new.h5");
  WriteLayoutOne(old_path, run);
  {
    DatasetWriter w(new_path, DatasetReader(old_path).header());
    w.WriteRun(DatasetReader(old_path).ReadRun(0));
    w.Commit();
  }
  const DatasetReader converted(new_path);
  EXPECT_EQ(converted.header().layout_version, 2);
  ExpectSameRun(converted.ReadRun(0), run);
}

TEST_F(DatasetLayoutsTest, ALayoutOneFileWithoutPartialSlipLabelsDerivesThem) {
  RunRecord run = AsLayoutOne(MakeRun(0, 6, 4));
  SensorRecord& s = run.sensors[0];
  s.incipient = PartialSlipLabels(s.pin_contact, s.pin_slip, s.n_pins);
  const std::string path = Path("old.h5");
  WriteLayoutOne(path, run, /*incipient=*/false);
  EXPECT_EQ(DatasetReader(path).ReadRun(0).sensors.at(0).incipient, s.incipient);
}

TEST_F(DatasetLayoutsTest, ALayoutOneFileNamesItsArraysUnderTheRun) {
  RunRecord run = AsLayoutOne(MakeRun(1, 4, 3));
  run.sensors[0].valid[3 * 2 + 1] = 2;  // frame 2, pin 1
  const std::string path = Path("old.h5");
  WriteLayoutOne(path, run);
  EXPECT_EQ(InputErrorOf([&] { DatasetReader(path).ReadRun(1); }),
            "dataset '" + path + "': run_0001/pins/valid is 2 at frame 2, pin 1 (must be 0 or 1)");
}

/// Writes MakeRun(0, 5, 3) to `path` in layout 2 and applies `edit` to the open file.
template <class Edit>
void WriteAndEdit(const std::string& path, Edit edit) {
  DatasetHeader h;
  h.tactip_version = "0.1.0";
  h.scenario = "rail";
  h.config_yaml = "rail: {}\n";
  {
    DatasetWriter w(path, h);
    w.WriteRun(MakeRun(0, 5, 3));
    w.Commit();
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  edit(f);
  H5Fclose(f);
}

TEST_F(DatasetLayoutsTest, ALayoutThisReaderDoesNotKnowIsRefused) {
  const std::string path = Path("x.h5");
  WriteAndEdit(path, [](hid_t f) {
    const std::uint64_t three = 3;
    const hid_t a = H5Aopen(f, "layout_version", H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_UINT64, &three);
    H5Aclose(a);
  });
  EXPECT_EQ(InputErrorOf([&] { DatasetReader r(path); }),
            "dataset '" + path + "': root attribute 'layout_version' = 3 is not a layout this tactip reads (1 to 2)");
}

TEST_F(DatasetLayoutsTest, BrokenSensorsAndActionsOfALayoutTwoRunAreRefusedNamingThem) {
  const std::string path = Path("x.h5");
  const std::string file = "dataset '" + path + "': ";
  const struct {
    const char* what;
    void (*edit)(hid_t);
    bool summary;  // ReadRunSummary refuses it too (else only ReadRun)
    std::string message;
  } cases[] = {
      {"no sensors group", [](hid_t f) { H5Ldelete(f, "/runs/run_0000/sensors", H5P_DEFAULT); }, true,
       "run_0000 has no group sensors"},
      {"no sensor in it",
       [](hid_t f) { H5Ldelete(f, "/runs/run_0000/sensors/tactip", H5P_DEFAULT); }, true,
       "run_0000/sensors holds no sensor (a run needs at least one)"},
      {"n_pins disagrees",
       [](hid_t f) {
         const std::int64_t four = 4;
         const hid_t g = H5Gopen2(f, "/runs/run_0000/sensors/tactip", H5P_DEFAULT);
         const hid_t a = H5Aopen(g, "n_pins", H5P_DEFAULT);
         H5Awrite(a, H5T_NATIVE_INT64, &four);
         H5Aclose(a);
         H5Gclose(g);
       },
       true, "run_0000/sensors/tactip has n_pins = 4 but its pins/valid holds 3 pins"},
      {"an event on the run too",
       [](hid_t f) {
         const double t = 1.5;
         const hid_t space = H5Screate(H5S_SCALAR);
         const hid_t a = H5Acreate_by_name(f, "/runs/run_0000", "gross_slip_onset_s", H5T_IEEE_F64LE, space,
                                           H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
         H5Awrite(a, H5T_NATIVE_DOUBLE, &t);
         H5Aclose(a);
         H5Sclose(space);
       },
       true, "run_0000 has attribute 'gross_slip_onset_s' both on the run and in events/"},
      {"actuators missing",
       [](hid_t f) { H5Adelete_by_name(f, "/runs/run_0000/actions/controls", "actuators", H5P_DEFAULT); }, false,
       "run_0000/actions/controls has no attribute 'actuators'"},
      {"what missing", [](hid_t f) { H5Ldelete(f, "/runs/run_0000/actions/what", H5P_DEFAULT); }, false,
       "run_0000 has no array actions/what"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    WriteAndEdit(path, c.edit);
    const DatasetReader reader(path);
    EXPECT_EQ(InputErrorOf([&] { reader.ReadRun(0); }), file + c.message);
    EXPECT_EQ(InputErrorOf([&] { reader.ReadRunSummary(0); }), c.summary ? file + c.message : "");
  }
}

}  // namespace
}  // namespace tactip
