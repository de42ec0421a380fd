// Behaviour kept: a fixed set of runs — the rail on the flat and curved40 stimuli at two
// speeds, two sensors side by side, rendered images, the incipient scene with each skin, a
// rail-catch and an incipient-stop trial, each with the legacy camera, and runs with the
// default and the pose-dataset cameras — is simulated again and every array, label, event,
// attribute and controller action must equal, bit for bit, what the code produced when the
// digests in assets/fixtures/behaviour_digests.txt were recorded. A change that is meant to
// move a figure records them anew (TACTIP_WRITE_DIGESTS=1) and says why in its commit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "detectors/threshold.h"
#include "models/skin.h"
#include "scenarios/incipient_stop/stop_controller.h"
#include "scenarios/rail/rail.h"
#include "scenarios/rail_catch/catch_controller.h"
#include "scenarios/registry.h"
#include "sensors/camera_presets.h"
#include "sim/config.h"
#include "tests/temp_dir.h"

namespace tactip {
namespace {

const std::filesystem::path kDigestFile = std::filesystem::path(TACTIP_SOURCE_DIR) / "assets/fixtures/behaviour_digests.txt";

// FNV-1a over the bytes of `data` (64 bit), with the element count: enough to tell any
// changed bit of an array.
template <class T>
std::string Digest(const std::vector<T>& data) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  for (size_t i = 0; i < data.size() * sizeof(T); ++i) {
    h ^= bytes[i];
    h *= 1099511628211ULL;
  }
  return fmt::format("{} x{:016x}", data.size(), h);
}

std::string Real(double v) { return fmt::format("{:.17g}", v); }

// One line per array and per attribute of `rec`, each prefixed by `run`.
void DigestRecord(const RunRecord& rec, const std::string& run, std::vector<std::string>& out) {
  const auto line = [&](const std::string& key, const std::string& value) { out.push_back(run + " " + key + " " + value); };
  line("time", Digest(rec.time));
  line("object_height_m", Digest(rec.object_height_m));
  for (const auto& [key, value] : rec.attrs) line("attr." + key, Real(value));
  for (const auto& [key, value] : rec.text_attrs) line("text." + key, value);
  std::string actuators;
  for (const std::string& a : rec.actions.actuators) actuators += a + ",";
  line("actions.actuators", actuators);
  line("actions.controls", Digest(rec.actions.controls));
  for (const ControllerAction& a : rec.actions.list) line("actions.list", Real(a.time_s) + " " + a.what);
  for (const SensorRecord& s : rec.sensors) {
    const std::string p = "sensors/" + s.name + "/";
    line(p + "n_pins", std::to_string(s.n_pins));
    line(p + "pos_px", Digest(s.pos_px));
    line(p + "valid", Digest(s.valid));
    line(p + "pos_m", Digest(s.pos_m));
    line(p + "gross_slip", Digest(s.gross_slip));
    line(p + "pin_slip", Digest(s.pin_slip));
    line(p + "pin_contact", Digest(s.pin_contact));
    line(p + "incipient", Digest(s.incipient));
    line(p + "pin_first_slip_s", Digest(s.pin_first_slip_s));
    line(p + "external_px", Digest(s.external_px));
    line(p + "external_m", Digest(s.external_m));
    line(p + "normal_N", Digest(s.normal_N));
    line(p + "tangential_N", Digest(s.tangential_N));
    std::vector<std::uint8_t> images;
    for (const CompressedFrame& f : s.images) images.insert(images.end(), f.begin(), f.end());
    line(p + "images", Digest(images) + fmt::format(" {}x{} {} frames", s.image_width, s.image_height, s.images.size()));
    line(p + "detected_px", Digest(s.detected_px));
    line(p + "detected_valid", Digest(s.detected_valid));
    for (const auto& [key, value] : s.attrs) line(p + "attr." + key, Real(value));
    for (const auto& [key, value] : s.text_attrs) line(p + "text." + key, value);
  }
}

// What drives the arm in a case.
enum class Loop { kOffline, kCatch, kStop };

struct DigestCase {
  std::string name;
  std::string scenario;                // "rail" or "incipient"
  std::string skin;                    // preset, or empty: the scenario's
  std::vector<std::string> overrides;  // --set, in order
  Loop loop = Loop::kOffline;
  // --camera preset. The cases recorded before the real-camera calibration keep the camera
  // they were recorded with (legacy: f = 580 px, independent noise); the *-tactip-camera and
  // *-pose-camera cases run the default camera and the pose-dataset crop.
  std::string camera = "legacy";
};

// gtest prints a case by its name.
void PrintTo(const DigestCase& c, std::ostream* os) { *os << c.name; }

// Short protocols (a 10 mm lift, retraction at 1-5 mm/s): each case takes seconds.
const std::vector<DigestCase>& Cases() {
  static const std::vector<DigestCase> cases = {
      {"rail-flat-1mm_s", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}},
      {"rail-flat-5mm_s", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=5"}},
      {"rail-curved40-1mm_s", "rail", "", {"rail.stimulus=curved40", "rail.lift_mm=10", "rail.retract_speed_mm_s=1"}},
      {"rail-curved40-5mm_s", "rail", "", {"rail.stimulus=curved40", "rail.lift_mm=10", "rail.retract_speed_mm_s=5"}},
      {"rail-two-sensors", "rail", "",
       {"rail.lift_mm=10", "rail.retract_speed_mm_s=5", "sensors.0.offset_y_mm=-30", "sensors.1.name=right",
        "sensors.1.offset_y_mm=30"}},
      {"rail-images", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=5", "images.enabled=true"}},
      {"incipient-smooth", "incipient", "smooth", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}},
      {"incipient-fingerprint-v1", "incipient", "fingerprint-v1", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}},
      {"incipient-fingerprint-v2", "incipient", "fingerprint-v2", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}},
      {"rail-catch-threshold", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}, Loop::kCatch},
      {"incipient-stop-v2", "incipient", "fingerprint-v2", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}, Loop::kStop},
      {"rail-flat-1mm_s-tactip-camera", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}, Loop::kOffline,
       "tactip-640x480"},
      {"rail-images-tactip-camera", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=5", "images.enabled=true"},
       Loop::kOffline, "tactip-640x480"},
      {"rail-images-pose-camera", "rail", "", {"rail.lift_mm=10", "rail.retract_speed_mm_s=5", "images.enabled=true"},
       Loop::kOffline, "pose-dataset-256"},
      {"incipient-stop-v2-tactip-camera", "incipient", "fingerprint-v2",
       {"rail.lift_mm=10", "rail.retract_speed_mm_s=1"}, Loop::kStop, "tactip-640x480"},
  };
  return cases;
}

