// The tables behind `tactip plot`: every figure's CSV checked against a small run worked
// by hand (3 pins, 6 frames).

#include "scenarios/figures/run_tables.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/base/nan.h"
#include "tests/scenarios/csv_table.h"
#include "input_error.h"

namespace tactip {
namespace {

using testing::Num;
using testing::ParseCsv;

/// CSV cells carry 9 significant digits (px values of a few hundred).
constexpr double kTableCellTol = 1e-6;
/// Axial displacements come from float metres (~0.01 m): a few 1e-7 mm of rounding each.
constexpr double kAxialTolMm = 1e-5;
const ImageCentre kCentre{320.0, 240.0};

/// A run worked by hand. Pins at rest (frames 0–2): 0 at the centre (320, 240), 1 at
/// (330, 240) (radius 10), 2 at (320, 260) (radius 20). At frame 3 pin 1 moves by (3, 4) and
/// pin 2 by (0, 3); they stay there. Pins 0 and 1 touch from frame 2 and are pushed in along
/// the axis by 1, 1.5, 1.5, 2 mm at frames 2–5; pin 2 never moves along it. Gross slip at
/// 0.035 s (frame 4), no incipient slip, fall at 0.05 s (frame 5).
RunRecord HandRun() {
  constexpr int kT = 6, kN = 3;
  RunRecord run;
  SensorRecord s;
  s.n_pins = kN;
  const double inward_mm[kT] = {0, 0, 1, 1.5, 1.5, 2};
  for (int f = 0; f < kT; ++f) {
    run.time.push_back(0.01 * f);
    const bool moved = f >= 3;
    for (const auto& [u, v] : {std::pair{320.0, 240.0}, std::pair{moved ? 333.0 : 330.0, moved ? 244.0 : 240.0},
                               std::pair{320.0, moved ? 263.0 : 260.0}}) {
      s.pos_px.push_back(static_cast<float>(u));
      s.pos_px.push_back(static_cast<float>(v));
      s.external_px.push_back(static_cast<float>(640.0 - u));  // mirrored, as the external camera
      s.external_px.push_back(static_cast<float>(v));
    }
    for (int i = 0; i < kN; ++i) {
      const double x_m = 0.010 - (i < 2 ? inward_mm[f] * 1e-3 : 0.0);
      s.pos_m.insert(s.pos_m.end(), {static_cast<float>(x_m), 0.0f, 0.0f});
      s.pin_contact.push_back(f >= 2 && i < 2 ? 1 : 0);
      s.normal_N.push_back(f >= 2 && i < 2 ? 0.5f : 0.0f);
    }
    s.gross_slip.push_back(f >= 4 ? 1 : 0);
    s.incipient.push_back(0);
  }
  run.sensors.push_back(s);
  run.attrs["gross_slip_onset_s"] = 0.035;
  run.attrs["incipient_onset_s"] = kNaN;
  run.attrs["object_fall_s"] = 0.05;
  return run;
}

TEST(RunTablesTest, EventsCsvGivesEachEventsTimeAndFrameAndEmptyCellsForOneThatDidNotHappen) {
  const auto rows = ParseCsv(EventsCsv(HandRun()));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].at("event"), "gross_slip_onset");
  EXPECT_NEAR(Num(rows[0], "time_s"), 0.035, kTableCellTol);
  EXPECT_EQ(rows[0].at("frame"), "4");  // first frame at or after 0.035 s
  EXPECT_EQ(rows[1].at("event"), "incipient_onset");
  EXPECT_EQ(rows[1].at("time_s"), "");
  EXPECT_EQ(rows[1].at("frame"), "");
  EXPECT_EQ(rows[2].at("frame"), "5");
}

TEST(RunTablesTest, RepresentativePinsAreCentreMidRadiusOutermostAndFarthestMovingEachOnce) {
  const RunRecord run = HandRun();
  const std::vector<ShownPin> pins = RepresentativePins(run.sensors[0], kCentre);
  ASSERT_EQ(pins.size(), 3u);
  EXPECT_EQ(pins[0].pin, 0);
  EXPECT_EQ(pins[0].role, "centre");
  EXPECT_EQ(pins[1].pin, 1);  // radius 10 = half of 20, and it moves 5 px (pin 2: 3 px)
  EXPECT_EQ(pins[1].role, "mid radius and farthest moving");
  EXPECT_EQ(pins[2].pin, 2);
  EXPECT_EQ(pins[2].role, "outermost");
}

TEST(RunTablesTest, MotionCsvHasDisplacementsFromTheFirstFrameAndFrameToFrameSpeeds) {
  const RunRecord run = HandRun();
  const auto pins = RepresentativePins(run.sensors[0], kCentre);
  const auto rows = ParseCsv(MotionCsv(run, run.sensors[0], pins));
  ASSERT_EQ(rows.size(), 6u);
  // Frame 0: no speed yet.
  EXPECT_EQ(rows[0].at("mean_speed_px_frame"), "");
  EXPECT_EQ(Num(rows[0], "mean_disp_px"), 0.0);
  // Frame 3: pin 1 has moved 5 px, pin 2 3 px, in this frame.
  EXPECT_NEAR(Num(rows[3], "mean_disp_px"), 8.0 / 3.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[3], "pin1_disp_px"), 5.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[3], "pin2_disp_px"), 3.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[3], "mean_speed_px_frame"), 8.0 / 3.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[3], "max_speed_px_frame"), 5.0, kTableCellTol);
  // Frame 4: still displaced, no longer moving; the gross-slip label is on.
  EXPECT_NEAR(Num(rows[4], "mean_disp_px"), 8.0 / 3.0, kTableCellTol);
  EXPECT_EQ(Num(rows[4], "max_speed_px_frame"), 0.0);
  EXPECT_EQ(rows[4].at("gross_slip"), "1");
  EXPECT_EQ(rows[3].at("gross_slip"), "0");
}

