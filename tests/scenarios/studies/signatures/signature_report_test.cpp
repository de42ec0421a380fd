// The slip-signature figures of `tactip report signatures` on small hand-built runs whose
// answers are known: spike width, peak and co-linearity from the onset, contact loss,
// incipient visibility, amplitudes and alarm, the first-slipping sector, the acceptance
// counts and the n/a / none cells of the table and CSV.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenarios/studies/incipient_report/incipient_report.h"
#include "scenarios/studies/signatures/signature_report.h"
#include "sim/base/nan.h"

namespace tactip {
namespace {

constexpr double kFrameS = 0.01;        // 100 fps
constexpr double kSpeedTol = 1e-4;      // px/frame: float positions of a few hundred px
constexpr double kTimeTol = 1e-9;       // s: times are copied, not computed
constexpr double kNoisePx = 0.28;       // the camera's per-coordinate noise
constexpr unsigned kSignatureSeed = 13;

/// A run of `frames` frames of `pins` still pins on a 10 px grid, all valid and in contact,
/// with skin `skin`; retraction at frame 40.
RunRecord StillRun(int frames, int pins, const std::string& skin = "smooth") {
  RunRecord r;
  SensorRecord s;
  s.n_pins = pins;
  for (int f = 0; f < frames; ++f) {
    r.time.push_back(kFrameS * f);
    for (int i = 0; i < pins; ++i) {
      s.pos_px.push_back(static_cast<float>(300 + 10 * (i % 5)));
      s.pos_px.push_back(static_cast<float>(200 + 10 * (i / 5)));
    }
  }
  const auto tn = static_cast<size_t>(frames * pins);
  s.valid.assign(tn, 1);
  s.pin_contact.assign(tn, 1);
  s.pin_slip.assign(tn, 0);
  s.text_attrs["skin_pattern"] = skin;
  r.sensors.push_back(s);
  r.attrs["retract_start_s"] = 40 * kFrameS;
  return r;
}

/// Moves pin `pin` by (du, dv) px per frame over frames [first, end) and keeps the offset.
void MovePin(SensorRecord& s, int pin, int first, int end, double du, double dv) {
  const int frames = static_cast<int>(s.valid.size()) / s.n_pins;
  for (int f = first; f < frames; ++f) {
    const int steps = std::min(f, end - 1) - first + 1;
    s.pos_px[(f * s.n_pins + pin) * 2] += static_cast<float>(du * steps);
    s.pos_px[(f * s.n_pins + pin) * 2 + 1] += static_cast<float>(dv * steps);
  }
}

/// Adds the camera's Gaussian noise (fixed seed) to every position.
void AddNoise(SensorRecord& s) {
  std::mt19937 rng(kSignatureSeed);
  std::normal_distribution<float> noise(0.0f, static_cast<float>(kNoisePx));
  for (float& p : s.pos_px) p += noise(rng);
}

/// A gross-slip run: 20 noisy pins, onset at frame 100, every pin moving 1 px/frame down
/// (+v) for exactly 17 frames from the onset frame, contact lost 12 frames after it.
RunRecord GrossRun() {
  RunRecord r = StillRun(160, 20);
  r.attrs["gross_slip_onset_s"] = 100 * kFrameS - 0.004;  // between frames 99 and 100
  SensorRecord& s = r.sensors[0];
  for (int i = 0; i < s.n_pins; ++i) MovePin(s, i, 100, 117, 0.0, 1.0);
  for (size_t k = 112 * 20; k < s.pin_contact.size(); ++k) s.pin_contact[k] = 0;
  AddNoise(s);
  return r;
}

TEST(GrossSignatureTest, SpikeOfSeventeenFramesAboveNoiseHasWidthSeventeen) {
  const RunRecord r = GrossRun();
  const auto g = MeasureGrossSignature(r, r.sensors[0]);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->onset_frame, 100);
  EXPECT_EQ(g->spike_start_frame, 100);
  EXPECT_EQ(g->spike_width_frames, 17);
  // The held noise is the camera's: ~0.5 px/frame mean pin speed (1.77 sigma).
  EXPECT_NEAR(g->noise.mean_speed_px, 1.77 * kNoisePx, 0.05);
  EXPECT_LT(g->noise.mean_speed_w5_px, g->noise.mean_speed_px / 2);
}

TEST(GrossSignatureTest, AllPinsMovingTogetherAreCoLinearAndContactLossIsTimedFromTheOnset) {
  const RunRecord r = GrossRun();
  const auto g = MeasureGrossSignature(r, r.sensors[0]);
  ASSERT_TRUE(g.has_value());
  EXPECT_DOUBLE_EQ(g->colinear_onset, 1.0);
  EXPECT_DOUBLE_EQ(g->colinear_later, 1.0);
  EXPECT_NEAR(g->contact_lost_s, 112 * kFrameS - (100 * kFrameS - 0.004), kTimeTol);
  // The peaks: 1 px/frame plus noise unsmoothed; the smoothed one averages the noise out.
  EXPECT_GT(g->spike_peak_px, 1.0);
  EXPECT_NEAR(g->spike_peak_w5_px, 1.0, 0.2);
}

TEST(GrossSignatureTest, PatternStepIsTheSlideAndTheLaterWindowIsAsStillAsTheHeldOne) {
  const RunRecord r = GrossRun();
  const auto g = MeasureGrossSignature(r, r.sensors[0]);
  ASSERT_TRUE(g.has_value());
  // Every pin moved 17 px down between frames 90-99 and 120-129; the noise averages over
  // 20 pins x 10 frames.
  EXPECT_NEAR(g->step_px, 17.0, 0.1);
  // Frames 120-129 are still: their W5 speed is the held window's noise.
  EXPECT_NEAR(g->after_w5_px, g->noise.mean_speed_w5_px, 0.03);
}

TEST(GrossSignatureTest, PinsStillMovingAfterTheSpikeAreNotFlatAndMissedPinsAreLeftOut) {
  RunRecord r = StillRun(160, 20);
  r.attrs["gross_slip_onset_s"] = 100 * kFrameS;
  SensorRecord& s = r.sensors[0];
  // Every pin moves 3 px right on frames 100-109 and 0.5 px/frame from frame 115 on.
  for (int i = 0; i < 20; ++i) MovePin(s, i, 100, 110, 0.3, 0.0);
  for (int i = 0; i < 20; ++i) MovePin(s, i, 115, 160, 0.5, 0.0);
  // Pin 0 is missed before the onset: it has no loaded position and does not count.
  for (int f = 90; f < 100; ++f) s.valid[static_cast<size_t>(f * 20)] = 0;
  s.pos_px[90 * 20 * 2] = 0.0f;
  const auto g = MeasureGrossSignature(r, s);
  ASSERT_TRUE(g.has_value());
  // Frames 120-129 sit 3 + 0.5 x (6..15) px right of frames 90-99: 8.25 px on average.
  EXPECT_NEAR(g->step_px, 8.25, kSpeedTol * 10);
  EXPECT_NEAR(g->after_w5_px, 0.5, kSpeedTol);
}

TEST(GrossSignatureTest, StepNeedsBothWindowsInTheRecording) {
  RunRecord r = StillRun(125, 4);
  r.attrs["gross_slip_onset_s"] = 100 * kFrameS;
  const auto g = MeasureGrossSignature(r, r.sensors[0]);
  ASSERT_TRUE(g.has_value());
  EXPECT_TRUE(std::isnan(g->step_px));  // the recording ends at frame 124, before frame 129
  EXPECT_TRUE(std::isnan(g->after_w5_px));
  const std::vector<SignatureRun> runs = {MeasureSignatures(r, r.sensors[0], {})};
  EXPECT_TRUE(SignatureCsv(runs).ends_with(",none,none,n/a,n/a\n")) << SignatureCsv(runs);
}

TEST(GrossSignatureTest, SpikeStartsAtTheNextFrameWhenTheOnsetFrameIsStillStatic) {
  RunRecord r = StillRun(160, 20);
  r.attrs["gross_slip_onset_s"] = 100 * kFrameS;
  for (int i = 0; i < 20; ++i) MovePin(r.sensors[0], i, 101, 110, 1.0, 0.0);
  const auto g = MeasureGrossSignature(r, r.sensors[0]);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->spike_start_frame, 101);
  EXPECT_EQ(g->spike_width_frames, 9);
  EXPECT_TRUE(std::isnan(g->contact_lost_s));  // never lost in the recording: "none"
}

