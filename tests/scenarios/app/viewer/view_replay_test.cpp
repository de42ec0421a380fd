// Replaying a stored run in the viewer: the re-simulation of a generated run matches the
// file exactly, a stored position that differs is reported by how much, the pins show the
// stored labels, and a file or run that cannot be replayed is refused in one line.

#include "scenarios/app/viewer/replay_view_source.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "tests/scenarios/cli_helpers.h"
#include "input_error.h"
#include "models/skin.h"
#include "mujoco_warning_guard.h"
#include "scenarios/registry.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

// The generated dataset's config: a 5 mm lift and a 5 mm/s retraction (about 420 frames).
const std::vector<std::string> kShortRun = {"rail.lift_mm=5", "rail.retract_speed_mm_s=5"};
constexpr int kRuns = 2;
constexpr std::uint64_t kReplaySeed = 4;

class ReplayViewSourceTest : public testing::MujocoWarningGuard {
 protected:
  // One dataset, generated as `tactip generate rail --runs 2 --seed 4` does, for all tests.
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("tactip_ReplayViewSourceTest_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    GenerateOptions opts;
    opts.runs = kRuns;
    opts.seed = kReplaySeed;
    opts.jobs = 1;
    opts.out_path = Path("generated.h5");
    GenerateRailDataset(RailFamily(FindScenario("rail")).Load({"", kShortRun}), opts);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string Path(const std::string& name) { return (dir_ / name).string(); }

  // Run 1 of the generated dataset as stored.
  static RunRecord StoredRun1() { return DatasetReader(Path("generated.h5")).ReadRun(1); }
  // Writes `run` into the dataset `name` under the generated dataset's header, changed by `edit`.
  template <class Edit>
  static std::string WriteDataset(const std::string& name, const RunRecord& run, Edit edit) {
    DatasetHeader header = DatasetReader(Path("generated.h5")).header();
    edit(header);
    DatasetWriter writer(Path(name), header);
    writer.WriteRun(run);
    writer.Commit();
    return Path(name);
  }
  static std::string WriteDataset(const std::string& name, const RunRecord& run) {
    return WriteDataset(name, run, [](DatasetHeader&) {});
  }

  static fs::path dir_;
};
fs::path ReplayViewSourceTest::dir_;

TEST_F(ReplayViewSourceTest, ARunReplayedFromTheFileIsTheRunStored) {
  ReplayViewSource replay(Path("generated.h5"), 1);
  ASSERT_TRUE(replay.AdvanceTo(replay.stored_end_s()));
  while (replay.Step()) {
  }
  const size_t frames = replay.stored().record.frames();
  ASSERT_GT(frames, 100u);
  EXPECT_EQ(replay.frames_compared(), frames);
  EXPECT_EQ(replay.record().frames(), frames);
  EXPECT_EQ(replay.max_pos_px_difference(), 0.0);
  EXPECT_EQ(replay.DifferenceReport(),
            "largest pos_px difference from the stored run: 0 px over " + std::to_string(frames) + " frames");
  EXPECT_EQ(replay.Status(), "replay of run 1 of " + Path("generated.h5") + ": " + replay.DifferenceReport());
}

TEST_F(ReplayViewSourceTest, AStoredPositionThatDiffersIsReportedFromItsFrameOn) {
  // One coordinate of one pin in frame 300 moved by a quarter pixel.
  RunRecord run = StoredRun1();
  constexpr size_t kFrame = 300, kPin = 5;
  SensorRecord& sensor = run.sensors.front();
  float& x = sensor.pos_px[(kFrame * static_cast<size_t>(sensor.n_pins) + kPin) * 2];
  const float original = x;
  x += 0.25f;
  ReplayViewSource replay(WriteDataset("moved.h5", run), 1);
  // Half a frame after frame kFrame - 1, and after frame kFrame.
  ASSERT_TRUE(replay.AdvanceTo(run.time[kFrame - 1] + 0.005));
  EXPECT_EQ(replay.frames_compared(), kFrame);
  EXPECT_EQ(replay.max_pos_px_difference(), 0.0);
  ASSERT_TRUE(replay.AdvanceTo(run.time[kFrame] + 0.005));
  EXPECT_EQ(replay.frames_compared(), kFrame + 1);
  EXPECT_EQ(replay.max_pos_px_difference(), static_cast<double>(x) - static_cast<double>(original));
  EXPECT_NEAR(replay.max_pos_px_difference(), 0.25, 1e-4);
}

TEST_F(ReplayViewSourceTest, PinsShowTheStoredLabelsOfTheNearestFrame) {
  // Frame 10 (t = 0.1 s, long before the press reaches the object) stored as every pin slipping.
  RunRecord run = StoredRun1();
  SensorRecord& sensor = run.sensors.front();
  const size_t n = static_cast<size_t>(sensor.n_pins);
  std::fill_n(sensor.pin_contact.begin() + 10 * n, n, 1);
  std::fill_n(sensor.pin_slip.begin() + 10 * n, n, 1);
  ReplayViewSource replay(WriteDataset("labels.h5", run), 1);
  auto count = [&](const Rgba& colour) {
    int k = 0;
    for (const GeomColour& c : replay.Colours()) k += c.rgba == colour;
    return k;
  };
  const int pins = static_cast<int>(replay.pin_geoms().size());
  ASSERT_TRUE(replay.AdvanceTo(0.08));  // nearest frame: 8
  EXPECT_EQ(count(PinColours::kNoContact), pins);
  ASSERT_TRUE(replay.AdvanceTo(0.096));  // nearest frame: 10
  EXPECT_EQ(count(PinColours::kSlip), pins);
  EXPECT_EQ(replay.sensor().labels().n_slip, 0) << "the re-simulated pins do not slip";
  ASSERT_TRUE(replay.AdvanceTo(0.106));  // nearest frame: 11
  EXPECT_EQ(count(PinColours::kNoContact), pins);
}

TEST_F(ReplayViewSourceTest, ARunTheFileDoesNotHoldIsRefusedWithTheRunsItHolds) {
  const std::string path = Path("generated.h5");
  EXPECT_EQ(InputErrorOf([&] { ReplayViewSource(path, 2); }), "--run 2: " + path + " has no run 2 (it has runs 0-1)");
  const std::string one = WriteDataset("one.h5", StoredRun1());
  EXPECT_EQ(InputErrorOf([&] { ReplayViewSource(one, 0); }), "--run 0: " + one + " has no run 0 (it has run 1)");
  EXPECT_EQ(InputErrorOf([&] { ReplayViewSource(Path("missing.h5"), 0); }),
            "cannot open dataset '" + Path("missing.h5") + "': no such file");
}

TEST_F(ReplayViewSourceTest, AFileWhoseScenarioOrConfigCannotBeReSimulatedIsRefused) {
  const RunRecord run = StoredRun1();
  const std::string unknown =
      WriteDataset("unknown.h5", run, [](DatasetHeader& h) { h.scenario = "nonsense"; });
  EXPECT_EQ(InputErrorOf([&] { ReplayViewSource(unknown, 1); }),
            "--replay " + unknown + ": unknown scenario 'nonsense' (known: rail, incipient)");
  // A skin of 5 rings (91 pins) where the run stores the 6 rings' 127.
  const std::string other = WriteDataset("other_skin.h5", run, [](DatasetHeader& h) {
    h.config_yaml = ConfigToYaml(LoadConfig<RailScenarioConfig>("", {"skin.rings=5"}));
  });
  EXPECT_EQ(InputErrorOf([&] { ReplayViewSource(other, 1); }),
            "--replay " + other + ": run 1 stores 127 pins, but its config builds 91");
}

// `tactip view --replay`: refusals, before any display is needed and with nothing written.
class ViewReplayCliTest : public testing::CliFolderTest {
 protected:
  void Generate() {
    const auto r = Run("generate rail --runs 2 --seed 4 --jobs 1 --quiet --set rail.lift_mm=5 "
                       "--set rail.retract_speed_mm_s=5 --out " + P("d.h5"));
    ASSERT_EQ(r.code, 0) << r.err;
  }
  // Exit code 2 and exactly `message` (one line), and no file but the dataset.
  void ExpectRefused(const std::string& args, const std::string& message) {
    const auto r = Run("view " + args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, "tactip: " + message + "\n") << args;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1) << args;
  }
};

