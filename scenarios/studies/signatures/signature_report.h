#pragma once
// `tactip report signatures`: the hardware-comparable slip signatures of every run of a
// dataset (gross slip and incipient slip), the acceptance counts of issue 13, and their
// text table and CSV.

#include <optional>
#include <string>
#include <vector>

#include "detectors/incipient.h"
#include "scenarios/studies/signatures/gross_signature.h"
#include "scenarios/studies/signatures/incipient_signature.h"
#include "sensors/dataset.h"

namespace tactip {

/// A signature table's cell for a figure the run does not have (no gross or incipient phase).
inline constexpr const char* kNotApplicable = "n/a";

/// The signatures of one run as one sensor recorded them; nullopt = does not apply.
struct SignatureRun {
  int run = 0;                  ///< run index
  double speed_mm_s = 0.0;      ///< retract_speed_mm_s (NaN if absent)
  std::string skin;             ///< the sensor's skin_pattern ("" if absent)
  bool incipient_onset = false; ///< the run has a ground-truth incipient_onset_s
  std::optional<GrossSignature> gross;          ///< runs with a gross-slip onset
  std::optional<IncipientSignature> incipient;  ///< fingerprint runs with a fall or an incipient onset
};

/// What the signatures are measured with.
struct SignatureOptions {
  IncipientParams detector;              ///< the incipient detector (hardware values by default)
  double held_window_s = kHeldWindowS;   ///< still window of the noise, s (HeldWindowS of the dataset)
  /// Order the first-slipping sectors by the frames' labels even where the dataset has
  /// each pin's first slipping step (labels/pin_first_slip_s).
  bool sectors_by_frame = false;
};

/// Measures both signatures of `sensor`'s recording of `run`.
SignatureRun MeasureSignatures(const RunRecord& run, const SensorRecord& sensor, const SignatureOptions& options);

/// Runs meeting one acceptance threshold of issue 13 among the runs it applies to.
struct AcceptanceCount {
  int passed = 0;      ///< runs meeting the per-run threshold
  int runs = 0;        ///< runs the criterion applies to
  int min_passed = 0;  ///< runs needed to pass (from the required share of `runs`)
  /// True when some run applies and at least min_passed meet the threshold.
  bool Pass() const { return runs > 0 && passed >= min_passed; }
};

/// Spike width needed per run, frames.
constexpr int kAcceptedSpikeFrames = 15;
/// Lead before the fall needed per run for visibility and for the alarm, s.
constexpr double kAcceptedLeadS = 0.5;

/// The acceptance counts: spike width >= 15 frames in >= 80 % of gross runs; visible
/// >= 0.5 s before the fall in >= 90 % and alarm >= 0.5 s before in >= 17/20 of
/// incipient runs; first slip east/west in most (more than half) of them.
struct SignatureAcceptance {
  AcceptanceCount spike_width, visible_lead, alarm_lead, east_west_first;
  /// Incipient runs whose first frame (or step) of slip holds east or west together with
  /// south or north (not counted as east/west first: it cannot order them).
  int east_west_tied = 0;
  /// Incipient runs whose sectors were ordered by physics step (the rest by frame).
  int sectors_at_steps = 0;
  /// Incipient runs with south before north, and with the hardware's whole order (east
  /// and west, then south, then north); no acceptance threshold, reported beside it.
  int south_before_north = 0, hardware_order = 0;
  /// Incipient runs whose detector alarmed, and those whose alarm set lies mostly on the
  /// east and/or west sides (IncipientSignature::alarm_sector): the first-moving sector as
  /// the camera sees it, which is how the hardware's order was observed. No threshold.
  int alarmed = 0, east_west_alarm = 0;
};

/// Counts SignatureAcceptance over `runs`.
SignatureAcceptance JudgeSignatures(const std::vector<SignatureRun>& runs);

/// The per-run tables and the summary (median and range beside the hardware value and the
/// acceptance), "n/a" where a figure does not apply and "none" where its event did not
/// happen; the headings name the options.
std::string FormatSignatureReport(const std::vector<SignatureRun>& runs, const SignatureOptions& options);

/// One CSV row per run (columns documented in docs/fingerprint-skins.md 'Slip signatures against the
/// hardware'); "n/a" / "none" as in the table.
std::string SignatureCsv(const std::vector<SignatureRun>& runs);

}  // namespace tactip
