#include "scenarios/app/cli/study_commands.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "scenarios/studies/contact_checks/contact_checks.h"
#include "scenarios/studies/marker_checks/marker_checks.h"
#include "scenarios/studies/incipient_report/incipient_report.h"
#include "scenarios/studies/noise/noise_structure.h"
#include "scenarios/studies/signatures/signature_report.h"
#include "scenarios/studies/tracking/tracking_report.h"
#include "sensors/slip_data.h"
#include "scenarios/studies/sweeps/sweep.h"
#include "sim/base/files.h"
#include "sim/base/progress.h"

namespace tactip::cli {

namespace {

// Options of the study subcommands (owned by the returned closure).
struct StudyArgs {
  ConfigArgs config;
  std::vector<std::string> validate_checks;
  std::vector<std::string> sweep_params;
  int sweep_runs = 4, jobs = 0;
  unsigned long long seed = 1;
  std::string out;
  bool quiet = false, no_plots = false;
  IncipientParams sweep_detector;
  std::string report_what, report_path, report_csv, report_sensor;
  IncipientParams report_params;
  bool report_sectors_by_frame = false;
};

// The dome-check options for the rail config with the dome's skin (fingerprint-v2 unless
// --skin names one), a 1 ms step and `extra` after the user's --set.
DomeCheckOptions DomeOptions(const ConfigArgs& c, const std::vector<std::string>& extra) {
  ConfigArgs dome = c;
  if (dome.skin.empty()) dome.skin = "fingerprint-v2";
  dome.sets = {"sim.timestep_s=0.001"};
  dome.sets.insert(dome.sets.end(), c.sets.begin(), c.sets.end());
  dome.sets.insert(dome.sets.end(), extra.begin(), extra.end());
  const RailScenarioConfig cfg = RailFamily(FindScenario("rail")).Load(dome.Source());
  return MembraneDomeOptions(cfg.sim, cfg.skin, cfg.contact);
}

// Runs one dome check and prints it; true when it passes.
bool RunDome(const DomeCheckOptions& d, const DomeCriteria& k, const std::string& title) {
  const SkinConfig& skin = d.rig.skin;
  ProgressF("validate: shearing the %s lattice (gel %.4g kPa in shear) to gross slip\n",
               skin.pattern.c_str(), skin.GelShearModulusPa() * 1e-3);
  const DomeCheck dc = RunDomeCheck(d);
  std::printf("dome under rising tangential load, %s (%s, %g mm skin of %g MPa on a gel of %.4g kPa in shear)\n%s",
              title.c_str(), skin.pattern.c_str(), skin.thickness_mm, skin.skin_modulus_mpa,
              skin.GelShearModulusPa() * 1e-3, FormatDomeCheck(dc, k).c_str());
  return k.Pass(dc);
}

// tactip validate contact: the brush check on the uncoupled lattice, then the dome on the
// membrane-coupled lattice (fingerprint-v2 unless --skin names another membrane skin) at
// 1 ms, twice: with the skin softened until the membrane reaches a third of the contact
// radius (the regime of the continuum band) and as configured. Every config is checked
// before anything runs.
int RunContactChecks(const ConfigArgs& c) {
  // The brush check's lattice: the rail scene's config as generate would load it (--skin
  // preset, then --set).
  const RailScenarioConfig rail = RailFamily(FindScenario("rail")).Load(c.Source());
  const DomeCheckOptions configured_dome = DomeOptions(c, {});
  const DomeCheckOptions continuum_dome = [&] {
    const std::string softened = ContinuumDomeSetting(configured_dome);
    try {
      return DomeOptions(c, {softened});
    } catch (const InputError& e) {
      throw InputError("continuum-regime dome (" + softened + "): " + e.what());
    }
  }();
  BrushCheckOptions o;
  o.rig.sim = rail.sim;
  o.rig.skin = rail.skin;
  o.rig.contact = rail.contact;
  ProgressF("validate: pressing an uncoupled %s lattice and shearing it past gross slip\n",
               rail.skin.pattern.c_str());
  const BrushCheck bc = RunBrushCheck(o);
  constexpr double kAgreement = 0.98, kLoadError = 0.03;
  std::printf("%s", FormatBrushCheck(bc, kAgreement, kLoadError).c_str());
  bool ok = bc.state_agreement >= kAgreement && bc.load_error_max <= kLoadError && bc.slip_order_correlation >= 0.9;
  DomeCriteria continuum, configured;
  configured.judge_band = false;
  ok = RunDome(continuum_dome, continuum, "continuum-regime lattice, its skin softened to lambda = a/3") && ok;
  ok = RunDome(configured_dome, configured, "configured lattice") && ok;
  if (!ok) ProgressF("tactip: validation failed\n");
  return ok ? 0 : 1;
}

// tactip validate markers: the flat-press marker field against a real TacTip's, for the
// rail scene's skin, camera and contact (--config, --skin, --set as for generate).
int RunMarkerCheck(const ConfigArgs& c) {
  const RailScenarioConfig rail = RailFamily(FindScenario("rail")).Load(c.Source());
  FlatPressOptions o;
  o.rig.sim = rail.sim;
  o.rig.skin = rail.skin;
  o.rig.contact = rail.contact;
  o.camera = rail.sensor;
  const bool real_like = rail.skin.pattern == "smooth" && PinLattice::Build(rail.skin).size() == 127;
  ProgressF("validate: pressing the skin onto a flat plate at 1, 2, 3 and 4 mm\n");
  const FlatPressCheck check = RunFlatPressCheck(o);
  std::printf("%s", FormatFlatPressCheck(check, real_like ? "" : "; the real figures are a 127-pin smooth TacTip's").c_str());
  if (!check.ok) ProgressF("tactip: validation failed\n");
  return check.ok ? 0 : 1;
}

// tactip report signatures: the hardware slip signatures of every run, optionally as CSV.
int RunSignatureReport(const StudyArgs& a, const DatasetReader& reader) {
  SignatureOptions options;
  options.detector = a.report_params;
  options.held_window_s = HeldWindowS(reader.header());
  options.sectors_by_frame = a.report_sectors_by_frame;
  std::vector<SignatureRun> runs;
  for (int idx : reader.run_indices()) {
    const RunRecord run = reader.ReadRun(idx);
    runs.push_back(MeasureSignatures(run, ChooseSensor(run, a.report_sensor, a.report_path), options));
  }
  std::printf("%s", FormatSignatureReport(runs, options).c_str());
  if (!a.report_csv.empty()) WriteFileAtomic(a.report_csv, SignatureCsv(runs));
  return 0;
}

// tactip report noise: the structure of the static pin noise of every run and sensor (the
// held window, or the whole run of a recording without one) beside a real TacTip's.
int RunNoiseReport(const StudyArgs& a, const DatasetReader& reader) {
  const double window_s = HeldWindowS(reader.header());
  std::vector<NoiseStructure> rows;
  for (int idx : reader.run_indices()) {
    const RunRecord run = reader.ReadRun(idx);
    const NoiseWindow still = StillFrames(run, window_s);
    for (const SensorRecord& s : run.sensors) {
      if (!a.report_sensor.empty() && s.name != a.report_sensor) continue;
      rows.push_back(MeasureNoiseStructure(run, s, still, idx));
    }
  }
  std::printf("%s", FormatNoiseReport(rows).c_str());
  if (!a.report_csv.empty()) WriteFileAtomic(a.report_csv, NoiseCsv(rows));
  return 0;
}

// tactip report incipient|signatures|noise: per-run figures of a dataset, optionally as CSV.
int RunReport(const StudyArgs& a) {
  CheckOutputsAreNotInputs({{"--csv", a.report_csv}}, {{"FILE", a.report_path}});
  if (!a.report_csv.empty()) CheckWritableLocation(a.report_csv);
  CheckSensorOption(a.report_path, a.report_sensor);
  const DatasetReader reader(a.report_path);
  NoteFlaggedRuns(reader, a.report_path);
  if (a.report_what == "signatures") return RunSignatureReport(a, reader);
  if (a.report_what == "noise") return RunNoiseReport(a, reader);
  std::vector<IncipientRunMetrics> metrics;
  for (int idx : reader.run_indices()) {
    const RunRecord run = reader.ReadRun(idx);
    metrics.push_back(AnalyzeIncipientRun(run, ChooseSensor(run, a.report_sensor, a.report_path), a.report_params));
  }
  std::printf("%s", FormatIncipientReport(metrics, SummarizeIncipient(metrics)).c_str());
  if (!a.report_csv.empty()) WriteFileAtomic(a.report_csv, IncipientCsv(metrics));
  return 0;
}

// tactip report tracking: the blob pipeline's detection error per run and sensor, and per sensor.
int RunTrackingReport(const StudyArgs& a) {
  CheckSensorOption(a.report_path, a.report_sensor);
  const DatasetReader reader(a.report_path);
  NoteFlaggedRuns(reader, a.report_path);
  const RailScenarioConfig stored = StoredRailConfig(reader.header());
  std::vector<TrackingFigures> rows, totals;
  for (int idx : reader.run_indices()) {
    const RunRecord run = reader.ReadRun(idx);
    for (const SensorRecord& s : run.sensors) {
      if (!a.report_sensor.empty() && s.name != a.report_sensor) continue;
      rows.push_back(AnalyzeTracking(s, idx, stored.sensor, stored.images.pin_tip_radius_mm, a.report_path));
      // Each sensor's total over the runs, in sensor order.
      auto total = std::find_if(totals.begin(), totals.end(), [&](const TrackingFigures& t) { return t.sensor == s.name; });
      if (total == totals.end()) total = totals.insert(totals.end(), TrackingFigures{s.name});
      total->Add(rows.back());
    }
  }
  std::printf("%s", FormatTrackingReport(rows, totals).c_str());
  return 0;
}

// One progress line per finished design.
void PrintDesignProgress(int done, int total, const SweepDesignResult& r) {
  std::string d;
  for (const auto& [k, v] : r.design) d += (d.empty() ? "" : " ") + k + "=" + v;
  ProgressF(
               "[%d/%d] %s: %d pins, incipient in %d/%d runs, lead %s +- %s s, pre-slip %s, peak %s px/frame, "
               "detector before fall %d/%d, first slip E/W %d/%d (%.1f s)\n",
               done, total, d.c_str(), r.n_pins, r.summary.with_incipient, r.summary.runs,
               Fmt(r.summary.lead_gross_mean_s).c_str(), Fmt(r.summary.lead_gross_std_s).c_str(),
               Fmt(r.summary.pre_slip_fraction_mean).c_str(), Fmt(r.summary.peak_speed_mean_px).c_str(),
               r.summary.detected_before_fall, r.summary.runs, r.summary.east_west_first, r.summary.runs, r.wall_time_s);
}

// tactip sweep: every design of the grid, CSVs and heatmaps in the output folder.
int RunSweepCommand(const StudyArgs& a, const std::atomic<bool>* stop) {
  const RailFamilyScenario& scenario = RailFamily(FindScenario(a.config.scenario));
  SweepOptions o;
  o.scenario = &scenario;
  o.base = a.config.Source();
  for (const auto& p : a.sweep_params) o.params.push_back(ParseSweepParam(p));
  o.runs = a.sweep_runs;
  o.seed = a.seed;
  o.jobs = a.jobs;
  o.out_dir = a.out.empty() ? "sweep" : a.out;
  std::vector<std::string> outputs = {"designs.csv", "runs.csv"};
  for (const auto& m : SweepMetrics()) outputs.push_back(m.name + ".png");
  CheckOutputsAreNotInputs(FilesInFolder("--out", o.out_dir, outputs), {{"--config", a.config.config_path}});
  o.plots = !a.no_plots;
  o.detector = a.sweep_detector;
  o.stop = stop;
  if (!a.quiet) {
    o.started = [&](size_t designs) {
      ProgressF("sweeping %zu design(s) x %d run(s) of %s into %s/\n", designs, a.sweep_runs,
                   scenario.name().c_str(), o.out_dir.c_str());
    };
  }
  const auto wall0 = std::chrono::steady_clock::now();
  NewFolderGuard folder(o.out_dir);
  const auto results = RunSweep(o, [&](int done, int total, const SweepDesignResult& r) {
    if (!a.quiet) PrintDesignProgress(done, total, r);
  });
  folder.Keep();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  ProgressF("done: %zu designs in %.1f s; wrote %s/designs.csv, runs.csv%s\n", results.size(), wall,
               o.out_dir.c_str(), SweepDrawsHeatmaps(o) ? " and one heatmap per metric (*.png)" : "");
  return 0;
}

// Registers `tactip sweep` and its options.
CLI::App* AddSweep(CLI::App& app, StudyArgs& a) {
  auto* c = app.add_subcommand("sweep",
                               "Run a scenario over a grid of config values; one CSV row per design with its "
                               "incipient-slip figures and one heatmap (PNG, drawn by matplotlib) per metric.");
  a.config.Add(c);
  c->add_option("--param", a.sweep_params,
                "Swept key: KEY=START:STOP:STEP, KEY=A,B,C or KEY=V (repeatable; first varies slowest; heatmaps "
                "need 1 or 2).")
      ->required()
      ->type_name("SPEC")
      ->check(NonEmpty("KEY=START:STOP:STEP, KEY=A,B,C or KEY=V"));
  c->add_option("--runs", a.sweep_runs, "Runs per design; every design uses the same run seeds (default 4).")
      ->check(CLI::Range(1, 100000));
  AddSeedOption(c, a.seed, "Master seed (default 1); the same seed reproduces the sweep exactly.");
  c->add_option("--jobs", a.jobs, "Worker threads (default: all cores); results do not depend on it.")
      ->check(CLI::Range(0, 256));
  c->add_option("--out", a.out, "Output folder (default sweep/); created if missing.")->check(NonEmpty("a folder"));
  c->add_option("--window", a.sweep_detector.window, "Incipient detector window W (default 5).")
      ->check(CLI::Range(1, 1000));
  c->add_option("--speed-thr-px", a.sweep_detector.speed_thr_px, "Incipient detector s_thr (default 0.2).")
      ->check(NumberAbove(0.0));
  c->add_option("--count-thr", a.sweep_detector.count_thr, "Incipient detector I_thr (default 4).")
      ->check(CLI::Range(1, 100000));
  c->add_flag("--quiet", a.quiet, "No per-design progress lines.");
  c->add_flag("--no-plots", a.no_plots, "Write the CSVs only: no heatmaps, no Python or matplotlib needed.");
  return c;
}

// Registers `tactip report incipient|signatures|tracking|noise` and their options.
CLI::App* AddReport(CLI::App& app, StudyArgs& a) {
  auto* c = app.add_subcommand("report",
                               "Per-run figures of a dataset. incipient: ground-truth lead times, first-slipping "
                               "pins, internal vs external tracking, and the incipient detector's alarms. "
                               "signatures: the hardware's gross- and incipient-slip signatures (spike width and "
                               "peak, co-linearity, contact loss, visibility, amplitudes, alarm lead, first-slipping "
                               "sector, marker agreement) beside the real TacTip's values, with pass/fail. tracking: "
                               "the blob pipeline's detection error. noise: the structure of the static pin noise "
                               "(common mode, similarity share, neighbour correlation, time, W = 1 and W = 5 speeds) "
                               "beside a real TacTip's.");
  c->add_option("what", a.report_what,
                "incipient, signatures, or tracking: the blob pipeline's pins (generate --images) against the "
                "projected truth per run and sensor (share within 1 px, RMS and largest error, misses), or noise: the "
                "static pin noise's structure in the held window (the whole run without one), every sensor unless "
                "--sensor")
      ->required()
      ->check(CLI::IsMember({"incipient", "signatures", "tracking", "noise"}));
  c->add_option("file", a.report_path, "HDF5 dataset written by 'tactip generate'.")
      ->required()
      ->check(NonEmpty("an HDF5 dataset"));
  c->add_option("--window", a.report_params.window, "Detector moving-average window W (default 5).")
      ->check(CLI::Range(1, 1000));
  c->add_option("--speed-thr-px", a.report_params.speed_thr_px,
                "Detector excess-speed threshold s_thr, px/frame (default 0.2).")
      ->check(NumberAbove(0.0));
  c->add_option("--count-thr", a.report_params.count_thr, "Detector set-size threshold I_thr (default 4).")
      ->check(CLI::Range(1, 100000));
  c->add_flag("--sectors-by-frame", a.report_sectors_by_frame,
              "signatures: order the first-slipping sectors by the camera frames' labels even where the dataset "
              "records each pin's first slipping physics step (labels/pin_first_slip_s; by step is the default "
              "then).");
  c->add_option("--csv", a.report_csv, "Also write the per-run table as CSV; not the input FILE.")
      ->check(NonEmpty("a file name"));
  AddSensorOption(c, a.report_sensor);
  return c;
}

}  // namespace

std::function<int()> AddStudyCommands(CLI::App& app, const std::atomic<bool>* stop) {
  auto a = std::make_shared<StudyArgs>();
  auto* validate = app.add_subcommand(
      "validate", "Check the simulated contact against analytic anchors and print measured vs predicted.");
  validate
      ->add_option("what", a->validate_checks,
                   "contact: the pin lattice against the brush model and the dome's exact solution; markers: the "
                   "flat-press marker field against a real TacTip's.")
      ->required()
      ->check(CLI::Validator(
          [](std::string& check) {
            return check == "contact" || check == "markers"
                       ? std::string()
                       : "unknown check '" + check + "'; the known checks are: contact, markers";
          },
          "contact|markers"));
  a->config.Add(validate, false);
  auto* sweep = AddSweep(app, *a);
  auto* report = AddReport(app, *a);
  return [a, validate, sweep, report, stop]() -> int {
    if (*validate) {
      int rc = 0;
      for (const std::string& check : a->validate_checks) {
        rc = std::max(rc, check == "markers" ? RunMarkerCheck(a->config) : RunContactChecks(a->config));
      }
      return rc;
    }
    if (*report) return a->report_what == "tracking" ? RunTrackingReport(*a) : RunReport(*a);
    if (*sweep) return RunSweepCommand(*a, stop);
    return -1;
  };
}

}  // namespace tactip::cli
