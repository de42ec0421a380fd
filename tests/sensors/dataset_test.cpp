#include "sensors/dataset.h"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "sim/config.h"
#include "input_error.h"
#include "run_records.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

/// Fresh empty folder per test, removed afterwards.
class DatasetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("tactip_dataset_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Path of `name` inside the test folder.
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  /// Names of all entries in the test folder.
  std::vector<std::string> Entries() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    return out;
  }

  fs::path dir_;
};

/// Header with non-ASCII and multi-line text and a seed needing all 64 bits.
DatasetHeader MakeHeader(std::uint64_t seed = 0xFEDCBA9876543210ULL) {
  DatasetHeader h;
  h.tactip_version = "0.1.0";
  h.scenario = "rail";
  h.seed = seed;
  h.config_yaml = "rail:\n  retract_speed_mm_s: 5\n  note: \"µ-slip ✓\"\n";
  return h;
}

/// Writes `runs` to `path` and commits.
void WriteDataset(const std::string& path, const std::vector<RunRecord>& runs, const DatasetHeader& header) {
  DatasetWriter w(path, header);
  for (const auto& r : runs) w.WriteRun(r);
  w.Commit();
}

/// Whole file as bytes.
std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(DatasetNameTest, RunGroupNamePadsToFourDigits) {
  EXPECT_EQ(RunGroupName(7), "run_0007");
  EXPECT_EQ(RunGroupName(0), "run_0000");
  EXPECT_EQ(RunGroupName(12345), "run_12345");
}

TEST_F(DatasetTest, RoundTripPreservesEveryArrayAndAttribute) {
  const std::string path = Path("x.h5");
  const RunRecord a = MakeRun(3, 5, 3);
  const RunRecord b = MakeRun(1, 2, 1);
  WriteDataset(path, {a, b}, MakeHeader());

  const DatasetReader reader(path);
  EXPECT_EQ(reader.header().tactip_version, "0.1.0");
  EXPECT_EQ(reader.header().scenario, "rail");
  EXPECT_EQ(reader.header().seed, 0xFEDCBA9876543210ULL);
  EXPECT_EQ(reader.header().config_yaml, MakeHeader().config_yaml);
  EXPECT_EQ(reader.header().layout_version, 2);
  EXPECT_EQ(reader.run_indices(), (std::vector<int>{1, 3}));

  const RunRecord r = reader.ReadRun(3);
  EXPECT_NO_THROW(r.CheckShapes());
  EXPECT_EQ(r.frames(), 5u);
  ASSERT_EQ(r.sensors.size(), 1u);
  EXPECT_EQ(r.sensors[0].name, "tactip");
  EXPECT_EQ(r.sensors[0].n_pins, 3);
  EXPECT_TRUE(r.sensors[0].external_px.empty());
  EXPECT_EQ(r.sensors[0].text_attrs.at("skin_pattern"), "smooth");
  ASSERT_EQ(r.attrs.size(), 3u);  // the event times among them
  EXPECT_EQ(r.attrs.at("friction_coefficient"), 0.6);
  EXPECT_EQ(r.attrs.at("gross_slip_onset_s"), 0.123456789);
  EXPECT_TRUE(std::isnan(r.attrs.at("object_fall_s")));
  ASSERT_EQ(r.actions.list.size(), 2u);
  EXPECT_EQ(r.actions.list[1].what, "stop ✓");
  ExpectSameRun(r, a);

  // A single-pin run round-trips too.
  ExpectSameRun(reader.ReadRun(1), b);
}