TEST(GrossSignatureTest, StillWindowIsTheConfiguredHoldUpToHalfASecond) {
  DatasetHeader h;
  h.config_yaml = "rail:\n  hold_s: 0.1\n";
  EXPECT_DOUBLE_EQ(HeldWindowS(h), 0.1);
  h.config_yaml = "rail:\n  hold_s: 2\n";
  EXPECT_DOUBLE_EQ(HeldWindowS(h), kHeldWindowS);
  h.config_yaml = "rail: {}\n";
  EXPECT_DOUBLE_EQ(HeldWindowS(h), kHeldWindowS);
  h.config_yaml = "rail: [\n";  // unreadable: the default
  EXPECT_DOUBLE_EQ(HeldWindowS(h), kHeldWindowS);
}

TEST(GrossSignatureTest, RunWithoutAnOnsetHasNoGrossSignature) {
  EXPECT_FALSE(MeasureGrossSignature(StillRun(50, 4), StillRun(50, 4).sensors[0]).has_value());
}

TEST(GrossSignatureTest, CoLinearShareCountsMovingPinsWithinThirtyDegreesOfTheirMeanDirection) {
  RunRecord r = StillRun(3, 10);
  for (int i = 0; i < 8; ++i) MovePin(r.sensors[0], i, 2, 3, 0.0, 2.0);
  MovePin(r.sensors[0], 8, 2, 3, 2.0, 0.0);
  MovePin(r.sensors[0], 9, 2, 3, -2.0, 0.0);
  EXPECT_DOUBLE_EQ(ColinearFraction(r.sensors[0], 2, 0.5), 0.8);
  EXPECT_TRUE(std::isnan(ColinearFraction(r.sensors[0], 1, 0.5)));  // nothing moves
}