TEST_F(ViewReplayCliTest, AFileOrRunThatDoesNotExistOrATimeAfterItsEndIsRefused) {
  ASSERT_NO_FATAL_FAILURE(Generate());
  const std::string shot = " --screenshot " + P("r.png");
  ExpectRefused("--replay " + P("missing.h5") + shot, "cannot open dataset '" + P("missing.h5") + "': no such file");
  ExpectRefused("--replay " + P("d.h5") + " --run 5" + shot, "--run 5: " + P("d.h5") + " has no run 5 (it has runs 0-1)");
  const auto r = Run("view --replay " + P("d.h5") + " --run 1 --time 50" + shot);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("tactip: --time = 50: run 1 of " + P("d.h5") + " ends at t = ", 0), 0u) << r.err;
}

TEST_F(ViewReplayCliTest, AScreenshotOverTheReplayedFileIsRefused) {
  ASSERT_NO_FATAL_FAILURE(Generate());
  fs::rename(P("d.h5"), P("d.png"));
  ExpectRefused("--replay " + P("d.png") + " --screenshot " + P("d.png"),
                "--screenshot " + P("d.png") + ": is the --replay file; choose another name");
}

TEST_F(ViewReplayCliTest, WhatTheFileFixesCannotBeGivenToo) {
  ASSERT_NO_FATAL_FAILURE(Generate());
  const std::string replay = "--replay " + P("d.h5") + " --screenshot " + P("r.png");
  ExpectRefused("rail " + replay, "scenario excludes --replay (see --help)");
  ExpectRefused(replay + " --seed 3", "--seed excludes --replay (see --help)");
  ExpectRefused(replay + " --set rail.lift_mm=6", "--set excludes --replay (see --help)");
  ExpectRefused(replay + " --skin smooth", "--skin excludes --replay (see --help)");
  ExpectRefused("--screenshot " + P("r.png"), "view: give a scenario (see 'tactip scenarios') or --replay FILE.h5");
}

}  // namespace
}  // namespace tactip