TEST_F(DatasetTest, TwoSensorsOfDifferentPinCountsRoundTripInTheirOrder) {
  const std::string path = Path("x.h5");
  RunRecord run = MakeRun(4, 6, 3);
  // A second sensor, named to sort before the first, with more pins and an external camera.
  run.sensors.push_back(MakeSensor("left", 6, 5, 7.0f, /*external=*/true));
  run.sensors[1].attrs["pixel_noise_px"] = 0.25;
  run.sensors[1].text_attrs["skin_pattern"] = "fingerprint-v2";
  WriteDataset(path, {run}, MakeHeader());

  const DatasetReader reader(path);
  const RunRecord back = reader.ReadRun(4);
  ASSERT_EQ(back.sensors.size(), 2u);
  EXPECT_EQ(back.sensors[0].name, "tactip");
  EXPECT_EQ(back.sensors[1].name, "left");
  EXPECT_EQ(back.sensors[1].n_pins, 5);
  EXPECT_EQ(back.sensors[1].external_m.size(), 6u * 5u * 3u);
  ExpectSameRun(back, run);

  // The summary names both sensors with their pin counts and attributes, and no arrays.
  const RunRecord summary = reader.ReadRunSummary(4);
  ASSERT_EQ(summary.sensors.size(), 2u);
  EXPECT_EQ(summary.sensors[0].n_pins, 3);
  EXPECT_EQ(summary.sensors[1].n_pins, 5);
  EXPECT_EQ(summary.sensors[1].attrs.at("pixel_noise_px"), 0.25);
  EXPECT_EQ(summary.sensors[1].text_attrs.at("skin_pattern"), "fingerprint-v2");
  EXPECT_TRUE(summary.sensors[1].pos_px.empty());
  EXPECT_TRUE(summary.actions.controls.empty());
}

TEST_F(DatasetTest, ARunWithoutActionsHasNoActionsGroupAndReadsBackEmpty) {
  const std::string path = Path("x.h5");
  RunRecord run = MakeRun(0, 4, 2);
  run.actions = {};
  WriteDataset(path, {run}, MakeHeader());
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(H5Lexists(f, "/runs/run_0000/actions", H5P_DEFAULT), 0);
  H5Fclose(f);
  ExpectSameRun(DatasetReader(path).ReadRun(0), run);
}

TEST_F(DatasetTest, SummaryReadsAttributesAndFrameCountOnly) {
  const std::string path = Path("x.h5");
  WriteDataset(path, {MakeRun(0, 5, 3)}, MakeHeader());
  const RunRecord s = DatasetReader(path).ReadRunSummary(0);
  EXPECT_EQ(s.frames(), 5u);
  ASSERT_EQ(s.sensors.size(), 1u);
  EXPECT_EQ(s.sensors[0].n_pins, 3);
  EXPECT_EQ(s.attrs.at("friction_coefficient"), 0.6);
  EXPECT_EQ(s.attrs.at("gross_slip_onset_s"), 0.123456789);  // from events/
  EXPECT_EQ(s.text_attrs.at("stimulus"), "flat");
  EXPECT_TRUE(s.sensors[0].pos_px.empty());
  EXPECT_TRUE(s.sensors[0].normal_N.empty());
  EXPECT_TRUE(s.object_height_m.empty());
}

// One dataset of the documented schema: element type, shape, whole-frame chunks deflated at
// level 4 (arrays with a pin axis), and a variable-length UTF-8 "units" attribute.
struct SchemaEntry {
  const char* path;
  hid_t type;
  std::vector<hsize_t> shape;
  const char* units;
};