/// Sensor of five pins: centre, east, west, south, north (image u right, v down).
SensorRecord CompassSensor(int frames) {
  RunRecord r = StillRun(frames, 5, "fingerprint-v2");
  SensorRecord s = r.sensors[0];
  const float offsets[5][2] = {{0, 0}, {50, 0}, {-50, 0}, {0, 50}, {0, -50}};
  for (int f = 0; f < frames; ++f) {
    for (int i = 0; i < 5; ++i) {
      s.pos_px[(f * 5 + i) * 2] = 320 + offsets[i][0];
      s.pos_px[(f * 5 + i) * 2 + 1] = 240 + offsets[i][1];
    }
  }
  return s;
}

/// Labels pin `pin` slipping from frame `first` on.
void SlipFrom(SensorRecord& s, int pin, int first) {
  for (size_t f = static_cast<size_t>(first); f < s.pin_slip.size() / 5; ++f) s.pin_slip[f * 5 + pin] = 1;
}

TEST(SlipSectorsTest, EastFirstRunOrdersTheSectorsByTheirFirstSlippingPin) {
  SensorRecord s = CompassSensor(30);
  SlipFrom(s, 1, 10);  // east
  SlipFrom(s, 2, 12);  // west
  SlipFrom(s, 3, 15);  // south; north never slips
  const SectorOrder o = OrderSlipSectors(s, 0, 30);
  EXPECT_EQ(o.first, "E");
  EXPECT_EQ(o.order, "E<W<S");
  EXPECT_TRUE(o.EastWestFirst());
  EXPECT_FALSE(o.EastWestTiedWithNorthSouth());
}

TEST(SlipSectorsTest, SectorsSlippingInTheSameFrameAreJoinedAndSouthFirstIsNotEastWest) {
  SensorRecord s = CompassSensor(30);
  SlipFrom(s, 3, 8);  // south
  SlipFrom(s, 4, 8);  // north
  SlipFrom(s, 1, 9);  // east
  const SectorOrder o = OrderSlipSectors(s, 0, 30);
  EXPECT_EQ(o.first, "S=N");
  EXPECT_EQ(o.order, "S=N<E");
  EXPECT_FALSE(o.EastWestFirst());
  EXPECT_FALSE(o.EastWestTiedWithNorthSouth());
  // East slipping in the same frame as north and south: a tie, not east/west first.
  SlipFrom(s, 1, 8);
  const SectorOrder tied = OrderSlipSectors(s, 0, 30);
  EXPECT_EQ(tied.first, "E=S=N");
  EXPECT_FALSE(tied.EastWestFirst());
  EXPECT_TRUE(tied.EastWestTiedWithNorthSouth());
  // Slip after the window's end is not counted.
  EXPECT_EQ(OrderSlipSectors(s, 0, 8).order, "");
}

TEST(SlipSectorsTest, FirstSlipStepsOrderSectorsThatShareAFrame) {
  // East, south and north all slip in frame 8; their first physics steps order them.
  SensorRecord s = CompassSensor(30);
  SlipFrom(s, 1, 8);  // east
  SlipFrom(s, 3, 8);  // south
  SlipFrom(s, 4, 8);  // north
  EXPECT_EQ(OrderSlipSectors(s, 0, 30).first, "E=S=N");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.pin_first_slip_s = {nan, 0.0795, nan, 0.0785, 0.0790};  // centre, E, W, S, N (frames every 10 ms)
  const SectorOrder steps = OrderSlipSectorsAtSteps(s, 0, 0.0, 0.30);
  EXPECT_TRUE(steps.at_steps);
  EXPECT_FALSE(OrderSlipSectors(s, 0, 30).at_steps);
  EXPECT_EQ(steps.first, "S");
  EXPECT_EQ(steps.order, "S<N<E");
  EXPECT_FALSE(steps.EastWestFirst());
  // Only the window [from_s, end_s) counts; equal steps tie as equal frames do.
  EXPECT_EQ(OrderSlipSectorsAtSteps(s, 0, 0.0786, 0.30).order, "N<E");
  EXPECT_EQ(OrderSlipSectorsAtSteps(s, 0, 0.0, 0.0790).order, "S");
  s.pin_first_slip_s[1] = 0.0785;
  const SectorOrder tied = OrderSlipSectorsAtSteps(s, 0, 0.0, 0.30);
  EXPECT_EQ(tied.first, "E=S");
  EXPECT_TRUE(tied.EastWestTiedWithNorthSouth());
  // A sensor without the first slips cannot be ordered by step.
  s.pin_first_slip_s.clear();
  EXPECT_THROW(OrderSlipSectorsAtSteps(s, 0, 0.0, 0.30), std::invalid_argument);
}