constexpr std::uint64_t kDigestSeed = 11;
constexpr double kCatchThresholdPx = 0.3;

// The case's config, as `tactip generate SCENARIO --skin SKIN --camera CAMERA --set ...`
// resolves it.
RailScenarioConfig CaseConfig(const DigestCase& c) {
  ConfigSource src;
  if (!c.skin.empty()) src.overrides = SkinPresetOverrides(c.skin);
  for (const std::string& o : CameraPreset(c.camera)) src.overrides.push_back(o);
  for (const std::string& o : c.overrides) src.overrides.push_back(o);
  return RailFamily(FindScenario(c.scenario)).Load(src);
}

// Run 0 of the case, simulated as its protocol runs it.
RunRecord Simulate(const DigestCase& c, const std::filesystem::path& dir) {
  RailScenarioConfig cfg = CaseConfig(c);
  RunRecord rec;
  if (c.loop == Loop::kOffline) {
    RailScenario(cfg).Run(0, kDigestSeed, rec);
    return rec;
  }
  if (c.loop == Loop::kCatch) {
    // As RunCatchTrials runs a trial.
    const std::string model = (dir / "threshold.model").string();
    ThresholdDetector(kCatchThresholdPx).Save(model);
    cfg.rail.post_fall_s = std::max(cfg.rail.post_fall_s, 2.0);
    SceneOptions every_pin;
    every_pin.all_pins_collide = true;
    const CatchOptions loop;
    RailScenario(cfg, every_pin).Run(0, kDigestSeed, rec, nullptr, [&](int, const RailSchedule& schedule) {
      return std::unique_ptr<RailController>(std::make_unique<CatchController>(schedule, LoadDetector(model), loop));
    });
    return rec;
  }
  // As RunStopTrials runs a trial.
  const StopOptions loop;
  RailScenario(cfg).Run(0, kDigestSeed, rec, nullptr, [&](int, const RailSchedule& schedule) {
    return std::unique_ptr<RailController>(std::make_unique<StopController>(schedule, loop));
  });
  return rec;
}

std::vector<std::string> CaseLines(const DigestCase& c, const std::filesystem::path& dir) {
  std::vector<std::string> lines;
  DigestRecord(Simulate(c, dir), c.name, lines);
  return lines;
}

// The recorded lines of case `name`.
std::vector<std::string> RecordedLines(const std::string& name) {
  std::ifstream in(kDigestFile);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(name + " ", 0) == 0) lines.push_back(line);
  }
  return lines;
}

// Every line that differs, as "- recorded" / "+ now", at most `limit` of them.
std::string Differences(const std::vector<std::string>& recorded, const std::vector<std::string>& now, size_t limit = 12) {
  std::string out;
  size_t shown = 0;
  const size_t n = std::max(recorded.size(), now.size());
  for (size_t i = 0; i < n && shown < limit; ++i) {
    const std::string a = i < recorded.size() ? recorded[i] : "(none)";
    const std::string b = i < now.size() ? now[i] : "(none)";
    if (a == b) continue;
    out += "\n- " + a + "\n+ " + b;
    ++shown;
  }
  return out;
}

class BehaviourDigestTest : public ::testing::TestWithParam<DigestCase> {};

TEST_P(BehaviourDigestTest, EveryArrayLabelEventAndAttributeIsAsRecorded) {
  const DigestCase& c = GetParam();
  testing::TestTempDir dir("digest");
  const std::vector<std::string> now = CaseLines(c, dir.path());
  if (const char* write = std::getenv("TACTIP_WRITE_DIGESTS"); write != nullptr && std::strcmp(write, "1") == 0) {
    // Record: replace this case's lines, keep the others'.
    std::vector<std::string> kept;
    {
      std::ifstream in(kDigestFile);
      std::string line;
      while (std::getline(in, line)) {
        if (line.rfind(c.name + " ", 0) != 0) kept.push_back(line);
      }
    }
    std::ofstream out(kDigestFile);
    for (const std::string& l : kept) out << l << "\n";
    for (const std::string& l : now) out << l << "\n";
    GTEST_SKIP() << "recorded " << now.size() << " lines of " << c.name << " in " << kDigestFile;
  }
  const std::vector<std::string> recorded = RecordedLines(c.name);
  ASSERT_FALSE(recorded.empty()) << "no digests of case " << c.name << " in " << kDigestFile;
  EXPECT_EQ(recorded, now) << "case " << c.name << " changed:" << Differences(recorded, now);
}

INSTANTIATE_TEST_SUITE_P(FixedRuns, BehaviourDigestTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<DigestCase>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace tactip
