#include "scenarios/rail_catch/catch_report.h"
#include "sim/base/number_text.h"

#include <cmath>
#include <map>

#include <fmt/format.h>

namespace tactip {

namespace {

// The hardware's online catch (127-pin TacTip on the rail, 20 trials per row, mission.md):
// caught percentage and stopping distance per retraction speed on the flat stimulus, and
// the caught percentage per curved stimulus (14.3-15.6 mm).
std::string HardwareFigures(const std::string& stimulus, double speed_mm_s) {
  static const std::map<double, std::string> flat = {{0.1, "100 %, 15.5 mm"}, {1.0, "100 %, 17.6 mm"},
                                                     {3.0, "100 %, 18.7 mm"}, {5.0, "85 %, 22.0 mm"},
                                                     {10.0, "80 %, 24.8 mm"}, {20.0, "90 %, 26.9 mm"}};
  static const std::map<std::string, std::string> curved = {
      {"curved80", "90 %, 14.3-15.6 mm"}, {"curved40", "100 %, 14.3-15.6 mm"}, {"curved20", "95 %, 14.3-15.6 mm"}};
  if (stimulus == "flat") {
    for (const auto& [v, text] : flat) {
      if (std::abs(v - speed_mm_s) < 1e-9) return text;
    }
    return "";
  }
  const auto it = curved.find(stimulus);
  return it == curved.end() ? "" : it->second;
}

}  // namespace

std::string CatchTrialsCsv(const std::vector<CatchTrial>& trials) {
  std::string out = "trial,stimulus,speed_mm_s,outcome,slip_distance_mm,onset_s,declared_s,delay_ms,classify_us\n";
  for (const CatchTrial& t : trials) {
    out += fmt::format("{},{},{},{},{},{},{},{},{}\n", t.trial, t.stimulus, NumberCell(t.speed_mm_s, "{:g}", "nan"),
                       ToString(t.outcome), NumberCell(t.slip_distance_mm, "{:.3f}", "nan"), NumberCell(t.onset_s, "{:.4f}", "nan"),
                       NumberCell(t.declared_s, "{:.4f}", "nan"), NumberCell(t.delay_ms, "{:.1f}", "nan"), NumberCell(t.classify_us, "{:.1f}", "nan"));
  }
  return out;
}

std::vector<CatchSummaryRow> SummariseCatch(const std::vector<CatchTrial>& trials) {
  std::vector<CatchSummaryRow> rows;
  std::vector<double> distance_sum;
  std::vector<int> caught;
  for (const CatchTrial& t : trials) {
    // The row of this trial's (stimulus, speed), made on first sight.
    size_t r = 0;
    while (r < rows.size() && !(rows[r].stimulus == t.stimulus && rows[r].speed_mm_s == t.speed_mm_s)) ++r;
    if (r == rows.size()) {
      rows.push_back({t.stimulus, t.speed_mm_s, 0, 0.0, 0.0, 0.0, 0.0, HardwareFigures(t.stimulus, t.speed_mm_s)});
      distance_sum.push_back(0.0);
      caught.push_back(0);
    }
    CatchSummaryRow& row = rows[r];
    ++row.trials;
    if (t.outcome == CatchOutcome::kCaught) {
      ++caught[r];
      distance_sum[r] += t.slip_distance_mm;
    }
    if (t.outcome == CatchOutcome::kFalsePositive) row.false_positive_pct += 1.0;
    if (t.outcome == CatchOutcome::kDropped) row.dropped_pct += 1.0;
  }
  for (size_t r = 0; r < rows.size(); ++r) {
    const double n = rows[r].trials;
    rows[r].caught_pct = 100.0 * caught[r] / n;
    rows[r].false_positive_pct *= 100.0 / n;
    rows[r].dropped_pct *= 100.0 / n;
    rows[r].mean_distance_mm = caught[r] ? distance_sum[r] / caught[r] : std::nan("");
  }
  return rows;
}

std::string FormatCatchTable(const std::vector<CatchSummaryRow>& rows) {
  std::string out = fmt::format("{:<10} {:>9} {:>7} {:>8} {:>9} {:>8} {:>12}   {}\n", "stimulus", "speed", "trials",
                                "caught", "false pos", "dropped", "distance", "hardware (caught, distance)");
  for (const CatchSummaryRow& r : rows) {
    out += fmt::format("{:<10} {:>4g} mm/s {:>7} {:>7.0f}% {:>8.0f}% {:>7.0f}% {:>9} mm   {}\n", r.stimulus,
                       r.speed_mm_s, r.trials, r.caught_pct, r.false_positive_pct, r.dropped_pct,
                       NumberCell(r.mean_distance_mm, "{:.1f}", "nan"), r.hardware.empty() ? "-" : r.hardware);
  }
  return out;
}

std::string CatchSummaryCsv(const std::vector<CatchSummaryRow>& rows) {
  std::string out = "stimulus,speed_mm_s,trials,caught_pct,false_positive_pct,dropped_pct,mean_distance_mm,hardware\n";
  for (const CatchSummaryRow& r : rows) {
    out += fmt::format("{},{:g},{},{:.1f},{:.1f},{:.1f},{},\"{}\"\n", r.stimulus, r.speed_mm_s, r.trials, r.caught_pct,
                       r.false_positive_pct, r.dropped_pct, NumberCell(r.mean_distance_mm, "{:.3f}", "nan"), r.hardware);
  }
  return out;
}

}  // namespace tactip