TEST(SlipSectorsTest, SouthBeforeNorthAndTheHardwareOrderNeedAStrictlyLaterFrame) {
  const auto order = [](const std::string& text) {
    SectorOrder o;
    o.order = text;
    return o;
  };
  // The hardware's order, east and west in either order or together.
  for (const char* text : {"E<W<S<N", "W<E<S<N", "E=W<S<N"}) {
    EXPECT_TRUE(order(text).HardwareOrder()) << text;
    EXPECT_TRUE(order(text).SouthBeforeNorth()) << text;
  }
  // South first, or a side after south, or ties across the steps: not the hardware's order.
  for (const char* text : {"S<E<W<N", "E<S<W<N", "E<W=S<N", "E=W<S=N", "E<W<N<S", "E<W<S", "W<S<N"}) {
    EXPECT_FALSE(order(text).HardwareOrder()) << text;
  }
  EXPECT_TRUE(order("S<E<W<N").SouthBeforeNorth());
  EXPECT_TRUE(order("E<S").SouthBeforeNorth());  // north never slipped
  EXPECT_FALSE(order("E<S=N").SouthBeforeNorth());
  EXPECT_FALSE(order("N<S").SouthBeforeNorth());
  EXPECT_FALSE(order("E<N").SouthBeforeNorth());  // south never slipped
  EXPECT_FALSE(order("").SouthBeforeNorth());
  // From a recording: east, west, south, north in successive frames.
  SensorRecord s = CompassSensor(30);
  SlipFrom(s, 1, 10);
  SlipFrom(s, 2, 10);
  SlipFrom(s, 3, 12);
  SlipFrom(s, 4, 14);
  const SectorOrder o = OrderSlipSectors(s, 0, 30);
  EXPECT_EQ(o.order, "E=W<S<N");
  EXPECT_TRUE(o.HardwareOrder());
}

TEST(SlipSectorsTest, MostCommonSectorOfAnAlarmSetJoinsTiesAndIsEmptyWithoutPins) {
  // Pins of CompassSensor: 0 centre, 1 east, 2 west, 3 south, 4 north. The sectors come
  // from the positions at the given frame relative to the contact's centroid.
  const SensorRecord s = CompassSensor(30);
  EXPECT_EQ(MostCommonSector(s, 0, {1}), "E");
  EXPECT_EQ(MostCommonSector(s, 0, {1, 2}), "E=W");
  EXPECT_EQ(MostCommonSector(s, 0, {2, 3}), "W=S");
  EXPECT_EQ(MostCommonSector(s, 0, {1, 2, 3, 4}), "E=W=S=N");
  EXPECT_EQ(MostCommonSector(s, 0, {}), "");
  EXPECT_EQ(MostCommonSector(s, 0, {0}), "-") << "the centre pin alone: an alarm set without a sector";
  EXPECT_EQ(MostCommonSector(s, 0, {0, 3}), "S") << "the centre pin does not vote";
  EXPECT_EQ(MostCommonSector(s, 30, {1}), "") << "a frame past the recording";
  EXPECT_TRUE(EastWestOnly("E=W"));
  EXPECT_TRUE(EastWestOnly("W"));
  EXPECT_FALSE(EastWestOnly("W=S"));
  EXPECT_FALSE(EastWestOnly("N"));
  EXPECT_FALSE(EastWestOnly(""));
  // Two pins in the south sector outvote one in the east.
  RunRecord r = StillRun(30, 6, "fingerprint-v2");
  SensorRecord six = r.sensors[0];
  const float offsets[6][2] = {{0, 0}, {50, 0}, {-50, 0}, {5, 50}, {-5, 60}, {0, -50}};
  for (int i = 0; i < 6; ++i) {
    six.pos_px[i * 2] = 320 + offsets[i][0];
    six.pos_px[i * 2 + 1] = 240 + offsets[i][1];
  }
  EXPECT_EQ(MostCommonSector(six, 0, {1, 3, 4}), "S");
}

TEST(SlipSectorsTest, ImageSectorIsTheDominantAxisWithVDownBeingSouth) {
  EXPECT_EQ(ImageSector(3, 1), 'E');
  EXPECT_EQ(ImageSector(-3, 1), 'W');
  EXPECT_EQ(ImageSector(1, 3), 'S');
  EXPECT_EQ(ImageSector(1, -3), 'N');
  EXPECT_EQ(ImageSector(2, 2), 'E');
  EXPECT_EQ(ImageSector(0, 0), '-');
}

/// An incipient run: 20 noise-free fingerprint pins on a 5 x 4 grid; retraction at frame
/// 40, the east column (pins 4, 9, 14, 19) labelled slipping from frame 60 and moving
/// 0.6 px/frame east until gross slip at frame 140; the object falls at frame 145.
RunRecord IncipientRun() {
  RunRecord r = StillRun(160, 20, "fingerprint-v2");
  r.attrs["incipient_onset_s"] = 60 * kFrameS;
  r.attrs["gross_slip_onset_s"] = 140 * kFrameS;
  r.attrs["object_fall_s"] = 145 * kFrameS;
  SensorRecord& s = r.sensors[0];
  for (int i = 4; i < 20; i += 5) {
    MovePin(s, i, 60, 140, 0.6, 0.0);
    for (int f = 60; f < 160; ++f) s.pin_slip[f * 20 + i] = 1;
  }
  return r;
}

