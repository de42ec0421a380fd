#include "scenarios/studies/sweeps/sweep.h"

#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "sim/base/number_text.h"
#include "scenarios/figures/plot.h"
#include "sim/base/files.h"

namespace tactip {

namespace {

ConfigSource DesignSource(const ConfigSource& base, const SweepDesign& d) {
  ConfigSource src = base;
  for (const auto& [key, value] : d) src.overrides.push_back(key + "=" + value);
  return src;
}

std::string DesignText(const SweepDesign& d) {
  std::string out;
  for (const auto& [key, value] : d) out += (out.empty() ? "" : ", ") + key + "=" + value;
  return out.empty() ? "(base config)" : out;
}


/// One PNG heatmap per metric from designs.csv: rows = first key, columns = second (or a
/// single row for one key).
void DrawHeatmaps(const SweepOptions& opts, const std::string& designs_csv) {
  const std::filesystem::path dir(opts.out_dir);
  const bool two = opts.params.size() == 2;
  for (const auto& m : SweepMetrics()) {
    HeatmapPlot p;
    p.csv = designs_csv;
    p.x_key = two ? opts.params[1].key : opts.params[0].key;
    p.y_key = two ? opts.params[0].key : "";
    p.value = m.name;
    p.title = m.title;
    p.unit = m.unit;
    p.out_png = (dir / (m.name + ".png")).string();
    try {
      PlotHeatmap(p);
    } catch (const PlotError& e) {
      throw PlotError(std::string(e.what()) + " (designs.csv and runs.csv are written)");
    }
  }
}

}  // namespace

bool SweepDrawsHeatmaps(const SweepOptions& opts) {
  return opts.plots && (opts.params.size() == 1 || opts.params.size() == 2);
}

const std::vector<SweepMetric>& SweepMetrics() {
  static const std::vector<SweepMetric> metrics = {
      {"lead_gross_mean_s", "Incipient lead before gross slip (mean)", "s",
       [](const SweepDesignResult& r) { return r.summary.lead_gross_mean_s; }},
      {"lead_gross_std_s", "Incipient lead before gross slip (spread, std)", "s",
       [](const SweepDesignResult& r) { return r.summary.lead_gross_std_s; }},
      {"pre_slip_fraction", "Contacting pins that slip before gross slip", "",
       [](const SweepDesignResult& r) { return r.summary.pre_slip_fraction_mean; }},
      {"peak_speed_px", "Gross-slip signal: peak mean pin speed", "px/frame",
       [](const SweepDesignResult& r) { return r.summary.peak_speed_mean_px; }},
      {"detector_lead_fall_s", "Incipient detector: alarm lead before the fall (detected runs)", "s",
       [](const SweepDesignResult& r) { return r.summary.detector_lead_fall_mean_s; }},
      {"detector_miss_rate", "Incipient detector: runs without an alarm before the fall", "",
       [](const SweepDesignResult& r) {
         return r.summary.runs > 0 ? 1.0 - static_cast<double>(r.summary.detected_before_fall) / r.summary.runs
                                   : std::nan("");
       }},
  };
  return metrics;
}

std::string SweepDesignsCsv(const std::vector<SweepParam>& params, const std::vector<SweepDesignResult>& results) {
  std::string out = "design";
  for (const auto& p : params) out += "," + p.key;
  out += ",n_pins,n_collidable,runs,runs_with_incipient";
  for (const auto& m : SweepMetrics()) out += "," + m.name;
  out += ",lead_fall_mean_s,alarm_before_gross,first_slip_radius_ratio,tracking_correlation,tracking_error,"
         "shear_relaxation_s,east_west_first,south_before_north,hardware_order,sim_time_s,wall_time_s\n";
  for (size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    out += std::to_string(i);
    for (const auto& kv : r.design) out += "," + kv.second;
    out += fmt::format(",{},{},{},{}", r.n_pins, r.n_collidable, r.summary.runs, r.summary.with_incipient);
    for (const auto& m : SweepMetrics()) out += "," + NumberCell(m.value(r), "{:.6g}", "nan");
    out += fmt::format(",{},{},{},{},{},{},{},{},{},{:.3f},{:.3f}\n", NumberCell(r.summary.lead_fall_mean_s, "{:.6g}", "nan"),
                       r.summary.alarm_before_gross, NumberCell(r.summary.first_slip_radius_ratio_mean, "{:.6g}", "nan"),
                       NumberCell(r.summary.tracking_correlation_mean, "{:.6g}", "nan"), NumberCell(r.summary.tracking_error_mean, "{:.6g}", "nan"),
                       NumberCell(r.shear_relaxation_s, "{:.6g}", "nan"), r.summary.east_west_first, r.summary.south_before_north,
                       r.summary.hardware_order, r.sim_time_s, r.wall_time_s);
  }
  return out;
}

std::vector<SweepDesignResult> RunSweep(const SweepOptions& opts,
                                        const std::function<void(int, int, const SweepDesignResult&)>& progress) {
  if (opts.scenario == nullptr) throw InputError("sweep: no scenario");
  if (opts.runs < 1) throw InputError(fmt::format("--runs = {}: must be >= 1", opts.runs));
  if (opts.out_dir.empty()) throw InputError("sweep: no output folder given (--out)");
  const std::vector<SweepDesign> designs = ExpandGrid(opts.params);
  // Every design's config must be valid before anything runs.
  std::vector<RailScenarioConfig> configs;
  for (const auto& d : designs) {
    try {
      configs.push_back(opts.scenario->Load(DesignSource(opts.base, d)));
    } catch (const InputError& e) {
      throw InputError("design " + DesignText(d) + ": " + e.what());
    }
  }
  // So must the plotting tool: a missing matplotlib fails now, not after hours of runs.
  if (SweepDrawsHeatmaps(opts)) CheckPlotting();
  CreateOutputFolder(opts.out_dir);
  const std::filesystem::path dir(opts.out_dir);
  CheckWritableLocation((dir / "designs.csv").string());
  if (opts.started) opts.started(designs.size());

  std::vector<SweepDesignResult> results;
  std::string runs_csv;
  for (size_t i = 0; i < designs.size(); ++i) {
    const auto wall0 = std::chrono::steady_clock::now();
    SweepDesignResult r;
    r.design = designs[i];
    const RailScenario scenario(configs[i]);
    r.n_pins = scenario.n_pins();
    r.n_collidable = scenario.n_collidable();
    const SkinMechanics mech = SkinMechanics::From(configs[i].skin, PinLattice::Build(configs[i].skin));
    const double c_tip = configs[i].skin.coupling == "membrane" ? mech.TipDamping(configs[i].sim.timestep_s)
                                                                 : mech.tip_damping_Ns_m;
    r.shear_relaxation_s = c_tip / mech.k_tip_N_m;
    RunRailRuns(scenario, 0, opts.runs, opts.seed, opts.jobs, opts.stop, [&](RunRecord&& rec, const RailRunSummary& s) {
      r.runs.push_back(AnalyzeIncipientRun(rec, opts.detector));
      r.sim_time_s += s.sim_time_s;
    });
    r.summary = SummarizeIncipient(r.runs);
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    // Per-run rows, prefixed with the design number.
    const std::string block = IncipientCsv(r.runs);
    size_t pos = block.find('\n') + 1;
    if (runs_csv.empty()) runs_csv = "design," + block.substr(0, pos);
    while (pos < block.size()) {
      const size_t next = block.find('\n', pos) + 1;
      runs_csv += std::to_string(i) + "," + block.substr(pos, next - pos);
      pos = next;
    }
    results.push_back(std::move(r));
    if (progress) progress(static_cast<int>(i) + 1, static_cast<int>(designs.size()), results.back());
  }

  WriteFileAtomic((dir / "designs.csv").string(), SweepDesignsCsv(opts.params, results));
  WriteFileAtomic((dir / "runs.csv").string(), runs_csv);
  if (SweepDrawsHeatmaps(opts)) DrawHeatmaps(opts, (dir / "designs.csv").string());
  return results;
}

}  // namespace tactip
