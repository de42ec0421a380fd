// Shards of a dataset job: the run blocks, the "i/n" rules and the shard attributes of
// a dataset file.

#include "sensors/shard.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

#include "input_error.h"
#include "sensors/dataset.h"
#include "temp_dir.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

TEST(ShardTest, BlocksAreContiguousAndHoldEveryRunOnce) {
  for (int runs = 1; runs <= 40; ++runs) {
    for (int n = 1; n <= runs; ++n) {
      int next = 0;
      for (int i = 0; i < n; ++i) {
        const ShardSpec s{i, n, runs};
        EXPECT_EQ(s.first_run(), next) << i << "/" << n << " of " << runs;
        EXPECT_GT(s.end_run(), s.first_run()) << "every shard has a run: " << i << "/" << n << " of " << runs;
        next = s.end_run();
      }
      EXPECT_EQ(next, runs) << n << " shards of " << runs;
    }
  }
}

TEST(ShardTest, BlockBoundsAreFloorOfIRByN) {
  // 3 shards of 4 runs: [0,1), [1,2), [2,4).
  EXPECT_EQ((ShardSpec{0, 3, 4}.end_run()), 1);
  EXPECT_EQ((ShardSpec{1, 3, 4}.first_run()), 1);
  EXPECT_EQ((ShardSpec{2, 3, 4}.first_run()), 2);
  EXPECT_EQ((ShardSpec{2, 3, 4}.end_run()), 4);
  EXPECT_EQ((ShardSpec{2, 3, 4}.runs_text()), "runs 2-3 of 4");
  EXPECT_EQ((ShardSpec{1, 3, 4}.runs_text()), "run 1 of 4");
  // No overflow with the largest allowed job.
  EXPECT_EQ((ShardSpec{99999, 100000, 100000}.first_run()), 99999);
}

TEST(ShardTest, ParseAcceptsIOfNAndNamesTheRuleItBreaks) {
  const ShardSpec s = ParseShardOption("2/3", 4);
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 3);
  EXPECT_EQ(s.runs_total, 4);
  EXPECT_EQ(s.text(), "2/3");
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"abc", "--shard 'abc': expected i/n, two integers with 0 <= i < n (e.g. 0/4)"},
      {"1/2/3", "--shard '1/2/3': expected i/n"},
      {"1", "--shard '1': expected i/n"},
      {"/2", "--shard '/2': expected i/n"},
      {"4/4", "--shard '4/4': i must be < n (shards are numbered 0 to n-1)"},
      {"-1/2", "--shard '-1/2': i must be >= 0 (shards are numbered 0 to n-1)"},
      {"0/0", "--shard '0/0': n must be >= 1"},
      {"0/5", "--shard '0/5': n must be <= the job's number of runs (--runs 4), so that every shard has a run"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(InputErrorOf([&] { ParseShardOption(c.text, 4); }).rfind(c.message, 0), 0u)
        << c.text << ": " << InputErrorOf([&] { ParseShardOption(c.text, 4); });
  }
}

/// Fresh folder per test, removed afterwards.
class DatasetShardTest : public ::testing::Test {
 protected:
  tactip::testing::TestTempDir temp_{"shard_test"};
  std::string Path(const std::string& name) const { return temp_.File(name); }

  /// A one-run dataset with `shard` (if any) in its header.
  void Write(const std::string& path, std::optional<ShardSpec> shard) const {
    DatasetHeader h;
    h.tactip_version = "0.1.0";
    h.scenario = "rail";
    h.seed = 7;
    h.config_yaml = "rail: {}\n";
    h.shard = shard;
    RunRecord run;  // one frame, one pin
    SensorRecord& s = run.sensors.emplace_back();
    s.n_pins = 1;
    run.time = {0.0};
    s.pos_px = {1.0f, 2.0f};
    s.valid = s.gross_slip = s.pin_slip = s.pin_contact = s.incipient = {0};
    s.pos_m = {0.0f, 0.0f, 0.0f};
    s.normal_N = {0.0f};
    s.tangential_N = {0.0f, 0.0f};
    run.object_height_m = {0.0};
    DatasetWriter w(path, h);
    w.WriteRun(run);
    w.Commit();
  }

};

TEST_F(DatasetShardTest, ShardAttributesRoundTripAndPlainFilesHaveNone) {
  Write(Path("part.h5"), ShardSpec{1, 3, 8});
  Write(Path("plain.h5"), std::nullopt);
  const DatasetReader part(Path("part.h5"));
  ASSERT_TRUE(part.header().shard.has_value());
  EXPECT_EQ(part.header().shard->text(), "1/3");
  EXPECT_EQ(part.header().shard->runs_total, 8);
  EXPECT_FALSE(DatasetReader(Path("plain.h5")).header().shard.has_value());
  // Stored as docs/dataset-format.md ('Shard files') documents: string `shard`, unsigned 64-bit
  // `runs_total`.
  const hid_t file = H5Fopen(Path("part.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t attr = H5Aopen(file, "runs_total", H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  EXPECT_GT(H5Tequal(type, H5T_STD_U64LE), 0);
  H5Tclose(type);
  H5Aclose(attr);
  EXPECT_GT(H5Aexists(file, "shard"), 0);
  H5Fclose(file);
}

TEST_F(DatasetShardTest, InconsistentShardAttributesAreAnInputErrorNamingTheFile) {
  // A shard spec that breaks its rule for the recorded runs_total.
  Write(Path("bad.h5"), ShardSpec{1, 3, 8});
  {
    const hid_t file = H5Fopen(Path("bad.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const std::uint64_t two = 2;
    const hid_t attr = H5Aopen(file, "runs_total", H5P_DEFAULT);
    H5Awrite(attr, H5T_NATIVE_UINT64, &two);
    H5Aclose(attr);
    H5Fclose(file);
  }
  EXPECT_EQ(InputErrorOf([&] { DatasetReader r(Path("bad.h5")); }),
            "dataset '" + Path("bad.h5") +
                "': root attribute 'shard' = '1/3' is invalid: n must be <= the job's number of runs (--runs 2), so "
                "that every shard has a run");
  // runs_total without shard.
  Write(Path("half.h5"), ShardSpec{0, 1, 1});
  {
    const hid_t file = H5Fopen(Path("half.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    H5Adelete(file, "shard");
    H5Fclose(file);
  }
  EXPECT_EQ(InputErrorOf([&] { DatasetReader r(Path("half.h5")); }),
            "dataset '" + Path("half.h5") + "' has root attribute 'runs_total' but no 'shard'");
}

}  // namespace
}  // namespace tactip