TEST(IncipientSignatureTest, SlipBecomesVisibleOnceTheSmoothedExcessSpeedPassesTheThreshold) {
  const RunRecord r = IncipientRun();
  const auto s = MeasureIncipientSignature(r, r.sensors[0]);
  ASSERT_TRUE(s.has_value());
  // W = 5: the slipping pins' smoothed speed is 0.12 at frame 60, 0.24 > 0.2 from frame 61.
  EXPECT_NEAR(s->visible_s, 61 * kFrameS, kTimeTol);
  EXPECT_NEAR(s->visible_lead_s, 84 * kFrameS, kTimeTol);
  EXPECT_NEAR(s->amplitude_w1_px, 0.6, kSpeedTol);
  EXPECT_NEAR(s->amplitude_w5_px, 0.6, kSpeedTol);
  // Held for 5 frames: the steady 0.6 px/frame over a still bulk.
  EXPECT_NEAR(s->sustained_excess_px, 0.6, kSpeedTol);
  // The detector's bulk includes the slipping pins until they join the set: excess 0.192
  // at frame 61, 0.288 at frame 62, when its four pins meet I_thr = 4.
  EXPECT_NEAR(s->alarm_s, 62 * kFrameS, kTimeTol);
  EXPECT_NEAR(s->alarm_lead_s, 83 * kFrameS, kTimeTol);
  // The alarm's four pins are the four labelled slipping.
  EXPECT_EQ(s->alarm_pins.slipping, 4);
  EXPECT_EQ(s->alarm_pins.total(), 4);
  EXPECT_EQ(s->sectors.first, "E");
  EXPECT_TRUE(s->has_phase);
  EXPECT_FALSE(s->has_external);
  EXPECT_TRUE(std::isnan(s->tracking_correlation));
}

TEST(IncipientSignatureTest, SectorsAreOrderedByPhysicsStepWhenTheRunRecordsFirstSlips) {
  RunRecord r = IncipientRun();
  EXPECT_FALSE(MeasureIncipientSignature(r, r.sensors[0])->sectors.at_steps);  // no first slips recorded
  // One pin's first slip in the window, another's after the gross-slip onset (not counted).
  r.sensors[0].pin_first_slip_s.assign(20, std::numeric_limits<double>::quiet_NaN());
  r.sensors[0].pin_first_slip_s[4] = 59.5 * kFrameS;
  r.sensors[0].pin_first_slip_s[9] = 141 * kFrameS;
  const auto steps = MeasureIncipientSignature(r, r.sensors[0]);
  EXPECT_TRUE(steps->sectors.at_steps);
  EXPECT_EQ(steps->sectors.order.size(), 1u) << steps->sectors.order;
  // --sectors-by-frame: the frames' labels, as without the first slips.
  const auto frames = MeasureIncipientSignature(r, r.sensors[0], {}, /*sectors_by_frame=*/true);
  EXPECT_FALSE(frames->sectors.at_steps);
  EXPECT_EQ(frames->sectors.first, "E");
  // The report's option reaches it.
  SignatureOptions options;
  EXPECT_TRUE(MeasureSignatures(r, r.sensors[0], options).incipient->sectors.at_steps);
  options.sectors_by_frame = true;
  EXPECT_FALSE(MeasureSignatures(r, r.sensors[0], options).incipient->sectors.at_steps);
}