void ExpectDatasetFollowsSchema(hid_t file, const SchemaEntry& e) {
  SCOPED_TRACE(e.path);
  const hid_t d = H5Dopen2(file, e.path, H5P_DEFAULT);
  ASSERT_GE(d, 0);
  // Element type and shape.
  const hid_t t = H5Dget_type(d);
  EXPECT_GT(H5Tequal(t, e.type), 0);
  H5Tclose(t);
  const hid_t s = H5Dget_space(d);
  std::vector<hsize_t> shape(static_cast<size_t>(H5Sget_simple_extent_ndims(s)));
  H5Sget_simple_extent_dims(s, shape.data(), nullptr);
  EXPECT_EQ(shape, e.shape);
  H5Sclose(s);
  // Layout: pin-axis arrays chunked by whole frames and deflated.
  const hid_t dcpl = H5Dget_create_plist(d);
  if (e.shape.size() > 1) {
    EXPECT_EQ(H5Pget_layout(dcpl), H5D_CHUNKED);
    std::vector<hsize_t> chunk(e.shape.size());
    H5Pget_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data());
    EXPECT_EQ(chunk, e.shape);  // T = 5 < 256
    unsigned flags = 0;
    size_t n_values = 1;
    unsigned level = 0;
    EXPECT_GE(H5Pget_filter_by_id2(dcpl, H5Z_FILTER_DEFLATE, &flags, &n_values, &level, 0, nullptr, nullptr), 0);
    EXPECT_EQ(level, 4u);
  }
  H5Pclose(dcpl);
  // "units" is a variable-length UTF-8 string (h5py reads it as str).
  const hid_t a = H5Aopen(d, "units", H5P_DEFAULT);
  ASSERT_GE(a, 0);
  const hid_t at = H5Aget_type(a);
  EXPECT_GT(H5Tis_variable_str(at), 0);
  EXPECT_EQ(H5Tget_cset(at), H5T_CSET_UTF8);
  char* units = nullptr;
  ASSERT_GE(H5Aread(a, at, &units), 0);
  EXPECT_STREQ(units, e.units);
  H5free_memory(units);
  H5Tclose(at);
  H5Aclose(a);
  H5Dclose(d);
}

TEST_F(DatasetTest, DatasetsHaveTheDocumentedTypesShapesChunksAndUnits) {
  const std::string path = Path("x.h5");
  WriteDataset(path, {MakeRun(2, 5, 3)}, MakeHeader());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<SchemaEntry> expected = {
      {"/runs/run_0002/time", H5T_IEEE_F64LE, {5}, "s"},
      {"/runs/run_0002/sensors/tactip/pins/pos_px", H5T_IEEE_F32LE, {5, 3, 2}, "px"},
      {"/runs/run_0002/sensors/tactip/pins/valid", H5T_STD_U8LE, {5, 3}, "1"},
      {"/runs/run_0002/sensors/tactip/pins/pos_m", H5T_IEEE_F32LE, {5, 3, 3}, "m"},
      {"/runs/run_0002/sensors/tactip/labels/gross_slip", H5T_STD_U8LE, {5}, "1"},
      {"/runs/run_0002/sensors/tactip/labels/pin_slip", H5T_STD_U8LE, {5, 3}, "1"},
      {"/runs/run_0002/sensors/tactip/labels/pin_contact", H5T_STD_U8LE, {5, 3}, "1"},
      {"/runs/run_0002/sensors/tactip/labels/incipient", H5T_STD_U8LE, {5}, "1"},
      {"/runs/run_0002/sensors/tactip/labels/pin_first_slip_s", H5T_IEEE_F64LE, {3}, "s"},
      {"/runs/run_0002/sensors/tactip/contact/normal_N", H5T_IEEE_F32LE, {5, 3}, "N"},
      {"/runs/run_0002/sensors/tactip/contact/tangential_N", H5T_IEEE_F32LE, {5, 3, 2}, "N"},
      {"/runs/run_0002/object/height_m", H5T_IEEE_F64LE, {5}, "m"},
      {"/runs/run_0002/actions/controls", H5T_IEEE_F64LE, {5, 2}, "ctrl"},
      {"/runs/run_0002/actions/time", H5T_IEEE_F64LE, {2}, "s"},
  };
  for (const auto& e : expected) ExpectDatasetFollowsSchema(file, e);
  H5Fclose(file);
}

