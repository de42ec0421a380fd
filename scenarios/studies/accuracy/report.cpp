// The accuracy study's table and CSV.

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "scenarios/studies/accuracy/study.h"

namespace tactip {

namespace {

// A number for the table: "-" for NaN, "inf" for a missed event.
std::string Cell(double v, const char* spec) {
  if (std::isnan(v)) return "-";
  if (std::isinf(v)) return "missed";
  return fmt::format(fmt::runtime(spec), v);
}

// A number for the CSV: empty for NaN, "inf" kept.
std::string CsvNumber(double v) {
  if (std::isnan(v)) return "";
  if (std::isinf(v)) return "inf";
  return fmt::format("{:.6g}", v);
}

std::string Quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string Overrides(const AccuracySetting& s) {
  std::string out;
  for (const auto& o : s.overrides) out += (out.empty() ? "" : " ") + o;
  return out;
}

}  // namespace

std::string FormatAccuracyTable(const AccuracyReport& r) {
  std::string out;
  const bool domes = r.scene == "domes";
  if (domes) {
    out += fmt::format("{:<20} {:>10} {:>12} {:>10} {:>8} {:>10} {:>8}  {}\n", "setting", "wall/sim", "release_err",
                       "gross_err", "band", "band_err", "healthy", "outcome");
    out += fmt::format("{:<20} {:>10} {:>12} {:>10} {:>8} {:>10} {:>8}\n", "", "s/s", "Q/muP", "Q/muP", "%", "%", "");
  } else {
    out += fmt::format("{:<18} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>7} {:>8} {:>7}  {}\n", "setting", "wall/sim",
                       "onset", "incip", "traj", "creep", "labels", "flicker", "coulomb", "healthy", "outcome");
    out += fmt::format("{:<18} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>7} {:>8} {:>7}\n", "", "s/s", "err ms",
                       "err ms", "rms px", "um", "diff %", "", "err ms", "");
  }
  for (const auto& row : r.rows) {
    const std::string name = row.setting.label + (row.setting.is_default ? " *" : "");
    const std::string note = row.outcome == "ok" ? "" : row.outcome;
    if (domes) {
      out += fmt::format("{:<20} {:>10} {:>12} {:>10} {:>8} {:>10} {:>8}  {}\n", name, Cell(row.wall_s_per_sim_s, "{:.3f}"),
                         Cell(row.release_error, "{:.4f}"), Cell(row.gross_error, "{:.4f}"),
                         Cell(100.0 * row.band_fraction, "{:.1f}"), Cell(100.0 * row.band_error, "{:.1f}"),
                         row.healthy ? "yes" : "no", note);
      continue;
    }
    out += fmt::format("{:<18} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>7} {:>8} {:>7}  {}\n", name,
                       Cell(row.wall_s_per_sim_s, "{:.3f}"), Cell(row.onset_error_ms, "{:.1f}"),
                       Cell(row.incipient_error_ms, "{:.1f}"), Cell(row.traj_rms_px, "{:.3f}"),
                       Cell(row.creep_um, "{:.2f}"), Cell(row.label_disagreement_pct, "{:.2f}"),
                       row.outcome == "ok" ? std::to_string(row.flicker_max) : "-", Cell(row.coulomb_error_ms, "{:.1f}"),
                       row.healthy ? "yes" : "no", note);
  }
  out += "(* the default; errors are against the reference row, coulomb against the Coulomb prediction of the "
         "same run)\n";
  return out;
}

std::string AccuracyCsv(const AccuracyReport& r) {
  std::string out =
      "setting,overrides,outcome,is_reference,is_default,healthy,wall_s_per_sim_s,onset_error_ms,incipient_error_ms,"
      "traj_rms_px,creep_um,label_disagreement_pct,flicker_max,coulomb_error_ms,release_error,gross_error,"
      "band_fraction,band_error\n";
  for (const auto& row : r.rows) {
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", Quoted(row.setting.label),
                       Quoted(Overrides(row.setting)), Quoted(row.outcome), row.setting.is_reference ? 1 : 0,
                       row.setting.is_default ? 1 : 0, row.healthy ? 1 : 0, CsvNumber(row.wall_s_per_sim_s),
                       CsvNumber(row.onset_error_ms), CsvNumber(row.incipient_error_ms), CsvNumber(row.traj_rms_px),
                       CsvNumber(row.creep_um), CsvNumber(row.label_disagreement_pct),
                       row.outcome == "ok" ? std::to_string(row.flicker_max) : "", CsvNumber(row.coulomb_error_ms),
                       CsvNumber(row.release_error), CsvNumber(row.gross_error), CsvNumber(row.band_fraction),
                       CsvNumber(row.band_error));
  }
  return out;
}

}  // namespace tactip