TEST(IncipientSignatureTest, IncipientReportAndSweepsOrderTheSectorsAsTheSignatureDoes) {
  // The compass pins in a run: retraction at frame 40, east and west slip in frame 45, south
  // in 47, north in 50, gross slip at 55.
  RunRecord r = StillRun(60, 5, "fingerprint-v2");
  r.sensors[0] = CompassSensor(60);
  r.sensors[0].pos_m.assign(r.sensors[0].valid.size() * 3, 0.0f);  // the report reads pin radii from it
  r.attrs["incipient_onset_s"] = 45 * kFrameS;
  r.attrs["gross_slip_onset_s"] = 55 * kFrameS;
  r.attrs["object_fall_s"] = 57 * kFrameS;
  for (const auto& [pin, frame] : {std::pair{1, 45}, {2, 45}, {3, 47}, {4, 50}}) SlipFrom(r.sensors[0], pin, frame);
  // A hand-built record without the true marker positions is refused, naming the array.
  RunRecord no_markers = r;
  no_markers.sensors[0].pos_m.clear();
  try {
    AnalyzeIncipientRun(no_markers, no_markers.sensors[0], {});
    ADD_FAILURE() << "a record without pos_m was analysed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("incipient analysis of run 0, sensor 'tactip': pos_m has 0 values, expected 900 = T*N*3"), std::string::npos) << e.what();
  }
  IncipientRunMetrics m = AnalyzeIncipientRun(r, r.sensors[0], {});
  EXPECT_EQ(m.sectors.order, "E=W<S<N");
  EXPECT_EQ(m.sectors.order, MeasureIncipientSignature(r, r.sensors[0])->sectors.order);
  EXPECT_FALSE(m.sectors.at_steps);
  // By physics step west comes first; so does it in the signature.
  r.sensors[0].pin_first_slip_s = {kNaN, 44.6 * kFrameS, 44.2 * kFrameS, 46.5 * kFrameS, 49.5 * kFrameS};
  m = AnalyzeIncipientRun(r, r.sensors[0], {});
  EXPECT_TRUE(m.sectors.at_steps);
  EXPECT_EQ(m.sectors.order, "W<E<S<N");
  EXPECT_EQ(m.sectors.order, MeasureIncipientSignature(r, r.sensors[0])->sectors.order);
  // The summary counts the runs; a run starting in the south counts only for south before north.
  IncipientRunMetrics south = m;
  south.sectors.order = "S<E=W<N";
  south.sectors.first = "S";
  const IncipientSummary sum = SummarizeIncipient({m, m, south});
  EXPECT_EQ(sum.east_west_first, 2);
  EXPECT_EQ(sum.south_before_north, 3);
  EXPECT_EQ(sum.hardware_order, 2);
  EXPECT_NE(FormatIncipientReport({m, m, south}, sum).find("first slip east/west in 2/3 runs, south before north in "
                                                           "3/3, east and west then south then north in 2/3"),
            std::string::npos);
  // The CSV ends with the order and the three flags.
  const std::string csv = IncipientCsv({m, south});
  EXPECT_NE(csv.find(",peak_speed_px,sector_order,east_west_first,south_before_north,hardware_order\n"),
            std::string::npos) << csv;
  EXPECT_NE(csv.find(",W<E<S<N,1,1,1\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",S<E=W<N,0,1,0\n"), std::string::npos) << csv;
}

/// A still 20-pin v2 run with its incipient onset at frame 60 and the fall at frame 145,
/// pin 0 labelled slipping on frames [slip_first, slip_end).
RunRecord PinZeroSlipsRun(int slip_first, int slip_end) {
  RunRecord r = StillRun(160, 20, "fingerprint-v2");
  r.attrs["incipient_onset_s"] = 60 * kFrameS;
  r.attrs["object_fall_s"] = 145 * kFrameS;
  for (int f = slip_first; f < slip_end; ++f) r.sensors[0].pin_slip[f * 20] = 1;
  return r;
}

TEST(IncipientSignatureTest, AlarmPinsAreCountedByTheirLabelsInTheAlarmFrame) {
  // Pins 0-3 move 0.6 px/frame from frame 60: pin 0 labelled slipping, pins 1 and 2 stuck,
  // pin 3 out of contact from frame 60. The detector alarms at frame 62 on all four.
  RunRecord r = PinZeroSlipsRun(60, 160);
  SensorRecord& sensor = r.sensors[0];
  for (int i = 0; i < 4; ++i) MovePin(sensor, i, 60, 145, 0.6, 0.0);
  for (int f = 60; f < 160; ++f) sensor.pin_contact[f * 20 + 3] = 0;
  const auto s = MeasureIncipientSignature(r, sensor);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->alarm_s, 62 * kFrameS, kTimeTol);
  EXPECT_EQ(s->alarm_pins.slipping, 1);
  EXPECT_EQ(s->alarm_pins.stuck, 2);
  EXPECT_EQ(s->alarm_pins.free, 1);
  const std::string text = FormatSignatureReport({MeasureSignatures(r, sensor, {})}, {});
  EXPECT_NE(text.find("   1/2/1 "), std::string::npos) << text;
  EXPECT_NE(text.find("alarm pins slip/stuck/free      1/2/1 of 4 in 1 runs (25 % slip)"), std::string::npos) << text;
}

TEST(IncipientSignatureTest, SlipTooSlowForTheCameraIsNeverVisible) {
  RunRecord r = PinZeroSlipsRun(60, 160);
  MovePin(r.sensors[0], 0, 60, 145, 0.1, 0.0);
  const auto s = MeasureIncipientSignature(r, r.sensors[0]);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(std::isnan(s->visible_s));
  EXPECT_TRUE(std::isnan(s->visible_lead_s));
  EXPECT_TRUE(std::isnan(s->alarm_s));
  EXPECT_EQ(s->alarm_pins.total(), 0);
  // No alarm: no pins to label in the table, the summary or the CSV.
  const std::vector<SignatureRun> runs = {MeasureSignatures(r, r.sensors[0], {})};
  const std::string text = FormatSignatureReport(runs, {});
  EXPECT_NE(text.find("alarm pins slip/stuck/free      no alarm"), std::string::npos) << text;
  EXPECT_NE(SignatureCsv(runs).find(",0.1,none,none,none,n/a,n/a,none,0.1\n"), std::string::npos) << SignatureCsv(runs);
  // How far from visible: 0.1 px/frame held, half the threshold; the one slipping pin is
  // also the best pin.
  EXPECT_NEAR(s->sustained_excess_px, 0.1, kSpeedTol);
  EXPECT_NEAR(s->pin_sustained_excess_px, 0.1, kSpeedTol);
}

TEST(IncipientSignatureTest, SustainedExcessIsTheBestValueHeldForTheWholeWindow) {
  // Pin 0 slips from frame 60 and jumps 2 px/frame on frames 70-72 only: its W5 speed is
  // 0.4, 0.8, 1.2, 1.2, 1.2, 0.8, 0.4 on frames 70-76, so the best 5-frame floor is 0.8.
  RunRecord r = PinZeroSlipsRun(60, 160);
  MovePin(r.sensors[0], 0, 70, 73, 2.0, 0.0);
  auto s = MeasureIncipientSignature(r, r.sensors[0]);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->amplitude_w5_px, 1.2, kSpeedTol);
  EXPECT_NEAR(s->sustained_excess_px, 0.8, kSpeedTol);
  EXPECT_NEAR(s->pin_sustained_excess_px, 0.8, kSpeedTol);
  EXPECT_NEAR(s->visible_s, 70 * kFrameS, kTimeTol);
  // Slipping on fewer consecutive frames than the window: no window to judge.
  RunRecord brief = PinZeroSlipsRun(70, 74);
  MovePin(brief.sensors[0], 0, 70, 73, 2.0, 0.0);
  s = MeasureIncipientSignature(brief, brief.sensors[0]);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(std::isnan(s->sustained_excess_px));
  EXPECT_TRUE(std::isnan(s->pin_sustained_excess_px));
  EXPECT_TRUE(std::isnan(s->visible_s));
}

