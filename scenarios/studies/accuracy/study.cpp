#include "scenarios/studies/accuracy/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "scenarios/studies/accuracy/compare.h"
#include "scenarios/studies/contact_checks/contact_checks.h"
#include "sim/base/nan.h"
#include "sim/simulation.h"

namespace tactip {

namespace {

// Camera noise off: the study compares what the physics does, not the noise draws.
const std::vector<std::string> kNoiseOff = {"sensor.noise_model=independent", "sensor.pixel_noise_px=0", "sensor.dropout_prob=0",
                                            "external.pixel_noise_px=0"};

double Mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return v.empty() ? kNaN : s / static_cast<double>(v.size());
}

ConfigSource WithSetting(const ConfigSource& base, const AccuracySetting& s) {
  ConfigSource src = base;
  src.overrides.insert(src.overrides.end(), kNoiseOff.begin(), kNoiseOff.end());
  src.overrides.insert(src.overrides.end(), s.overrides.begin(), s.overrides.end());
  return src;
}

// Runs one setting of a rail-protocol scene; keeps its records and summaries.
struct RailSettingRuns {
  std::vector<RunRecord> records;
  std::vector<RailRunSummary> summaries;
};

RailSettingRuns RunRailSetting(const RailFamilyScenario& family, const AccuracyOptions& o, const AccuracySetting& s) {
  const RailScenario scenario(family.Load(WithSetting(o.base, s)));
  RailSettingRuns out;
  RunRailRuns(scenario, 0, o.runs, o.seed, o.jobs, o.stop, [&](RunRecord&& rec, const RailRunSummary& sum) {
    out.records.push_back(std::move(rec));
    out.summaries.push_back(sum);
  });
  return out;
}

// A setting's row from its runs and the reference's.
AccuracyRow RailRow(const AccuracySetting& s, const RailSettingRuns& runs, const RailSettingRuns& ref) {
  AccuracyRow row;
  row.setting = s;
  double wall = 0.0, sim = 0.0;
  std::vector<double> onset, incip, traj, labels, coulomb;
  for (size_t k = 0; k < runs.records.size(); ++k) {
    const RailRunSummary& sum = runs.summaries[k];
    wall += sum.wall_time_s;
    sim += sum.sim_time_s;
    row.healthy = row.healthy && sum.health.ok;
    row.flicker_max = std::max(row.flicker_max, sum.health.flicker_max);
    row.creep_um = std::max(row.creep_um, sum.creep_um);
    if (!std::isnan(sum.gross_slip_onset_s) && !std::isnan(sum.predicted_onset_s)) {
      coulomb.push_back(std::abs(sum.gross_slip_onset_s - sum.predicted_onset_s));
    }
    const RunDifference d = CompareRuns(runs.records[k], ref.records[k]);
    onset.push_back(d.onset_error_s);
    incip.push_back(d.incipient_error_s);
    traj.push_back(d.traj_rms_px);
    labels.push_back(d.label_disagreement);
  }
  row.wall_s_per_sim_s = sim > 0.0 ? wall / sim : kNaN;
  row.onset_error_ms = 1e3 * Mean(onset);
  row.incipient_error_ms = 1e3 * Mean(incip);
  row.traj_rms_px = Mean(traj);
  row.label_disagreement_pct = 100.0 * Mean(labels);
  row.coulomb_error_ms = 1e3 * Mean(coulomb);
  return row;
}

// A row for a setting that did not run (refused or failed).
AccuracyRow NotRun(const AccuracySetting& s, const std::string& why) {
  AccuracyRow row;
  row.setting = s;
  row.outcome = why;
  row.healthy = false;
  for (double* v : {&row.wall_s_per_sim_s, &row.onset_error_ms, &row.incipient_error_ms, &row.traj_rms_px,
                    &row.creep_um, &row.label_disagreement_pct, &row.coulomb_error_ms, &row.release_error,
                    &row.gross_error, &row.band_fraction, &row.band_error}) {
    *v = kNaN;
  }
  return row;
}

std::vector<AccuracySetting> Selected(const std::vector<AccuracySetting>& all, const std::vector<std::string>& only) {
  if (only.empty()) return all;
  std::vector<AccuracySetting> out = {all.front()};  // the reference
  for (const auto& label : only) {
    const AccuracySetting& s = FindSetting(all, label);
    if (!s.is_reference) out.push_back(s);
  }
  return out;
}

// Measures every setting in turn with `measure` (a row per setting, progress after each). A
// setting refused (InputError) or failed (SimulationError) becomes a row saying so, except the
// reference, which every other row is compared with.
template <class Measure>
AccuracyReport MeasureSettings(const std::string& scene, const std::vector<AccuracySetting>& settings,
                               const AccuracyOptions& o, Measure measure) {
  AccuracyReport report;
  report.scene = scene;
  for (size_t i = 0; i < settings.size(); ++i) {
    const AccuracySetting& s = settings[i];
    AccuracyRow row;
    try {
      row = measure(s);
    } catch (const InputError& e) {
      if (s.is_reference) throw;
      row = NotRun(s, std::string("refused: ") + e.what());
    } catch (const SimulationError& e) {
      if (s.is_reference) throw;
      row = NotRun(s, std::string("failed: ") + e.what());
    }
    report.rows.push_back(row);
    if (o.progress) o.progress(static_cast<int>(i + 1), static_cast<int>(settings.size()), row);
  }
  return report;
}

AccuracyReport RunRailAccuracy(const AccuracyOptions& o) {
  const RailFamilyScenario& family = RailFamily(FindScenario(o.scene));
  const std::vector<AccuracySetting> settings = Selected(AccuracySettings(o), o.only);
  // Every setting's config is checked before anything runs, except those the stability
  // check refuses (reported as such).
  family.Load(WithSetting(o.base, settings.front()));
  RailSettingRuns ref;
  return MeasureSettings(o.scene, settings, o, [&](const AccuracySetting& s) {
    RailSettingRuns runs = RunRailSetting(family, o, s);
    if (s.is_reference) ref = runs;
    return RailRow(s, runs, ref);
  });
}

// The dome's config at one setting: fingerprint-v2 (unless the base config names another
// skin) at 1 ms, with `extra` last.
DomeCheckOptions DomeAt(const AccuracyOptions& o, const AccuracySetting& s, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = SkinPreset("fingerprint-v2");
  sets.push_back("sim.timestep_s=0.001");
  sets.insert(sets.end(), o.base.overrides.begin(), o.base.overrides.end());
  sets.insert(sets.end(), extra.begin(), extra.end());
  sets.insert(sets.end(), s.overrides.begin(), s.overrides.end());
  const auto cfg = LoadConfig<RailScenarioConfig>(o.base.yaml_path, sets);
  return MembraneDomeOptions(cfg.sim, cfg.skin, cfg.contact);
}

// The dome checks of `validate contact` at one setting: the continuum-regime lattice (the
// skin softened to lambda = a/3) and the configured membrane lattice.
std::vector<DomeCheck> RunDomes(const AccuracyOptions& o, const AccuracySetting& s, double* wall_s) {
  const DomeCheckOptions configured = DomeAt(o, s, {});
  std::vector<DomeCheck> out;
  *wall_s = 0.0;
  for (const DomeCheckOptions& d : {DomeAt(o, s, {ContinuumDomeSetting(configured)}), configured}) {
    const auto t0 = std::chrono::steady_clock::now();
    out.push_back(RunDomeCheck(d));
    *wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return out;
}

AccuracyRow DomeRow(const AccuracySetting& s, const std::vector<DomeCheck>& domes, double wall_s,
                    const std::vector<DomeCheck>& ref) {
  AccuracyRow row = NotRun(s, "ok");
  row.healthy = true;
  double sim = 0.0, release = 0.0;
  row.gross_error = 0.0;
  for (const DomeCheck& d : domes) {
    sim += d.sim_time_s;
    release += d.release_error_mean / static_cast<double>(domes.size());
    row.gross_error = std::max(row.gross_error, std::abs(d.gross_q_ratio - 1.0));
  }
  row.wall_s_per_sim_s = wall_s / sim;
  row.release_error = release;
  row.band_fraction = domes.front().bracket_fraction;
  row.band_error = ref.empty() ? 0.0 : std::abs(domes.front().bracket_fraction - ref.front().bracket_fraction);
  return row;
}

AccuracyReport RunDomeAccuracy(const AccuracyOptions& o) {
  const std::vector<AccuracySetting> settings = Selected(AccuracySettings(o), o.only);
  std::vector<DomeCheck> ref;
  return MeasureSettings("domes", settings, o, [&](const AccuracySetting& s) {
    if (o.stop && o.stop->load()) throw Interrupted();
    double wall = 0.0;
    const std::vector<DomeCheck> domes = RunDomes(o, s, &wall);
    if (s.is_reference) ref = domes;
    return DomeRow(s, domes, wall, ref);
  });
}

}  // namespace

std::vector<AccuracySetting> AccuracySettings(const AccuracyOptions& opts) {
  if (opts.scene == "domes") return DomeAccuracySettings();
  if (opts.scene != "rail" && opts.scene != "incipient") {
    throw InputError("accuracy: unknown scene '" + opts.scene + "' (known: rail, incipient, domes)");
  }
  const RailScenarioConfig cfg = RailFamily(FindScenario(opts.scene)).Load(opts.base);
  return RailAccuracySettings(cfg.sim.timestep_s, cfg.contact.timeconst_s);
}

void CheckAccuracyOptions(const AccuracyOptions& opts) {
  if (opts.runs < 1) throw InputError(fmt::format("--runs = {}: must be >= 1", opts.runs));
  const bool domes = opts.scene == "domes";
  const std::vector<AccuracySetting> settings = Selected(AccuracySettings(opts), opts.only);
  if (!domes) RailFamily(FindScenario(opts.scene)).Load(WithSetting(opts.base, settings.front()));
}

AccuracyReport RunAccuracy(const AccuracyOptions& opts) {
  CheckAccuracyOptions(opts);
  return opts.scene == "domes" ? RunDomeAccuracy(opts) : RunRailAccuracy(opts);
}

std::vector<std::string> AccuracyErrorColumns(const std::string& scene) {
  if (scene == "domes") return {"release_error", "gross_error", "band_error"};
  return {"onset_error_ms", "traj_rms_px", "label_disagreement_pct", "creep_um", "coulomb_error_ms"};
}

}  // namespace tactip
