// Scaling out from the command line: `generate --shard i/n` simulates one block of the
// job's runs; a bad shard is one line with exit code 2 and writes nothing.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "input_error.h"
#include "scenarios/rail.h"
#include "sensors/dataset.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;

class ShardCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tactip_shard_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliResult Run(const std::string& args) { return testing::RunTactip(args, dir_); }
  std::string P(const std::string& name) const { return (dir_ / name).string(); }
  // Names of the files in the test folder.
  std::vector<std::string> Files() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

  fs::path dir_;
};

// A short protocol (about 0.5 s per run on one core): small lift, fast retraction.
const std::string kQuick =
    " --speed-mm-s 3 --set rail.lift_mm=5 --set rail.hold_s=0.1 --set rail.settle_s=0.05 --set rail.post_fall_s=0.05"
    " --seed 5";

TEST_F(ShardCliTest, ShardRunsAreTheSameRunsOfTheWholeJob) {
  ASSERT_EQ(Run("generate rail --runs 4 --jobs 2 --quiet" + kQuick + " --out " + P("one.h5")).code, 0);
  const CliResult r = Run("generate rail --runs 4 --shard 1/2 --jobs 2" + kQuick + " --out " + P("part1.h5"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("generating shard 1/2: rail runs 2-3 of 4"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[2/2] run 3"), std::string::npos) << r.err;
  const DatasetReader one(P("one.h5")), part(P("part1.h5"));
  ASSERT_EQ(part.run_indices(), (std::vector<int>{2, 3}));
  ASSERT_TRUE(part.header().shard.has_value());
  EXPECT_EQ(part.header().shard->text(), "1/2");
  EXPECT_EQ(part.header().shard->runs_total, 4);
  EXPECT_FALSE(one.header().shard.has_value());
  EXPECT_EQ(part.header().config_yaml, one.header().config_yaml);
  for (const int k : {2, 3}) {
    const RunRecord a = one.ReadRun(k), b = part.ReadRun(k);
    EXPECT_EQ(a.time, b.time) << k;
    EXPECT_EQ(a.pos_px, b.pos_px) << k;
    EXPECT_EQ(a.valid, b.valid) << k;
    EXPECT_EQ(a.pin_slip, b.pin_slip) << k;
    EXPECT_EQ(a.normal_N, b.normal_N) << k;
    EXPECT_EQ(a.object_height_m, b.object_height_m) << k;
    EXPECT_EQ(a.text_attrs, b.text_attrs) << k;
    EXPECT_EQ(a.attrs.size(), b.attrs.size()) << k;
    for (const auto& [key, value] : a.attrs) {
      EXPECT_TRUE(value == b.attrs.at(key) || (std::isnan(value) && std::isnan(b.attrs.at(key)))) << k << " " << key;
    }
  }
}

TEST_F(ShardCliTest, BadShardOptionGetsOneLineNamingTheRuleAndWritesNothing) {
  const struct {
    std::string shard, message;
  } cases[] = {
      {"abc", "tactip: --shard 'abc': expected i/n, two integers with 0 <= i < n (e.g. 0/4)\n"},
      {"1/2/3", "tactip: --shard '1/2/3': expected i/n, two integers with 0 <= i < n (e.g. 0/4)\n"},
      {"2/2", "tactip: --shard '2/2': i must be < n (shards are numbered 0 to n-1)\n"},
      {"-1/2", "tactip: --shard '-1/2': i must be >= 0 (shards are numbered 0 to n-1)\n"},
      {"0/0", "tactip: --shard '0/0': n must be >= 1\n"},
      {"0/5",
       "tactip: --shard '0/5': n must be <= the job's number of runs (--runs 4), so that every shard has a run\n"},
  };
  for (const auto& c : cases) {
    const CliResult r = Run("generate rail --runs 4 --shard " + c.shard + " --out " + P("x.h5"));
    EXPECT_EQ(r.code, 2) << c.shard;
    EXPECT_EQ(r.err, c.message) << c.shard;
    EXPECT_TRUE(Files().empty()) << c.shard << ": nothing written";
  }
}

TEST(GenerateShardTest, ShardOfAnotherRunCountIsRefused) {
  GenerateOptions opts;
  opts.runs = 4;
  opts.shard = ShardSpec{1, 2, 6};
  opts.out_path = (fs::temp_directory_path() / "tactip_never_written.h5").string();
  EXPECT_EQ(InputErrorOf([&] { GenerateRailDataset(RailScenarioConfig{}, opts); }),
            "--shard 1/2 is of a 6-run job, but --runs = 4");
  opts.shard = ShardSpec{4, 4, 4};
  EXPECT_EQ(InputErrorOf([&] { GenerateRailDataset(RailScenarioConfig{}, opts); }),
            "--shard '4/4': i must be < n (shards are numbered 0 to n-1)");
  EXPECT_FALSE(fs::exists(opts.out_path));
}

}  // namespace
}  // namespace tactip