TEST(IncipientSignatureTest, BestPinExcessSeesTheOneFastSlippingPinThatTheMeanHides) {
  // Pins 0-3 labelled slipping from frame 60; only pin 0 moves (0.6 px/frame). The slipping
  // pins' mean excess over the still bulk is 0.15, under s_thr: not visible; pin 0's is 0.6.
  RunRecord r = PinZeroSlipsRun(60, 160);
  for (int i = 1; i < 4; ++i) {
    for (int f = 60; f < 160; ++f) r.sensors[0].pin_slip[f * 20 + i] = 1;
  }
  MovePin(r.sensors[0], 0, 60, 145, 0.6, 0.0);
  const auto s = MeasureIncipientSignature(r, r.sensors[0]);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->sustained_excess_px, 0.15, kSpeedTol);
  EXPECT_TRUE(std::isnan(s->visible_s));
  EXPECT_NEAR(s->pin_sustained_excess_px, 0.6, kSpeedTol);
  // A pin moving while it is not labelled slipping does not count: pin 5 (stuck) at 1 px/frame.
  MovePin(r.sensors[0], 5, 60, 145, 1.0, 0.0);
  const auto stuck = MeasureIncipientSignature(r, r.sensors[0]);
  ASSERT_TRUE(stuck.has_value());
  // It raises the bulk (the 16 pins not slipping) by 1/16 px/frame instead.
  EXPECT_NEAR(stuck->pin_sustained_excess_px, 0.6 - 1.0 / 16.0, kSpeedTol);
}

TEST(IncipientSignatureTest, SmoothSkinAndRunsWithoutFallOrOnsetHaveNoIncipientSignature) {
  RunRecord smooth = IncipientRun();
  smooth.sensors[0].text_attrs["skin_pattern"] = "smooth";
  EXPECT_FALSE(MeasureIncipientSignature(smooth, smooth.sensors[0]).has_value());
  const RunRecord still = StillRun(50, 4, "fingerprint-v1");
  EXPECT_FALSE(MeasureIncipientSignature(still, still.sensors[0]).has_value());
}

/// A SignatureRun with only a gross signature of spike width `width`.
SignatureRun GrossOnly(int width) {
  SignatureRun r;
  r.gross = GrossSignature{};
  r.gross->spike_width_frames = width;
  return r;
}

/// A SignatureRun with only an incipient signature of the given leads and first sector.
SignatureRun IncipientOnly(double visible_lead_s, double alarm_lead_s, const std::string& first) {
  SignatureRun r;
  r.incipient = IncipientSignature{};
  r.incipient->visible_lead_s = visible_lead_s;
  r.incipient->alarm_lead_s = alarm_lead_s;
  r.incipient->sectors.first = first;
  return r;
}

TEST(SignatureAcceptanceTest, SpikeWidthNeedsFifteenFramesInEightyPercentOfRuns) {
  std::vector<SignatureRun> runs = {GrossOnly(20), GrossOnly(16), GrossOnly(15), GrossOnly(14), GrossOnly(3)};
  SignatureAcceptance a = JudgeSignatures(runs);
  EXPECT_EQ(a.spike_width.passed, 3);
  EXPECT_EQ(a.spike_width.runs, 5);
  EXPECT_EQ(a.spike_width.min_passed, 4);
  EXPECT_FALSE(a.spike_width.Pass());
  runs[3] = GrossOnly(15);
  EXPECT_TRUE(JudgeSignatures(runs).spike_width.Pass());
  EXPECT_EQ(a.visible_lead.runs, 0);
  EXPECT_FALSE(a.visible_lead.Pass());  // no run: nothing passes
}

