// Scaling out from the command line: `generate --shard i/n` and `merge` give the file one
// machine writes, byte for byte; every refusal is one line with exit code 2 and leaves
// the output untouched.

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "tests/scenarios/cli_helpers.h"
#include "input_error.h"
#include "scenarios/rail/rail.h"
#include "sensors/dataset.h"

namespace fs = std::filesystem;

namespace tactip {
namespace {

using testing::CliResult;
using testing::Slurp;

class ShardCliTest : public testing::CliFolderTest {
 protected:
  // Names of the files in the test folder.
  std::vector<std::string> Files() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

};

// A short protocol (about 0.5 s per run on one core): small lift, fast retraction.
const std::string kQuickShardRun =
    " --speed-mm-s 3 --set rail.lift_mm=5 --set rail.hold_s=0.1 --set rail.settle_s=0.05 --set rail.post_fall_s=0.05"
    " --seed 5";

using testing::LineCount;

TEST_F(ShardCliTest, TwoShardsMergeToTheOneMachineFileByteForByte) {
  ASSERT_EQ(Run("generate rail --runs 4 --jobs 2 --quiet" + kQuickShardRun + " --out " + P("one.h5")).code, 0);
  for (const std::string i : {"0", "1"}) {
    const CliResult r = Run("generate rail --runs 4 --shard " + i + "/2 --jobs 1 --quiet" + kQuickShardRun + " --out " +
                            P("part" + i + ".h5"));
    ASSERT_EQ(r.code, 0) << r.err;
  }
  // The shard file says which runs it holds.
  const CliResult info = Run("info " + P("part1.h5"));
  EXPECT_NE(info.out.find("shard        1/2: runs 2-3 of 4"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("runs         2\n"), std::string::npos) << info.out;
  // Merge order is the run order, whatever the order on the command line.
  const CliResult m = Run("merge " + P("part1.h5") + " " + P("part0.h5") + " --out " + P("all.h5"));
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_NE(m.err.find("done: 4 runs from 2 shard file(s)"), std::string::npos) << m.err;
  EXPECT_TRUE(Slurp(P("all.h5")) == Slurp(P("one.h5"))) << "merged file differs from the one-machine file";
  EXPECT_NE(Slurp(P("part0.h5")), Slurp(P("one.h5")));
  EXPECT_EQ(Files(), (std::vector<std::string>{"all.h5", "one.h5", "part0.h5", "part1.h5"})) << "no temporary files";
}

TEST_F(ShardCliTest, ThreeUnevenShardsOfFourRunsMergeToTheOneMachineFile) {
  ASSERT_EQ(Run("generate rail --runs 4 --jobs 1 --quiet" + kQuickShardRun + " --out " + P("one.h5")).code, 0);
  // Runs [0,1), [1,2), [2,4): progress names each shard's runs.
  const char* expected[] = {"generating shard 0/3: rail run 0 of 4", "generating shard 1/3: rail run 1 of 4",
                            "generating shard 2/3: rail runs 2-3 of 4"};
  for (int i = 0; i < 3; ++i) {
    const std::string name = "p" + std::to_string(i) + ".h5";
    const CliResult r = Run("generate rail --runs 4 --shard " + std::to_string(i) + "/3 --jobs 2" + kQuickShardRun + " --out " +
                            P(name));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find(expected[i]), std::string::npos) << r.err;
  }
  const CliResult m = Run("merge " + P("p2.h5") + " " + P("p0.h5") + " " + P("p1.h5") + " --out " + P("all.h5"));
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_TRUE(Slurp(P("all.h5")) == Slurp(P("one.h5"))) << "merged file differs from the one-machine file";
}

TEST_F(ShardCliTest, ShardRunsAreTheSameRunsOfTheWholeJob) {
  ASSERT_EQ(Run("generate rail --runs 4 --jobs 2 --quiet" + kQuickShardRun + " --out " + P("one.h5")).code, 0);
  const CliResult r = Run("generate rail --runs 4 --shard 1/2 --jobs 2" + kQuickShardRun + " --out " + P("part1.h5"));
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
    EXPECT_EQ(a.sensors[0].pos_px, b.sensors[0].pos_px) << k;
    EXPECT_EQ(a.sensors[0].valid, b.sensors[0].valid) << k;
    EXPECT_EQ(a.sensors[0].pin_slip, b.sensors[0].pin_slip) << k;
    EXPECT_EQ(a.sensors[0].normal_N, b.sensors[0].normal_N) << k;
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

// ---------------------------------------------------------------------------------------
// Refusals of `merge`, on small synthetic shard files (no simulation).

/// A two-frame, two-pin run with index `index`.
RunRecord TinyRun(int index) {
  RunRecord r;
  r.index = index;
  SensorRecord& s = r.sensors.emplace_back();
  s.n_pins = 2;
  r.time = {0.0, 0.01};
  s.pos_px.assign(8, 1.5f);
  s.valid.assign(4, 1);
  s.pos_m.assign(12, 0.01f);
  s.gross_slip = {0, 1};
  s.pin_slip.assign(4, 0);
  s.pin_contact.assign(4, 1);
  s.incipient = {0, 0};
  s.normal_N.assign(4, 0.5f);
  s.tangential_N.assign(8, 0.1f);
  r.object_height_m = {0.05, 0.049};
  r.attrs["gross_slip_onset_s"] = 0.01;
  r.text_attrs["stimulus"] = "flat";
  return r;
}

/// The header of the synthetic job (4 runs, seed 7).
DatasetHeader JobHeader(std::optional<ShardSpec> shard) {
  DatasetHeader h;
  h.tactip_version = "0.1.0";
  h.scenario = "rail";
  h.seed = 7;
  h.config_yaml = "rail:\n  retract_speed_mm_s: 3\n";
  h.shard = shard;
  return h;
}

/// Writes `header` and runs [first, end) to `path`.
void WriteShard(const std::string& path, const DatasetHeader& header, int first, int end) {
  DatasetWriter w(path, header);
  for (int k = first; k < end; ++k) w.WriteRun(TinyRun(k));
  w.Commit();
}

/// Writes shard `i/n` of the 4-run synthetic job, with `edit` applied to its header.
template <class Edit>
void WriteJobShard(const std::string& path, int i, int n, Edit edit) {
  DatasetHeader h = JobHeader(ShardSpec{i, n, 4});
  edit(h);
  WriteShard(path, h, h.shard->first_run(), h.shard->end_run());
}
void WriteJobShard(const std::string& path, int i, int n) {
  WriteJobShard(path, i, n, [](DatasetHeader&) {});
}

TEST_F(ShardCliTest, SyntheticShardsMergeToTheFileWrittenInOneGo) {
  WriteShard(P("one.h5"), JobHeader(std::nullopt), 0, 4);
  WriteJobShard(P("a.h5"), 0, 3);
  WriteJobShard(P("b.h5"), 1, 3);
  WriteJobShard(P("c.h5"), 2, 3);
  const CliResult r = Run("merge " + P("c.h5") + " " + P("a.h5") + " " + P("b.h5") + " --out " + P("all.h5"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(Slurp(P("all.h5")) == Slurp(P("one.h5")));
  // Shards of different counts merge too when their blocks tile the job: 0/3, 1/3 and 1/2.
  WriteJobShard(P("half.h5"), 1, 2);
  const CliResult mixed =
      Run("merge " + P("half.h5") + " " + P("b.h5") + " " + P("a.h5") + " --out " + P("mixed.h5"));
  ASSERT_EQ(mixed.code, 0) << mixed.err;
  EXPECT_TRUE(Slurp(P("mixed.h5")) == Slurp(P("one.h5")));
}

TEST_F(ShardCliTest, SyntheticShardsOfTwoSensorsWithActionsMergeToTheFileWrittenInOneGo) {
  // Each run: a second sensor of three pins after the first, and a controller's record.
  const auto two_sensor_run = [](int k) {
    RunRecord r = TinyRun(k);
    SensorRecord s = r.sensors[0];
    s.name = "left";
    s.n_pins = 3;
    s.pos_px.assign(12, 2.5f + static_cast<float>(k));
    s.valid.assign(6, 1);
    s.pos_m.assign(18, 0.02f);
    s.pin_slip.assign(6, 1);
    s.pin_contact.assign(6, 1);
    s.normal_N.assign(6, 0.25f);
    s.tangential_N.assign(12, 0.05f);
    s.text_attrs["skin_pattern"] = "fingerprint-v2";
    r.sensors.push_back(s);
    r.actions.actuators = {"servo_x", "servo_z"};
    r.actions.controls = {0.001, 0.0, 0.002, 0.001 * k};
    r.actions.list = {{0.005 * k, "catch"}};
    return r;
  };
  const auto write = [&](const std::string& path, const DatasetHeader& header, int first, int end) {
    DatasetWriter w(path, header);
    for (int k = first; k < end; ++k) w.WriteRun(two_sensor_run(k));
    w.Commit();
  };
  write(P("one.h5"), JobHeader(std::nullopt), 0, 4);
  write(P("a.h5"), JobHeader(ShardSpec{0, 2, 4}), 0, 2);
  write(P("b.h5"), JobHeader(ShardSpec{1, 2, 4}), 2, 4);
  const CliResult r = Run("merge " + P("b.h5") + " " + P("a.h5") + " --out " + P("all.h5"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(Slurp(P("all.h5")) == Slurp(P("one.h5")));
  const RunRecord back = DatasetReader(P("all.h5")).ReadRun(3);
  ASSERT_EQ(back.sensors.size(), 2u);
  EXPECT_EQ(back.sensors[1].name, "left");
  EXPECT_EQ(back.sensors[1].pos_px, two_sensor_run(3).sensors[1].pos_px);
  ASSERT_EQ(back.actions.list.size(), 1u);
  EXPECT_EQ(back.actions.list[0].what, "catch");
}

TEST_F(ShardCliTest, MergeRefusesWithOneLineNamingTheFileAndLeavesTheOutputUntouched) {
  // Job: 4 runs in 2 shards (a, b) or 3 (t0..t2); other jobs, copies and broken files.
  WriteJobShard(P("a.h5"), 0, 2);
  WriteJobShard(P("b.h5"), 1, 2);
  WriteJobShard(P("t0.h5"), 0, 3);
  WriteJobShard(P("t2.h5"), 2, 3);
  fs::copy_file(P("a.h5"), P("a_copy.h5"));
  WriteShard(P("plain.h5"), JobHeader(std::nullopt), 0, 4);
  WriteJobShard(P("scenario.h5"), 1, 2, [](DatasetHeader& h) { h.scenario = "incipient"; });
  WriteJobShard(P("seed.h5"), 1, 2, [](DatasetHeader& h) { h.seed = 8; });
  WriteJobShard(P("config.h5"), 1, 2, [](DatasetHeader& h) { h.config_yaml += "  lift_mm: 5\n"; });
  WriteJobShard(P("version.h5"), 1, 2, [](DatasetHeader& h) { h.tactip_version = "0.0.9"; });
  WriteShard(P("total.h5"), JobHeader(ShardSpec{1, 2, 6}), 3, 6);
  WriteJobShard(P("layout.h5"), 1, 2);
  {
    // A shard without the root attribute layout_version: layout 1.
    const hid_t f = H5Fopen(P("layout.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    ASSERT_GE(H5Adelete(f, "layout_version"), 0);
    H5Fclose(f);
  }
  WriteShard(P("holes.h5"), JobHeader(ShardSpec{1, 2, 4}), 2, 3);
  std::ofstream(P("text.h5")) << "not hdf5\n";
  const std::string good = Slurp(P("a.h5"));
  std::ofstream(P("trunc.h5"), std::ios::binary) << good.substr(0, good.size() / 2);
  const std::string kOut = P("out.h5");
  const std::string b_before = Slurp(P("b.h5"));
  std::ofstream(kOut) << "previous contents";

  const struct {
    std::string args, message;
  } cases[] = {
      {P("a.h5") + " " + P("plain.h5"),
       "merge: '" + P("plain.h5") +
           "' is not a shard file (no root attribute 'shard'; shards are written by 'tactip generate ... --shard i/n')"},
      {P("a.h5") + " " + P("text.h5"), "cannot open dataset '" + P("text.h5") + "': not an HDF5 file"},
      {P("a.h5") + " " + P("trunc.h5"), "cannot open dataset '" + P("trunc.h5") + "': damaged or truncated HDF5 file"},
      {P("a.h5") + " " + P("missing.h5"), "cannot open dataset '" + P("missing.h5") + "': no such file"},
      {P("a.h5") + " " + P("holes.h5"),
       "merge: '" + P("holes.h5") + "' is corrupt: shard 1/2 should hold runs 2-3 of 4 but holds run 2"},
      {P("a.h5") + " " + P("scenario.h5"),
       "merge: '" + P("scenario.h5") + "' is from a different job than '" + P("a.h5") +
           "': it has scenario 'incipient', not 'rail'"},
      {P("a.h5") + " " + P("seed.h5"),
       "merge: '" + P("seed.h5") + "' is from a different job than '" + P("a.h5") + "': it has seed 8, not 7"},
      {P("a.h5") + " " + P("config.h5"),
       "merge: '" + P("config.h5") + "' is from a different job than '" + P("a.h5") +
           "': it has a different config (root attribute 'config_yaml')"},
      {P("a.h5") + " " + P("version.h5"),
       "merge: '" + P("version.h5") + "' is from a different job than '" + P("a.h5") +
           "': it has tactip version '0.0.9', not '0.1.0'"},
      {P("a.h5") + " " + P("layout.h5"),
       "merge: '" + P("layout.h5") + "' is from a different job than '" + P("a.h5") +
           "': it has layout_version 1, not 2"},
      {P("a.h5") + " " + P("total.h5"),
       "merge: '" + P("total.h5") + "' is from a different job than '" + P("a.h5") + "': it has runs_total 6, not 4"},
      {P("a.h5") + " " + P("b.h5") + " " + P("a_copy.h5"),
       "merge: '" + P("a_copy.h5") + "' (shard 0/2, runs 0-1 of 4) is a duplicate: '" + P("a.h5") +
           "' holds the same runs"},
      {P("a.h5") + " " + P("b.h5") + " " + P("a.h5"), "merge: '" + P("a.h5") + "' is given twice"},
      {P("a.h5") + " " + P("b.h5") + " " + dir_.string() + "/./b.h5",
       "merge: '" + P("b.h5") + "' and '" + dir_.string() + "/./b.h5' are the same file"},
      {P("a.h5") + " " + P("t0.h5") + " " + P("b.h5"),
       "merge: '" + P("t0.h5") + "' (shard 0/3, run 0 of 4) overlaps '" + P("a.h5") + "' (shard 0/2, runs 0-1 of 4)"},
      {P("a.h5"), "merge: missing runs 2-3 of 4 (shard 1/2 not given)"},
      {P("t2.h5"), "merge: missing runs 0-1 of 4 (shards 0/3, 1/3 not given)"},
      {P("t0.h5") + " " + P("b.h5"), "merge: missing run 1 of 4"},
  };
  for (const auto& c : cases) {
    const CliResult r = Run("merge " + c.args + " --out " + kOut);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(LineCount(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("tactip: " + c.message, 0), 0u) << c.args << "\n" << r.err;
    EXPECT_EQ(Slurp(kOut), "previous contents") << c.args;
  }
  EXPECT_TRUE(Slurp(P("b.h5")) == b_before) << "an input is never written";
  for (const auto& f : Files()) EXPECT_EQ(f.find(".tmp."), std::string::npos) << f << " left behind";
}

TEST_F(ShardCliTest, MergeRefusesItsOwnInputAsOutputAndMissingArguments) {
  WriteJobShard(P("a.h5"), 0, 2);
  WriteJobShard(P("b.h5"), 1, 2);
  const std::string kOut = P("out.h5");
  const std::string b_before = Slurp(P("b.h5"));
  // The output must not be an input: refused, input untouched.
  const CliResult self = Run("merge " + P("a.h5") + " " + P("b.h5") + " --out " + P("b.h5"));
  EXPECT_EQ(self.code, 2);
  EXPECT_EQ(self.err, "tactip: merge: --out '" + P("b.h5") +
                          "' is one of the input files; write the merged dataset to a new file\n");
  // Missing arguments are usage errors.
  const CliResult none = Run("merge --out " + kOut);
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.err, "tactip: files is required (see --help)\n");
  const CliResult no_out = Run("merge " + P("a.h5") + " " + P("b.h5"));
  EXPECT_EQ(no_out.code, 2);
  EXPECT_EQ(no_out.err, "tactip: --out is required (see --help)\n");
  EXPECT_TRUE(Slurp(P("b.h5")) == b_before) << "an input is never written";
  for (const auto& f : Files()) EXPECT_EQ(f.find(".tmp."), std::string::npos) << f << " left behind";
}

TEST_F(ShardCliTest, ShardBrokenMidwayLeavesNoOutputAndNoTemporaryFile) {
  // Valid headers, but run 3 lost an array: found only while copying.
  WriteJobShard(P("a.h5"), 0, 2);
  WriteJobShard(P("b.h5"), 1, 2);
  {
    const hid_t file = H5Fopen(P("b.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Ldelete(file, "/runs/run_0003/sensors/tactip/pins/pos_px", H5P_DEFAULT), 0);
    H5Fclose(file);
  }
  std::ofstream(P("out.h5")) << "previous contents";
  const CliResult r = Run("merge " + P("a.h5") + " " + P("b.h5") + " --out " + P("out.h5") + " --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "tactip: dataset '" + P("b.h5") + "': run_0003 has no array sensors/tactip/pins/pos_px\n");
  EXPECT_EQ(Slurp(P("out.h5")), "previous contents");
  EXPECT_EQ(Files(), (std::vector<std::string>{"a.h5", "b.h5", "out.h5"}));
}

}  // namespace
}  // namespace tactip