TEST(RunTablesTest, QuiverFramesSurroundTheGrossOnsetElseTheIncipientOnsetElseThePeakSpeed) {
  RunRecord run = HandRun();
  QuiverFrames q = ChooseQuiverFrames(run, run.sensors[0]);
  EXPECT_EQ(q.onset_name, "gross-slip onset");
  EXPECT_EQ(q.at, 4);
  EXPECT_EQ(q.before, 1);  // 4 − 3
  EXPECT_EQ(q.after, 5);   // 4 + 3, clamped to the last frame
  run.attrs["gross_slip_onset_s"] = kNaN;
  run.attrs["incipient_onset_s"] = 0.02;
  q = ChooseQuiverFrames(run, run.sensors[0]);
  EXPECT_EQ(q.onset_name, "incipient onset");
  EXPECT_EQ(q.at, 2);
  run.attrs["incipient_onset_s"] = kNaN;
  q = ChooseQuiverFrames(run, run.sensors[0]);
  EXPECT_EQ(q.onset_name, "peak mean pin speed");
  EXPECT_EQ(q.at, 3);
  EXPECT_NEAR(q.onset_s, 0.03, 1e-12);
}

TEST(RunTablesTest, QuiverCsvHoldsEachPinsPositionAndVelocityInTheThreeFrames) {
  const RunRecord run = HandRun();
  QuiverFrames q;
  q.before = 1, q.at = 3, q.after = 5;
  const auto rows = ParseCsv(QuiverCsv(run, run.sensors[0], q));
  ASSERT_EQ(rows.size(), 9u);  // 3 panels × 3 pins
  const auto& pin1_at = rows[4];
  EXPECT_EQ(pin1_at.at("panel"), "at");
  EXPECT_EQ(pin1_at.at("frame"), "3");
  EXPECT_EQ(pin1_at.at("pin"), "1");
  EXPECT_NEAR(Num(pin1_at, "u_px"), 333.0, kTableCellTol);
  EXPECT_NEAR(Num(pin1_at, "du_px"), 3.0, kTableCellTol);
  EXPECT_NEAR(Num(pin1_at, "dv_px"), 4.0, kTableCellTol);
  EXPECT_EQ(pin1_at.at("contact"), "1");
  EXPECT_EQ(rows[7].at("panel"), "after");
  EXPECT_EQ(Num(rows[7], "du_px"), 0.0);
}

TEST(RunTablesTest, QuiverFramesOfARunOfOneFrameAreRefused) {
  RunRecord run = HandRun();
  run.time.resize(1);
  EXPECT_THROW(ChooseQuiverFrames(run, run.sensors[0]), InputError);
}

TEST(RunTablesTest, MarkersCsvComparesInternalAndExternalMeansAndNeedsExternalMarkers) {
  RunRecord run = HandRun();
  const auto rows = ParseCsv(MarkersCsv(run, run.sensors[0]));
  ASSERT_EQ(rows.size(), 6u);
  // The mirrored external markers move by the same distances.
  EXPECT_NEAR(Num(rows[3], "internal_disp_px"), 8.0 / 3.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[3], "external_disp_px"), 8.0 / 3.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[3], "external_speed_px_frame"), 8.0 / 3.0, kTableCellTol);
  EXPECT_EQ(rows[0].at("internal_speed_px_frame"), "");
  run.sensors[0].external_px.clear();
  EXPECT_THROW(MarkersCsv(run, run.sensors[0]), std::logic_error);
}

TEST(RunTablesTest, DeepestPressIsSoughtBeforeTheOnsetAndRestIsTheFrameBeforeTheFirstContact) {
  RunRecord run = HandRun();
  const ChosenFrame deepest = DeepestPressFrame(run, run.sensors[0]);
  EXPECT_EQ(deepest.frame, 3);  // frame 5 is deeper, but the onset is at frame 4
  EXPECT_EQ(deepest.reason, "deepest press before the onset");
  EXPECT_EQ(RestFrame(run.sensors[0]), 1);
  run.attrs["gross_slip_onset_s"] = kNaN;
  EXPECT_EQ(DeepestPressFrame(run, run.sensors[0]).frame, 5);
}

TEST(RunTablesTest, IndentationCsvHasRadialImageAndAxialDisplacementsAgainstTheRestFrame) {
  const RunRecord run = HandRun();
  const auto rows = ParseCsv(IndentationCsv(run.sensors[0], 1, 3, kCentre));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(Num(rows[0], "rest_radius_px"), 0.0, kTableCellTol);
  EXPECT_EQ(Num(rows[0], "radial_disp_px"), 0.0);  // at the centre: no radial direction
  EXPECT_NEAR(Num(rows[0], "axial_in_mm"), 1.5, kAxialTolMm);
  EXPECT_NEAR(Num(rows[1], "rest_radius_px"), 10.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[1], "radial_disp_px"), 3.0, kTableCellTol);  // (3, 4) along (1, 0)
  EXPECT_EQ(rows[1].at("contact"), "1");
  EXPECT_NEAR(Num(rows[1], "normal_N"), 0.5, kTableCellTol);
  EXPECT_NEAR(Num(rows[2], "rest_radius_px"), 20.0, kTableCellTol);
  EXPECT_NEAR(Num(rows[2], "radial_disp_px"), 3.0, kTableCellTol);  // (0, 3) along (0, 1)
  EXPECT_NEAR(Num(rows[2], "axial_in_mm"), 0.0, kAxialTolMm);
  EXPECT_EQ(rows[2].at("contact"), "0");
}

}  // namespace
}  // namespace tactip