TEST(SignatureAcceptanceTest, AlarmNeedsSeventeenOfTwentyAndVisibilityNinetyPercent) {
  std::vector<SignatureRun> runs;
  for (int i = 0; i < 20; ++i) runs.push_back(IncipientOnly(i < 18 ? 1.0 : kNaN, i < 17 ? 0.5 : 0.4, "E"));
  SignatureAcceptance a = JudgeSignatures(runs);
  EXPECT_EQ(a.alarm_lead.passed, 17);
  EXPECT_EQ(a.alarm_lead.min_passed, 17);
  EXPECT_TRUE(a.alarm_lead.Pass());
  EXPECT_EQ(a.visible_lead.passed, 18);
  EXPECT_EQ(a.visible_lead.min_passed, 18);
  EXPECT_TRUE(a.visible_lead.Pass());
  runs[0] = IncipientOnly(kNaN, kNaN, "S");
  a = JudgeSignatures(runs);
  EXPECT_FALSE(a.alarm_lead.Pass());
  EXPECT_FALSE(a.visible_lead.Pass());
  EXPECT_EQ(a.east_west_first.passed, 19);
  EXPECT_EQ(a.east_west_first.min_passed, 11);
  EXPECT_EQ(a.east_west_tied, 0);
  runs[1] = IncipientOnly(1.0, 0.5, "W=S");
  runs[2] = IncipientOnly(1.0, 0.5, "E=W=S=N");
  a = JudgeSignatures(runs);
  EXPECT_EQ(a.east_west_first.passed, 17);
  EXPECT_EQ(a.east_west_tied, 2);
  EXPECT_NE(FormatSignatureReport(runs, {}).find("E/W first 17 of 20, tied with S/N 2 (by frame)"),
            std::string::npos);
  // The summary says how the sectors were ordered.
  EXPECT_EQ(a.sectors_at_steps, 0);
  runs[3].incipient->sectors.at_steps = true;
  a = JudgeSignatures(runs);
  EXPECT_EQ(a.sectors_at_steps, 1);
  EXPECT_NE(FormatSignatureReport(runs, {}).find("tied with S/N 2 (by physics step in 1 of 20)"), std::string::npos);
  for (SignatureRun& r : runs) r.incipient->sectors.at_steps = true;
  EXPECT_NE(FormatSignatureReport(runs, {}).find("tied with S/N 2 (by physics step)"), std::string::npos);
  // South before north and the whole order are counted beside the acceptance.
  EXPECT_EQ(a.south_before_north, 0);
  runs[4].incipient->sectors.order = "E<W<S<N";
  runs[5].incipient->sectors.order = "S<E<W<N";
  runs[6].incipient->sectors.order = "E<N<S<W";
  a = JudgeSignatures(runs);
  EXPECT_EQ(a.south_before_north, 2);
  EXPECT_EQ(a.hardware_order, 1);
  EXPECT_NE(FormatSignatureReport(runs, {}).find("S before N 2 of 20; E and W, then S, then N 1 of 20"),
            std::string::npos);
}

TEST(SignatureReportTest, FiguresThatDoNotApplyPrintNotApplicableNotZero) {
  const RunRecord gross = GrossRun();
  RunRecord incipient = IncipientRun();
  incipient.index = 1;
  incipient.attrs.erase("gross_slip_onset_s");  // its window ends at the fall
  const std::vector<SignatureRun> runs = {MeasureSignatures(gross, gross.sensors[0], {}),
                                          MeasureSignatures(incipient, incipient.sensors[0], {})};
  const std::string text = FormatSignatureReport(runs, {});
  EXPECT_NE(text.find("internal/external correlation   n/a (no external markers)"), std::string::npos) << text;
  EXPECT_NE(text.find("spike width, frames             17 [17, 17] (1 of 1 runs)"), std::string::npos) << text;
  EXPECT_NE(text.find("E/W in most runs: 1/1, needs 1: PASS"), std::string::npos) << text;
  const std::string csv = SignatureCsv(runs);
  const std::string gross_row = csv.substr(csv.find('\n') + 1, csv.find('\n', csv.find('\n') + 1) - csv.find('\n'));
  EXPECT_EQ(gross_row.substr(0, 15), "0,none,smooth,0") << csv;
  EXPECT_NE(gross_row.find(",17,1,"), std::string::npos) << csv;
  EXPECT_NE(gross_row.find(",0.124,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,n/a,16.99"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find(",tracking_correlation,sustained_excess_px,alarm_pins_slipping,alarm_pins_stuck,alarm_pins_free,"
                     "step_px,after_w5_px,alarm_sector,pin_sustained_excess_px\n"),
            std::string::npos)
      << csv;
  // The incipient run's excess (its four pins' steady 0.6 px/frame) and its alarm's pins,
  // the last columns, and the summary.
  EXPECT_NE(csv.find(",E,E,n/a,0.6,4,0,0,n/a,n/a,E,0.6\n"), std::string::npos) << csv;
  EXPECT_EQ(gross_row.substr(gross_row.size() - 9), ",n/a,n/a\n") << csv;
  // Its alarm set is the same four pins: the camera's first-moving sector is east too.
  EXPECT_NE(text.find("first-moving sector (camera)    E/W 1 of 1 alarms"), std::string::npos) << text;
  EXPECT_NE(text.find("pattern step at gross slip, px  17."), std::string::npos) << text;
  EXPECT_NE(text.find("alarm pins slip/stuck/free      4/0/0 of 4 in 1 runs (100 % slip)"), std::string::npos) << text;
  EXPECT_NE(text.find("sustained excess, px/frame      0.60 [0.60, 0.60] (1 of 1 runs)"), std::string::npos) << text;
  EXPECT_NE(text.find("sustained excess, best pin      0.60 [0.60, 0.60] (1 of 1 runs)"), std::string::npos) << text;
}

TEST(SignatureReportTest, DatasetWithoutOnsetsSaysSoForBothSections) {
  const RunRecord still = StillRun(50, 4);
  const std::string text = FormatSignatureReport({MeasureSignatures(still, still.sensors[0], {})}, {});
  EXPECT_EQ(text,
            "gross slip: n/a (no run has a gross-slip onset)\n\nincipient slip: n/a (no fingerprint-skin run with a "
            "fall; hardware: a smooth skin shows no incipient slip); ground-truth incipient onset in 0 of 1 runs\n");
}

}  // namespace
}  // namespace tactip
