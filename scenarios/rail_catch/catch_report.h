#pragma once
// The rail catch's results: one CSV row per trial, and a table in the shape of the
// hardware's (per stimulus and retraction speed: caught / false positive / dropped and the
// slip distance), with the hardware's figures beside.

#include <string>
#include <vector>

#include "scenarios/rail_catch/catch_trials.h"

namespace tactip {

/// trials.csv: header `trial,stimulus,speed_mm_s,outcome,slip_distance_mm,onset_s,declared_s,delay_ms,classify_us`,
/// one row per trial ("nan" for an event that did not happen).
std::string CatchTrialsCsv(const std::vector<CatchTrial>& trials);

/// One row of the summary: the trials of one (stimulus, speed).
struct CatchSummaryRow {
  std::string stimulus;
  double speed_mm_s = 0.0;
  int trials = 0;
  double caught_pct = 0.0, false_positive_pct = 0.0, dropped_pct = 0.0;
  double mean_distance_mm = 0.0;  ///< mean slip distance of the caught trials (NaN: none caught)
  std::string hardware;           ///< the hardware's figures for this row, or ""
};

/// Groups trials by (stimulus, speed), in the order they first appear.
std::vector<CatchSummaryRow> SummariseCatch(const std::vector<CatchTrial>& trials);

/// The summary as a text table (what `tactip run rail-catch` prints and writes to summary.txt).
std::string FormatCatchTable(const std::vector<CatchSummaryRow>& rows);

/// The summary as CSV (summary.csv).
std::string CatchSummaryCsv(const std::vector<CatchSummaryRow>& rows);

}  // namespace tactip