TEST_F(DatasetTest, AttributesFollowTheDocumentedLayout) {
  const std::string path = Path("x.h5");
  WriteDataset(path, {MakeRun(2, 5, 3)}, MakeHeader());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // Root seed is uint64; run attributes are float64.
  const hid_t seed = H5Aopen(file, "seed", H5P_DEFAULT);
  const hid_t seed_type = H5Aget_type(seed);
  EXPECT_GT(H5Tequal(seed_type, H5T_STD_U64LE), 0);
  H5Tclose(seed_type);
  H5Aclose(seed);
  const hid_t mu = H5Aopen_by_name(file, "/runs/run_0002", "friction_coefficient", H5P_DEFAULT, H5P_DEFAULT);
  const hid_t mu_type = H5Aget_type(mu);
  EXPECT_GT(H5Tequal(mu_type, H5T_IEEE_F64LE), 0);
  H5Tclose(mu_type);
  H5Aclose(mu);
  // Layout 2: the root says so; event times live in events/, not on the run; the sensor
  // group carries its pin count and text attributes.
  std::uint64_t layout = 0;
  const hid_t lv = H5Aopen(file, "layout_version", H5P_DEFAULT);
  ASSERT_GE(lv, 0);
  EXPECT_GE(H5Aread(lv, H5T_NATIVE_UINT64, &layout), 0);
  EXPECT_EQ(layout, 2u);
  H5Aclose(lv);
  EXPECT_GT(H5Aexists_by_name(file, "/runs/run_0002/events", "gross_slip_onset_s", H5P_DEFAULT), 0);
  EXPECT_GT(H5Aexists_by_name(file, "/runs/run_0002/events", "object_fall_s", H5P_DEFAULT), 0);
  EXPECT_EQ(H5Aexists_by_name(file, "/runs/run_0002", "gross_slip_onset_s", H5P_DEFAULT), 0);
  EXPECT_EQ(H5Aexists_by_name(file, "/runs/run_0002/events", "friction_coefficient", H5P_DEFAULT), 0);
  long long n_pins = 0;
  const hid_t np = H5Aopen_by_name(file, "/runs/run_0002/sensors/tactip", "n_pins", H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(np, 0);
  EXPECT_GE(H5Aread(np, H5T_NATIVE_LLONG, &n_pins), 0);
  EXPECT_EQ(n_pins, 3);
  H5Aclose(np);
  EXPECT_GT(H5Aexists_by_name(file, "/runs/run_0002/sensors/tactip", "skin_pattern", H5P_DEFAULT), 0);
  EXPECT_EQ(H5Aexists_by_name(file, "/runs/run_0002", "skin_pattern", H5P_DEFAULT), 0);
  // The controls name their actuators; what the controller did is a list of strings.
  const hid_t controls = H5Dopen2(file, "/runs/run_0002/actions/controls", H5P_DEFAULT);
  EXPECT_GT(H5Aexists(controls, "actuators"), 0);
  H5Dclose(controls);
  const hid_t what = H5Dopen2(file, "/runs/run_0002/actions/what", H5P_DEFAULT);
  ASSERT_GE(what, 0);
  const hid_t what_type = H5Dget_type(what);
  EXPECT_GT(H5Tis_variable_str(what_type), 0);
  H5Tclose(what_type);
  H5Dclose(what);
  H5Fclose(file);
}

TEST_F(DatasetTest, IdenticalInputGivesByteIdenticalFiles) {
  const std::vector<RunRecord> runs = {MakeRun(0, 5, 3), MakeRun(1, 300, 4)};
  WriteDataset(Path("a.h5"), runs, MakeHeader());
  // HDF5 timestamps have 1 s resolution: make sure they would differ if stored.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  WriteDataset(Path("b.h5"), runs, MakeHeader());
  const std::string a = Slurp(Path("a.h5"));
  const std::string b = Slurp(Path("b.h5"));
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "files differ (" << a.size() << " vs " << b.size() << " bytes)";
}

TEST_F(DatasetTest, UncommittedWriterLeavesNoFiles) {
  const std::string path = Path("x.h5");
  std::string temp;
  {
    DatasetWriter w(path, MakeHeader());
    w.WriteRun(MakeRun(0, 5, 3));
    temp = w.temp_path();
    EXPECT_TRUE(fs::exists(temp));
    EXPECT_EQ(fs::path(temp).parent_path(), dir_);
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_TRUE(Entries().empty());
}

TEST_F(DatasetTest, CommitReplacesAnExistingFile) {
  const std::string path = Path("x.h5");
  std::ofstream(path) << "old contents\n";
  WriteDataset(path, {MakeRun(0, 5, 3)}, MakeHeader(1));
  EXPECT_EQ(DatasetReader(path).header().seed, 1u);
  WriteDataset(path, {MakeRun(4, 2, 2)}, MakeHeader(2));
  const DatasetReader reader(path);
  EXPECT_EQ(reader.header().seed, 2u);
  EXPECT_EQ(reader.run_indices(), std::vector<int>{4});
  EXPECT_EQ(Entries(), std::vector<std::string>{"x.h5"});  // no temp files left
}

TEST_F(DatasetTest, ADatasetWithoutRunsIsRefused) {
  const std::string path = Path("x.h5");
  WriteDataset(path, {}, MakeHeader());
  EXPECT_EQ(InputErrorOf([&] { DatasetReader r(path); }), "dataset '" + path + "' has no runs (/runs is empty)");
}

TEST_F(DatasetTest, AMemberOfRunsNotNamedRunNNNNIsRefused) {
  for (const char* name : {"run_99999999999", "run_7", "run_00007", "run_-001", "notes"}) {
    const std::string path = Path("x.h5");
    WriteDataset(path, {MakeRun(7, 5, 3), MakeRun(8, 5, 3)}, MakeHeader());
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    ASSERT_GE(H5Lmove(f, "/runs/run_0008", f, (std::string("/runs/") + name).c_str(), H5P_DEFAULT, H5P_DEFAULT), 0);
    H5Fclose(f);
    EXPECT_EQ(InputErrorOf([&] { DatasetReader r(path); }),
              "dataset '" + path + "': /runs/" + name +
                  " is not a run (runs are named run_NNNN, NNNN from 0000 to 2147483647)");
  }
}

/// Overwrites array `rel` of run `run` in the file at `path` with `values` (same size).
template <class T>
void Overwrite(const std::string& path, const std::string& rel, hid_t mem_type, const std::vector<T>& values) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t d = H5Dopen2(f, rel.c_str(), H5P_DEFAULT);
  ASSERT_GE(d, 0);
  EXPECT_GE(H5Dwrite(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(d);
  H5Fclose(f);
}

TEST_F(DatasetTest, BadFrameTimesAreRefusedNamingTheFileRunAndArray) {
  const std::string path = Path("x.h5");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string where = "dataset '" + path + "': run_0002/time ";
  const struct {
    std::vector<double> time;
    std::string problem;
  } cases[] = {
      {{0.0, 0.01, nan, 0.03}, "is nan at frame 2 (must be a finite number)"},
      {{0.0, 0.02, 0.01, 0.03}, "is not increasing: frame 2 at 0.01 s is not after frame 1 at 0.02 s"},
      {{nan, nan, nan, nan}, "is nan at frame 0 (must be a finite number)"},
      {{1.0, 1.0, 1.0, 1.0}, "is not increasing: frame 1 at 1 s is not after frame 0 at 1 s"},
  };
  for (const auto& c : cases) {
    WriteDataset(path, {MakeRun(2, 4, 3)}, MakeHeader());
    Overwrite(path, "/runs/run_0002/time", H5T_NATIVE_DOUBLE, c.time);
    const DatasetReader reader(path);
    EXPECT_EQ(InputErrorOf([&] { reader.ReadRunSummary(2); }), where + c.problem);
    EXPECT_EQ(InputErrorOf([&] { reader.ReadRun(2); }), where + c.problem);
  }
}

TEST_F(DatasetTest, ARunWithoutFramesIsRefused) {
  const std::string path = Path("x.h5");
  WriteDataset(path, {MakeRun(2, 4, 3)}, MakeHeader());
  {
    // time (0) and pins/valid (0, 3): consistent shapes, no frames.
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hsize_t time_shape[1] = {0}, valid_shape[2] = {0, 3};
    for (const auto& [rel, rank, shape, type] :
         {std::tuple{"/runs/run_0002/time", 1, time_shape, H5T_IEEE_F64LE},
          std::tuple{"/runs/run_0002/sensors/tactip/pins/valid", 2, valid_shape, H5T_STD_U8LE}}) {
      ASSERT_GE(H5Ldelete(f, rel, H5P_DEFAULT), 0);
      const hid_t space = H5Screate_simple(rank, shape, nullptr);
      const hid_t d = H5Dcreate2(f, rel, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      ASSERT_GE(d, 0);
      H5Dclose(d);
      H5Sclose(space);
    }
    H5Fclose(f);
  }
  const DatasetReader reader(path);
  EXPECT_EQ(InputErrorOf([&] { reader.ReadRunSummary(2); }),
            "dataset '" + path + "': run_0002/time has no frames (a run needs at least one)");
}

TEST_F(DatasetTest, NonFinitePinPositionsAreRefusedByReadRun) {
  const std::string path = Path("x.h5");
  const float inf = std::numeric_limits<float>::infinity();
  RunRecord run = MakeRun(2, 4, 3);
  WriteDataset(path, {run}, MakeHeader());
  std::vector<float>& pos_px = run.sensors[0].pos_px;
  pos_px[2 * (3 * 1 + 2) + 1] = inf;  // frame 1, pin 2, v
  Overwrite(path, "/runs/run_0002/sensors/tactip/pins/pos_px", H5T_NATIVE_FLOAT, pos_px);
  const DatasetReader reader(path);
  EXPECT_NO_THROW(reader.ReadRunSummary(2));  // reads no positions
  EXPECT_EQ(InputErrorOf([&] { reader.ReadRun(2); }),
            "dataset '" + path +
                "': run_0002/sensors/tactip/pins/pos_px is inf at frame 1, pin 2 (must be a finite number)");
}

TEST_F(DatasetTest, MissingFolderThrowsInputErrorAndLeavesNothing) {
  const std::string path = Path("no/such/folder/x.h5");
  const std::string msg = InputErrorOf([&] { DatasetWriter w(path, MakeHeader()); });
  EXPECT_NE(msg.find("cannot write dataset '" + path + "'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  EXPECT_TRUE(Entries().empty());
}

TEST_F(DatasetTest, FolderThatTakesNoFilesIsNamedWithTheSystemsReason) {
  // /proc exists but refuses new files (ENOENT, even for root): not a missing folder.
  const std::string msg = InputErrorOf([] { DatasetWriter w("/proc/x.h5", MakeHeader()); });
  EXPECT_EQ(msg.rfind("cannot write dataset '/proc/x.h5': cannot create a file in folder '/proc' (", 0), 0u) << msg;
}

TEST_F(DatasetTest, ReadingAMissingFileThrowsInputError) {
  const std::string path = Path("missing.h5");
  EXPECT_EQ(InputErrorOf([&] { DatasetReader r(path); }), "cannot open dataset '" + path + "': no such file");
}

TEST_F(DatasetTest, ReadingATextFileThrowsNotAnHdf5File) {
  const std::string path = Path("notes.h5");
  std::ofstream(path) << "this is not HDF5\n";
  const std::string msg = InputErrorOf([&] { DatasetReader r(path); });
  EXPECT_EQ(msg, "cannot open dataset '" + path + "': not an HDF5 file");
}

TEST_F(DatasetTest, ReadingAForeignHdf5FileNamesTheMissingPart) {
  const std::string path = Path("foreign.h5");
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  H5Fclose(f);
  const std::string msg = InputErrorOf([&] { DatasetReader r(path); });
  EXPECT_NE(msg.find("dataset '" + path + "'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tactip_version"), std::string::npos) << msg;
}

TEST_F(DatasetTest, AMissingArrayNamesTheRunAndTheArray) {
  const std::string path = Path("x.h5");
  WriteDataset(path, {MakeRun(7, 5, 3)}, MakeHeader());
  // Remove one array behind the reader's back.
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  ASSERT_GE(H5Ldelete(f, "/runs/run_0007/sensors/tactip/pins/pos_m", H5P_DEFAULT), 0);
  H5Fclose(f);
  const DatasetReader reader(path);
  EXPECT_NO_THROW(reader.ReadRunSummary(7));
  const std::string msg = InputErrorOf([&] { reader.ReadRun(7); });
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("run_0007"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sensors/tactip/pins/pos_m"), std::string::npos) << msg;
  EXPECT_NE(InputErrorOf([&] { reader.ReadRun(8); }).find("has no run run_0008"), std::string::npos);
}

TEST(DatasetShapeTest, CheckShapesNamesTheWrongField) {
  RunRecord r = MakeRun(0, 5, 3);
  EXPECT_NO_THROW(r.CheckShapes());
  r.sensors[0].tangential_N.pop_back();
  try {
    r.CheckShapes();
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("sensor 'tactip': tangential_N"), std::string::npos) << e.what();
  }
  RunRecord empty;
  empty.sensors.emplace_back().n_pins = 3;
  EXPECT_THROW(empty.CheckShapes(), std::logic_error);  // T = 0
  RunRecord no_pins = MakeRun(0, 5, 3);
  no_pins.sensors[0].n_pins = 0;
  EXPECT_THROW(no_pins.CheckShapes(), std::logic_error);
}

TEST(DatasetShapeTest, CheckShapesRefusesRunsWhoseSensorsOrControlsCannotBeWritten) {
  const struct {
    const char* what;
    void (*spoil)(RunRecord&);
    const char* message;
  } cases[] = {
      {"no sensor", [](RunRecord& r) { r.sensors.clear(); }, "has no sensor"},
      {"same name", [](RunRecord& r) { r.sensors.push_back(r.sensors[0]); }, "two sensors are named 'tactip'"},
      {"slash", [](RunRecord& r) { r.sensors[0].name = "a/b"; }, "sensor name 'a/b' cannot name a group"},
      {"empty name", [](RunRecord& r) { r.sensors[0].name = ""; }, "sensor name '' cannot name a group"},
      {"n_pins attribute", [](RunRecord& r) { r.sensors[0].attrs["n_pins"] = 3; }, "'n_pins' is not an attribute"},
      {"controls", [](RunRecord& r) { r.actions.controls.pop_back(); }, "actions.controls has 9 values, expected 10"},
      {"actuators", [](RunRecord& r) { r.actions.actuators[1] = "servo_x"; }, "actuator 'servo_x' is listed twice"},
      {"attribute kinds", [](RunRecord& r) { r.text_attrs["friction_coefficient"] = "high"; }, "both numeric and text"},
  };
  for (const auto& c : cases) {
    RunRecord r = MakeRun(0, 5, 3);
    c.spoil(r);
    try {
      r.CheckShapes();
      ADD_FAILURE() << c.what << ": no exception";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << c.what << ": " << e.what();
    }
  }
}

TEST_F(DatasetTest, WriteRunRejectsBadRecordsWithLogicError) {
  DatasetWriter w(Path("x.h5"), MakeHeader());
  RunRecord bad = MakeRun(0, 5, 3);
  bad.sensors[0].valid.push_back(1);
  EXPECT_THROW(w.WriteRun(bad), std::logic_error);
  w.WriteRun(MakeRun(0, 5, 3));  // the failed call wrote nothing
  EXPECT_THROW(w.WriteRun(MakeRun(0, 5, 3)), std::logic_error);  // same index twice
  w.Commit();
  EXPECT_EQ(DatasetReader(Path("x.h5")).run_indices(), std::vector<int>{0});
}

}  // namespace
}  // namespace tactip
