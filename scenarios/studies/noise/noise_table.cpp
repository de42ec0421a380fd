// The noise report's table, the real TacTip's figures beside it, and its CSV.

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scenarios/studies/noise/noise_structure.h"
#include "sim/base/nan.h"

namespace tactip {

namespace {

/// Widening of the real range within which a figure counts as matched.
constexpr double kFactor = 1.5;

/// One figure of the summary: its value in a row, the real range (a single value: lo = hi),
/// and how the band is widened (by kFactor, or by an absolute tolerance when tol > 0).
struct Figure {
  const char* name;
  double NoiseStructure::*field;
  double lo, hi, tol;
  const char* source;
};

// real-sensor section 6 (the noise of the still frames, 1-4 mm pressed) and section 2 (the
// thesis's pin-speed noise at 100 fps, W = 1 and W = 5; the acceptance tolerance).
const std::vector<Figure>& Figures() {
  static const std::vector<Figure> figures = {
      {"per-pin std, px", &NoiseStructure::pin_std_px, 0.29, 0.49, 0.0, "s6"},
      {"common mode / independent", &NoiseStructure::common_ratio, 4.5, 8.7, 0.0, "s6"},
      {"translation removes", &NoiseStructure::translation_share, 0.24, 0.55, 0.0, "s6"},
      {"similarity removes", &NoiseStructure::similarity_share, 0.59, 0.74, 0.0, "s6"},
      {"residual std, px", &NoiseStructure::residual_std_px, 0.17, 0.25, 0.0, "s6"},
      {"residual corr, <= 1.3 pitch", &NoiseStructure::neighbour_corr, 0.27, 0.27, 0.0, "s6"},
      {"residual corr, 1.3-2.3 pitch", &NoiseStructure::next_corr, 0.14, 0.14, 0.0, "s6"},
      {"common mode lag-1 autocorr", &NoiseStructure::common_lag1, 0.26, 0.75, 0.0, "s6*"},
      {"consecutive / random step", &NoiseStructure::consecutive_over_random, 0.55, 0.64, 0.0, "s6*"},
      {"pin speed W=1, px/frame", &NoiseStructure::speed_w1_px, 0.5, 0.5, 0.1, "s2"},
      {"pin speed W=5, px/frame", &NoiseStructure::speed_w5_px, 0.1, 0.1, 0.03, "s2"},
  };
  return figures;
}

std::string Num(double v, int digits = 3) { return std::isnan(v) ? "-" : fmt::format("{:.{}g}", v, digits); }

/// The mean of a figure over the rows where it is finite (NaN without one).
double MeanOf(const std::vector<NoiseStructure>& rows, double NoiseStructure::*field) {
  double sum = 0.0;
  int n = 0;
  for (const NoiseStructure& r : rows) {
    if (std::isnan(r.*field)) continue;
    sum += r.*field;
    ++n;
  }
  return n > 0 ? sum / n : kNaN;
}

std::string Verdict(const Figure& f, double v) {
  if (std::isnan(v)) return "-";
  const double lo = f.tol > 0.0 ? f.lo - f.tol : f.lo / kFactor, hi = f.tol > 0.0 ? f.hi + f.tol : f.hi * kFactor;
  return v >= lo && v <= hi ? "yes" : "no";
}

std::string RealRange(const Figure& f) {
  std::string r = f.lo == f.hi ? Num(f.lo) : Num(f.lo) + "-" + Num(f.hi);
  return f.tol > 0.0 ? r + " +- " + Num(f.tol) : r;
}

}  // namespace

std::string FormatNoiseReport(const std::vector<NoiseStructure>& rows) {
  std::string out = fmt::format("{:>4} {:<10} {:>6} {:>5} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}\n", "run",
                                "sensor", "frames", "pins", "R px", "pin std", "common", "transl", "simil", "lag1",
                                "W1", "W5");
  for (const NoiseStructure& r : rows) {
    out += fmt::format("{:>4} {:<10} {:>6} {:>5} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}{}\n", r.run, r.sensor,
                       r.frames, r.pins, Num(r.pattern_radius_px), Num(r.pin_std_px), Num(r.common_ratio),
                       Num(r.translation_share), Num(r.similarity_share), Num(r.common_lag1), Num(r.speed_w1_px),
                       Num(r.speed_w5_px), r.held ? "" : "  (whole run: no held window)");
  }
  out += fmt::format("\n{:<30} {:>10} {:>16} {:>8}\n", "figure (mean over the rows)", "this", "real TacTip",
                     "matched");
  for (const Figure& f : Figures()) {
    const double v = MeanOf(rows, f.field);
    out += fmt::format("{:<30} {:>10} {:>12} {:<3} {:>8}\n", f.name, Num(v), RealRange(f), f.source, Verdict(f, v));
  }
  out += fmt::format(
      "real: a 127-pin TacTip (pattern radius R = 131 px) held still at 1-4 mm (s6: real-sensor section 6; * per "
      "frame step of frames whose interval is not recorded) and the thesis's 100 fps pin-speed noise (s2); matched: "
      "within a factor {} of the real range (speeds: within the tolerance). Pixel figures scale with R.\n",
      kFactor);
  return out;
}

std::string NoiseCsv(const std::vector<NoiseStructure>& rows) {
  std::string out =
      "run,sensor,held,frames,pins,pattern_radius_px,pin_std_px,common_std_px,common_ratio,translation_share,"
      "similarity_share,residual_std_px,neighbour_corr,next_corr,common_lag1,consecutive_over_random,speed_w1_px,"
      "speed_w5_px\n";
  for (const NoiseStructure& r : rows) {
    out += fmt::format("{},{},{},{},{}", r.run, r.sensor, r.held ? 1 : 0, r.frames, r.pins);
    for (double v : {r.pattern_radius_px, r.pin_std_px, r.common_std_px, r.common_ratio, r.translation_share,
                     r.similarity_share, r.residual_std_px, r.neighbour_corr, r.next_corr, r.common_lag1,
                     r.consecutive_over_random, r.speed_w1_px, r.speed_w5_px}) {
      out += std::isnan(v) ? std::string(",") : fmt::format(",{:.6g}", v);
    }
    out += "\n";
  }
  return out;
}

}  // namespace tactip
