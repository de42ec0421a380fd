// A dataset in layout 1 (one sensor's arrays directly under each run, no layout_version),
// written by the tactip of that layout, reads as the same runs this tactip simulates, and
// the commands that read pins see the same frames in it.
//
// assets/fixtures/layout1_rail.h5 was written by the last tactip of layout 1 with
//   tactip generate rail <kFixtureArgs> --out layout1_rail.h5

#include <gtest/gtest.h>

#include <string>

#include "tests/scenarios/cli_helpers.h"
#include "run_records.h"
#include "sensors/dataset.h"

namespace tactip {
namespace {

using testing::CliFolderTest;
using testing::CliResult;
using testing::Slurp;

/// The fixture's job: two short runs of a 19-pin skin on acrylic with the external camera.
/// The fixture predates the gel field (skin.marker_model): its markers are the pin bodies';
/// the free sliding of fast contacts (sim.free_sliding_speed_mm_s) and the sliding step
/// (sim.sliding_timestep_s) and the gel's own shear modulus (skin.gel_shear_modulus_kpa: the
/// lumped shell's E_gel / 3 then) and the camera before the real-camera calibration
/// (--camera legacy: f = 580 px, independent 0.28 px noise).
const char* kFixtureArgs =
    "--camera legacy --set skin.marker_model=pins --set skin.gel_shear_modulus_kpa=0 --set sim.free_sliding_speed_mm_s=0 --set sim.sliding_timestep_s=0 --runs 2 --seed 5 --stimulus acrylic --set external.enabled=true --set skin.rings=2 "
    "--set sensor.frame_rate_hz=20 --set rail.lift_mm=5 --set rail.hold_s=0.1 --set rail.settle_s=0.1 "
    "--set rail.retract_speed_mm_s=5 --set rail.post_fall_s=0.1 --jobs 1 --quiet";

// `text` with its first `from` replaced by `to` (unchanged if `from` is absent).
std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

const std::string kFixture = std::string(TACTIP_SOURCE_DIR) + "/assets/fixtures/layout1_rail.h5";

class LayoutOneFixtureTest : public CliFolderTest {
 protected:
  void SetUp() override {
    CliFolderTest::SetUp();
    const CliResult g = Run(std::string("generate rail ") + kFixtureArgs + " --out " + P("now.h5"));
    ASSERT_EQ(g.code, 0) << g.err;
  }
};

TEST_F(LayoutOneFixtureTest, ReadsAsTheSameRunsThisVersionSimulates) {
  const DatasetReader old_file(kFixture), now(P("now.h5"));
  EXPECT_EQ(old_file.header().layout_version, 1);
  EXPECT_EQ(now.header().layout_version, 2);
  // The same config; this version has the gel field's keys, the gel's own shear modulus, the
  // free-sliding speed, the sliding step, the breakaway friction, the friction's slip memory, the shell's damper (and its
  // gel's loss tangent) and
  // the skin's rim, its membrane links and its normal springs, the pin-noise model and the structured model's sizes,
  // the marker camera of the hardware-style labels, the retraction speed range
  // (at the values that give the fixture's physics), adds the images
  // section (off, at its defaults) and lists the scene's sensors (the one default TacTip).
  std::string now_yaml = now.header().config_yaml;
  for (const std::string line :
       {"  marker_model: \"pins\"\n", "  gel_flow_depth_mm: 2.5\n", "  gel_squeeze_mm: 0.5\n",
        "  free_sliding_speed_mm_s: 0\n", "  sliding_timestep_s: 0\n", "  breakaway_ratio: 1\n", "  slip_memory_um: 0\n",
        "  shell_damping: \"viscous\"\n", "  gel_loss_tangent: 0.16\n", "  gel_shear_modulus_kpa: 0\n", "  rim: \"free\"\n",
        "  membrane_links: \"isotropic\"\n", "  normal_spring: \"axial\"\n", "  ridge_rocking: \"winkler\"\n",
        "  noise_model: \"independent\"\n", "  common_shift_px: 0.19\n", "  common_rotation_deg: 0.089\n",
        "  common_scale_pct: 0.15\n", "  common_time_s: 0.012\n", "  local_noise_px: 0.113\n",
        "  local_length_pitch: 1.2\n", "  retract_speed_max_mm_s: 0\n",
        "marker_camera:\n  frame_rate_hz: 30\n  mm_per_px: 0.3\n  jitter_px: 0.2\n  threshold_mm: 1\n  reference_s: 0.5\n"}) {
    const size_t at = now_yaml.find(line);
    ASSERT_NE(at, std::string::npos) << line;
    now_yaml.erase(at, line.size());
  }
  const std::string images =
      "images:\n  enabled: false\n  pin_tip_radius_mm: 0.5\n  skin_grey: 25\n  pin_grey: 225\n"
      "  rim_falloff_power: 4\n  blur_sigma_px: 1\n  noise_grey: 2\n  threshold_min: 60\n  threshold_max: 190\n"
      "  threshold_step: 32\n  min_blob_area_px: 12\n  max_blob_area_px: 2500\n  gate_px: 10\n";
  EXPECT_EQ(old_file.header().config_yaml + images + "sensors:\n  - name: \"tactip\"\n    offset_y_mm: 0\n", now_yaml);
  ASSERT_EQ(old_file.run_indices(), now.run_indices());
  for (const int k : now.run_indices()) {
    SCOPED_TRACE("run " + std::to_string(k));
    RunRecord expected = now.ReadRun(k);
    EXPECT_EQ(expected.actions.actuators.size(), 2u);
    expected.actions = {};  // layout 1 records no controller
    expected.attrs.erase("marker_onset_s");  // nor the hardware-style onset
    for (SensorRecord& s : expected.sensors) s.pin_first_slip_s.clear();  // nor the first slips (added later)
    RunRecord old_run = old_file.ReadRun(k);
    ASSERT_FALSE(old_run.sensors.at(0).external_px.empty());
    // This version's held pin speed also discounts the object's motion relative to the sensor
    // (docs/model.md, 'Run health'): it can only be lower, and the runs the fixture's version
    // flagged for it (run 0: 1.59 px/frame) are healthy now. Every other figure is unchanged.
    EXPECT_GE(old_run.attrs.at("held_pin_speed_px"), expected.attrs.at("held_pin_speed_px"));
    for (const char* key : {"held_pin_speed_px", "health_ok"}) old_run.attrs[key] = expected.attrs.at(key);
    old_run.text_attrs["health_reason"] = expected.text_attrs.at("health_reason");
    // This version dates the gross-slip onset back to the first step of the run of steps in
    // which every contacting pin slides that brings the object into motion (docs/model.md,
    // 'Ground truth'): at most one 2 ms step earlier here (run 0: 3.250 s, the fixture
    // 3.252 s), and the frames from it on are gross slip. Nothing else changes.
    const double onset = expected.attrs.at("gross_slip_onset_s"), old_onset = old_run.attrs.at("gross_slip_onset_s");
    EXPECT_LE(onset, old_onset);
    EXPECT_GE(onset, old_onset - 0.002 - 1e-9);
    SensorRecord& old_sensor = old_run.sensors.at(0);
    for (size_t f = 0; f < old_run.frames(); ++f) {
      if (old_run.time[f] >= onset - 1e-9 && old_run.time[f] < old_onset) old_sensor.gross_slip[f] = 1;
    }
    old_run.attrs["gross_slip_onset_s"] = onset;
    // The pins sliding from that step on slid in gross slip, so they no longer count as slipping
    // before it (run 0: the fixture's pre_slip_fraction 1, now 0; run 1 had 0).
    if (onset < old_onset) {
      EXPECT_EQ(old_run.attrs.at("pre_slip_fraction"), 1.0);
      old_run.attrs["pre_slip_fraction"] = 0.0;
    }
    ExpectSameRun(old_run, expected);
  }
}

TEST_F(LayoutOneFixtureTest, CommandsThatReadPinsSeeTheSameFrames) {
  for (const std::string& args : {std::string("detect incipient --contact-measure"), std::string("report incipient")}) {
    SCOPED_TRACE(args);
    const bool report = args.rfind("report", 0) == 0;
    const auto run = [&](const std::string& data, const std::string& out) {
      return Run(report ? args + " " + data + " --csv " + out : args + " --data " + data + " --out " + out);
    };
    const CliResult a = run(kFixture, P("old.csv")), b = run(P("now.h5"), P("now.csv"));
    ASSERT_EQ(a.code, 0) << a.err;
    ASSERT_EQ(b.code, 0) << b.err;
    // The one difference in what they read: run 0's onset, dated back one step (see above).
    // With it the frame at 3.250 s, whose pins all slide, leaves the incipient window, so
    // the report's sectors for run 0 (by frame, E=W=S=N, in the fixture) are none now, and its
    // pins no longer count as slipping before gross slip (pre 1 -> 0; the mean 0.50 -> 0.00).
    std::string old_csv = Replaced(Slurp(P("old.csv")), ",3.252,", ",3.25,");
    std::string old_out = Replaced(a.out, "     3.252 ", "     3.250 ");
    if (report) {
      old_csv = Replaced(Replaced(old_csv, ",E=W=S=N,", ",none,"), ",3.3,nan,nan,1,nan,", ",3.3,nan,nan,0,nan,");
      old_out = Replaced(Replaced(old_out, "   E=W=S=N\n", "         -\n"), "   1.00       -", "   0.00       -");
      old_out = Replaced(old_out, "pins slipping before gross slip 0.50", "pins slipping before gross slip 0.00");
    }
    EXPECT_EQ(old_csv, Slurp(P("now.csv")));
    EXPECT_EQ(old_out, b.out);
  }
  const CliResult info = Run("info " + kFixture);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("sensors      tactip: 19 pins, skin_pattern smooth (layout 1)\n"), std::string::npos)
      << info.out;
}

}  // namespace
}  // namespace tactip
