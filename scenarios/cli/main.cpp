// tactip: the command-line program of tactip-sim.

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "detectors/detector.h"
#include "scenarios/cli/detect_commands.h"
#include "scenarios/incipient_report.h"
#include "scenarios/registry.h"
#include "scenarios/sweep.h"
#include "scenarios/validate.h"
#include "sensors/dataset.h"
#include "sim/files.h"
#include "sim/simulation.h"
#include "tactip/version.h"

namespace {

// Set by SIGINT/SIGTERM; long runs poll it and stop cleanly (no partial output). A
// signal handler can only reach a global.
std::atomic<bool> g_stop{false};

void OnSignal(int) { g_stop = true; }

std::string Fmt(double v, const char* spec = "{:.3f}") {
  return std::isnan(v) ? std::string("-") : fmt::format(fmt::runtime(spec), v);
}

double Attr(const tactip::RunRecord& r, const std::string& key) {
  auto it = r.attrs.find(key);
  return it == r.attrs.end() ? std::nan("") : it->second;
}

// Prints what a dataset holds: header, one line per run, totals, and (optionally) the
// resolved config.
void PrintDatasetSummary(const std::string& path, bool with_config) {
  tactip::DatasetReader reader(path);
  const auto& h = reader.header();
  const auto& runs = reader.run_indices();
  std::printf("dataset      %s\n", path.c_str());
  std::printf("scenario     %s (tactip %s, seed %llu)\n", h.scenario.c_str(), h.tactip_version.c_str(),
              static_cast<unsigned long long>(h.seed));
  std::printf("runs         %zu\n", runs.size());
  std::printf("%5s %7s %9s %10s %10s %10s %8s %9s %8s %9s\n", "run", "frames", "length_s", "onset_s", "fall_s",
              "coulomb_s", "mu", "depth_mm", "v_mm_s", "creep_um");
  size_t frames = 0;
  int slipped = 0;
  double err_sum = 0.0;
  int err_n = 0;
  for (int idx : runs) {
    const tactip::RunRecord r = reader.ReadRunSummary(idx);
    frames += r.frames();
    const double onset = Attr(r, "gross_slip_onset_s");
    const double pred = Attr(r, "predicted_onset_s");
    if (!std::isnan(onset)) ++slipped;
    if (!std::isnan(onset) && !std::isnan(pred)) {
      err_sum += std::abs(onset - pred);
      ++err_n;
    }
    std::printf("%5d %7zu %9.2f %10s %10s %10s %8.4f %9.3f %8.3f %9s\n", idx, r.frames(),
                r.frames() ? r.time.back() : 0.0, Fmt(onset).c_str(), Fmt(Attr(r, "object_fall_s")).c_str(),
                Fmt(pred).c_str(), Attr(r, "friction_coefficient"), Attr(r, "press_depth_mm"),
                Attr(r, "retract_speed_mm_s"), Fmt(Attr(r, "creep_um"), "{:.2f}").c_str());
  }
  std::printf("total        %zu frames; gross slip in %d of %zu runs", frames, slipped, runs.size());
  if (err_n > 0) std::printf("; mean |onset - Coulomb prediction| = %.1f ms", 1e3 * err_sum / err_n);
  std::printf("\n");
  if (with_config) std::printf("config:\n%s", h.config_yaml.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tactip-sim: a MuJoCo simulator of the TacTip optical tactile sensor, with exact slip ground truth.\n"
               "Scenarios build a scene, drive a protocol and write labelled HDF5 datasets."};
  app.set_version_flag("--version", std::string("tactip ") + TACTIP_VERSION);
  app.require_subcommand(1);

  // tactip scenarios
  auto* cmd_list = app.add_subcommand("scenarios", "List the registered scenarios with one-line descriptions.");

  // Shared config options.
  std::string scenario_name, config_path, out_path;
  std::vector<std::string> sets;
  double speed = std::nan("");
  std::string stimulus, skin_name;
  auto add_config_opts = [&](CLI::App* c) {
    c->add_option("scenario", scenario_name, "Scenario name (see 'tactip scenarios').")->required();
    c->add_option("--config", config_path,
                  "YAML config file; its keys override the built-in defaults (see assets/scenes/).")
        ->check(CLI::ExistingFile);
    c->add_option("--set", sets,
                  "Override one config key, e.g. --set sensor.pixel_noise_px=0.3 (repeatable; applied after "
                  "--config and the shortcut options). 'tactip config SCENARIO' lists every key.")
        ->type_name("KEY=VALUE");
    c->add_option("--speed-mm-s", speed, "Shortcut for --set rail.retract_speed_mm_s=V.");
    c->add_option("--stimulus", stimulus,
                  "Shortcut for --set rail.stimulus=S (flat, acrylic, curved80, curved40, curved20).");
    c->add_option("--skin", skin_name,
                  "Skin preset: smooth, fingerprint-v1 or fingerprint-v2 (sets skin.pattern, skin.coupling and the "
                  "variant's ridge/thickness/pin keys; applied before --set).");
  };

  // tactip generate
  auto* cmd_gen = app.add_subcommand("generate", "Simulate runs of a scenario and write a labelled HDF5 dataset.");
  add_config_opts(cmd_gen);
  int runs = 4, jobs = 0;
  unsigned long long seed = 1;
  bool quiet = false;
  cmd_gen->add_option("--runs", runs, "Number of runs (default 4).")->check(CLI::Range(1, 100000));
  cmd_gen->add_option("--seed", seed, "Master seed; run i derives its own seed from it (default 1).");
  cmd_gen->add_option("--out", out_path, "Output HDF5 file (default SCENARIO.h5); written atomically.");
  cmd_gen->add_option("--jobs", jobs, "Worker threads (default: all cores); results do not depend on it.")
      ->check(CLI::Range(0, 256));
  cmd_gen->add_flag("--quiet", quiet, "No per-run progress lines.");

  // tactip info
  std::string info_path;
  bool no_config = false;
  auto* cmd_info = app.add_subcommand("info", "Show the runs, frames, slip onsets and config of a dataset.");
  cmd_info->add_option("file", info_path, "HDF5 dataset written by 'tactip generate'.")->required();
  cmd_info->add_flag("--no-config", no_config, "Do not print the stored config.");

  // tactip export-mjcf
  auto* cmd_export = app.add_subcommand("export-mjcf", "Write the exact MuJoCo model (MJCF) a scenario builds.");
  add_config_opts(cmd_export);
  cmd_export->add_option("--out", out_path, "Output XML file (default: standard output).");

  // tactip config
  bool as_yaml = false;
  auto* cmd_config = app.add_subcommand("config", "List every config key of a scenario with unit, range and meaning.");
  add_config_opts(cmd_config);
  cmd_config->add_flag("--yaml", as_yaml, "Print the resolved config as YAML instead of the table.");
  bool with_comments = false;
  cmd_config->add_flag("--comments", with_comments, "With --yaml: each key's meaning and unit as a comment above it.");

  // tactip validate contact
  std::string validate_what;
  auto* cmd_validate = app.add_subcommand(
      "validate", "Check the simulated contact against analytic anchors and print measured vs predicted.");
  cmd_validate->add_option("what", validate_what, "contact: the pin lattice against the brush model.")
      ->required()
      ->check(CLI::IsMember({"contact"}));
  add_config_opts(cmd_validate);
  cmd_validate->get_option("scenario")->required(false);

  // tactip sweep
  auto* cmd_sweep = app.add_subcommand(
      "sweep", "Run a scenario over a grid of config values; one CSV row per design with its incipient-slip figures "
               "and one heatmap (SVG) per metric.");
  add_config_opts(cmd_sweep);
  std::vector<std::string> sweep_params;
  int sweep_runs = 4;
  tactip::IncipientParams sweep_detector;
  cmd_sweep->add_option("--param", sweep_params,
                        "Swept key: KEY=START:STOP:STEP, KEY=A,B,C or KEY=V (repeatable; first varies slowest; "
                        "heatmaps need 1 or 2).")
      ->required()
      ->type_name("SPEC");
  cmd_sweep->add_option("--runs", sweep_runs, "Runs per design; every design uses the same run seeds (default 4).")
      ->check(CLI::Range(1, 100000));
  cmd_sweep->add_option("--seed", seed, "Master seed (default 1); the same seed reproduces the sweep exactly.");
  cmd_sweep->add_option("--jobs", jobs, "Worker threads (default: all cores); results do not depend on it.")
      ->check(CLI::Range(0, 256));
  cmd_sweep->add_option("--out", out_path, "Output folder (default sweep/); created if missing.");
  cmd_sweep->add_option("--window", sweep_detector.window, "Incipient detector window W (default 5).")
      ->check(CLI::Range(1, 1000));
  cmd_sweep->add_option("--speed-thr-px", sweep_detector.speed_thr_px, "Incipient detector s_thr (default 0.2).")
      ->check(CLI::PositiveNumber);
  cmd_sweep->add_option("--count-thr", sweep_detector.count_thr, "Incipient detector I_thr (default 4).")
      ->check(CLI::Range(1, 100000));
  cmd_sweep->add_flag("--quiet", quiet, "No per-design progress lines.");

  // tactip report incipient
  std::string report_what, report_path, report_csv;
  tactip::IncipientParams report_params;
  auto* cmd_report = app.add_subcommand(
      "report", "Per-run incipient-slip figures of a dataset: ground-truth lead times, first-slipping pins, "
                "internal vs external tracking, and the incipient detector's alarms.");
  cmd_report->add_option("what", report_what, "incipient")->required()->check(CLI::IsMember({"incipient"}));
  cmd_report->add_option("file", report_path, "HDF5 dataset written by 'tactip generate'.")->required();
  cmd_report->add_option("--window", report_params.window, "Detector moving-average window W (default 5).")
      ->check(CLI::Range(1, 1000));
  cmd_report->add_option("--speed-thr-px", report_params.speed_thr_px,
                         "Detector excess-speed threshold s_thr, px/frame (default 0.2).")
      ->check(CLI::PositiveNumber);
  cmd_report->add_option("--count-thr", report_params.count_thr, "Detector set-size threshold I_thr (default 4).")
      ->check(CLI::Range(1, 100000));
  cmd_report->add_option("--csv", report_csv, "Also write the per-run table as CSV.");

  // tactip train / evaluate / detect / bench
  const auto run_detector_command = tactip::cli::AddDetectorCommands(app, &g_stop);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "tactip: %s (see --help)\n", e.what());
    return 2;
  }

  // Long simulations stop cleanly on Ctrl-C; other commands keep the default handling
  // (their outputs are written atomically at the end).
  if (*cmd_gen || *cmd_sweep || app.got_subcommand("bench")) {
    std::signal(SIGINT, OnSignal);
    std::signal(SIGTERM, OnSignal);
  }
  try {
    if (*cmd_list) {
      for (const auto& s : tactip::Scenarios()) std::printf("%-12s %s\n", s.name.c_str(), s.description.c_str());
      return 0;
    }
    if (*cmd_info) {
      PrintDatasetSummary(info_path, !no_config);
      return 0;
    }
    if (const int code = run_detector_command(); code >= 0) return code;
    if (*cmd_report) {
      if (!report_csv.empty()) tactip::CheckWritableLocation(report_csv);
      const tactip::DatasetReader reader(report_path);
      std::vector<tactip::IncipientRunMetrics> metrics;
      for (int idx : reader.run_indices()) {
        metrics.push_back(tactip::AnalyzeIncipientRun(reader.ReadRun(idx), report_params));
      }
      std::printf("%s", tactip::FormatIncipientReport(metrics, tactip::SummarizeIncipient(metrics)).c_str());
      if (!report_csv.empty()) tactip::WriteFileAtomic(report_csv, tactip::IncipientCsv(metrics));
      return 0;
    }
    if (*cmd_validate) {
      // The skin, contact and solver sections of the rail config apply to the rigs. The
      // dome: the membrane-coupled lattice (the fingerprint-v2 skin unless --skin names
      // another membrane skin) with single-coefficient friction at 1 ms, twice: with a
      // 0.3 mm skin, whose membrane reaches a third of the contact radius (the regime of the
      // continuum band), and as configured. Every config is checked before anything runs.
      const auto rail = tactip::LoadConfig<tactip::RailScenarioConfig>(config_path, sets);
      std::vector<std::string> dome_sets = tactip::SkinPreset(skin_name.empty() ? "fingerprint-v2" : skin_name);
      dome_sets.push_back("sim.timestep_s=0.001");
      dome_sets.insert(dome_sets.end(), sets.begin(), sets.end());
      const auto dome_options = [&](const std::vector<std::string>& extra) {
        std::vector<std::string> all = dome_sets;
        all.insert(all.end(), extra.begin(), extra.end());
        const auto cfg = tactip::LoadConfig<tactip::RailScenarioConfig>(config_path, all);
        tactip::DomeCheckOptions d;
        d.rig.sim = cfg.sim;
        d.rig.skin = cfg.skin;
        d.rig.contact = cfg.contact;
        tactip::CheckDomeSkin(d.rig.skin);
        return d;
      };
      const tactip::DomeCheckOptions configured_dome = dome_options({});
      const tactip::DomeCheckOptions continuum_dome = [&] {
        try {
          return dome_options({"skin.thickness_mm=0.3"});
        } catch (const tactip::InputError& e) {
          throw tactip::InputError(std::string("continuum-regime dome (skin.thickness_mm=0.3): ") + e.what());
        }
      }();
      tactip::BrushCheckOptions o;
      o.rig.sim = rail.sim;
      o.rig.skin = rail.skin;
      o.rig.contact = rail.contact;
      std::fprintf(stderr, "validate: pressing an uncoupled lattice and shearing it past gross slip\n");
      const tactip::BrushCheck c = tactip::RunBrushCheck(o);
      constexpr double kAgreement = 0.98, kLoadError = 0.03;
      std::printf("%s", tactip::FormatBrushCheck(c, kAgreement, kLoadError).c_str());
      bool ok = c.state_agreement >= kAgreement && c.load_error_max <= kLoadError && c.slip_order_correlation >= 0.9;
      const auto run_dome = [&](const tactip::DomeCheckOptions& d, const tactip::DomeCriteria& k,
                                const std::string& title) {
        const tactip::SkinConfig& skin = d.rig.skin;
        std::fprintf(stderr, "validate: shearing the %s lattice (%g mm skin) to gross slip\n", skin.pattern.c_str(),
                     skin.thickness_mm);
        const tactip::DomeCheck dc = tactip::RunDomeCheck(d);
        std::printf("dome under rising tangential load, %s (%s, skin.thickness_mm = %g)\n%s", title.c_str(),
                    skin.pattern.c_str(), skin.thickness_mm, tactip::FormatDomeCheck(dc, k).c_str());
        return k.Pass(dc);
      };
      tactip::DomeCriteria continuum, configured;
      configured.judge_band = false;
      ok = run_dome(continuum_dome, continuum, "continuum-regime lattice, its thickness fixed") && ok;
      ok = run_dome(configured_dome, configured, "configured lattice") && ok;
      if (!ok) std::fprintf(stderr, "tactip: validation failed\n");
      return ok ? 0 : 1;
    }
    const tactip::ScenarioEntry& entry = tactip::FindScenario(scenario_name);
    tactip::ConfigSource src;
    src.yaml_path = config_path;
    if (!skin_name.empty()) src.overrides = tactip::SkinPreset(skin_name);
    if (!std::isnan(speed)) src.overrides.push_back(fmt::format("rail.retract_speed_mm_s={}", speed));
    if (!stimulus.empty()) src.overrides.push_back("rail.stimulus=" + stimulus);
    src.overrides.insert(src.overrides.end(), sets.begin(), sets.end());

    if (*cmd_config) {
      const auto fields = entry.describe(src);
      if (as_yaml && with_comments) {
        const std::string header = fmt::format(
            "# {} scenario: every config key with its meaning; values as resolved from the given options.\n"
            "# Use with: tactip generate {} --config FILE [--set key=value ...]\n"
            "# 'tactip config {}' prints the same keys with units and allowed ranges.\n",
            entry.name, entry.name, entry.name);
        std::printf("%s", tactip::FieldsToCommentedYaml(fields, header).c_str());
        return 0;
      }
      if (as_yaml) {
        std::printf("%s", tactip::FieldsToYaml(fields).c_str());
        return 0;
      }
      for (const auto& f : fields) {
        std::printf("%-32s %-12s %-8s %-16s %s\n", f.key.c_str(), f.value.c_str(), f.unit.c_str(), f.allowed.c_str(),
                    f.doc.c_str());
      }
      return 0;
    }
    if (*cmd_export) {
      if (!out_path.empty()) tactip::CheckWritableLocation(out_path);
      const std::string xml = entry.export_mjcf(src);
      if (out_path.empty()) {
        std::printf("%s", xml.c_str());
      } else {
        tactip::WriteFileAtomic(out_path, xml);
        std::fprintf(stderr, "wrote %s (%zu bytes)\n", out_path.c_str(), xml.size());
      }
      return 0;
    }
    if (*cmd_sweep) {
      tactip::SweepOptions o;
      o.scenario = &entry;
      o.base = src;
      for (const auto& p : sweep_params) o.params.push_back(tactip::ParseSweepParam(p));
      o.runs = sweep_runs;
      o.seed = seed;
      o.jobs = jobs;
      o.out_dir = out_path.empty() ? "sweep" : out_path;
      o.detector = sweep_detector;
      o.stop = &g_stop;
      if (!quiet) {
        o.started = [&](size_t designs) {
          std::fprintf(stderr, "sweeping %zu design(s) x %d run(s) of %s into %s/\n", designs, sweep_runs,
                       entry.name.c_str(), o.out_dir.c_str());
        };
      }
      const auto wall0 = std::chrono::steady_clock::now();
      const auto results = tactip::RunSweep(o, [&](int done, int total, const tactip::SweepDesignResult& r) {
        if (quiet) return;
        std::string d;
        for (const auto& [k, v] : r.design) d += (d.empty() ? "" : " ") + k + "=" + v;
        std::fprintf(stderr,
                     "[%d/%d] %s: %d pins, incipient in %d/%d runs, lead %s +- %s s, pre-slip %s, peak %s px/frame, "
                     "detector before fall %d/%d (%.1f s)\n",
                     done, total, d.c_str(), r.n_pins, r.summary.with_incipient, r.summary.runs,
                     Fmt(r.summary.lead_gross_mean_s).c_str(), Fmt(r.summary.lead_gross_std_s).c_str(),
                     Fmt(r.summary.pre_slip_fraction_mean).c_str(), Fmt(r.summary.peak_speed_mean_px).c_str(),
                     r.summary.detected_before_fall, r.summary.runs, r.wall_time_s);
      });
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      std::fprintf(stderr, "done: %zu designs in %.1f s; wrote %s/designs.csv, runs.csv%s\n", results.size(), wall,
                   o.out_dir.c_str(), o.params.size() <= 2 ? " and one heatmap per metric (*.svg)" : "");
      return 0;
    }
    if (*cmd_gen) {
      entry.describe(src);  // validates the config before anything is printed or written
      tactip::GenerateOptions opts;
      tactip::CheckWritableLocation(out_path.empty() ? entry.name + ".h5" : out_path);
      opts.runs = runs;
      opts.seed = seed;
      opts.jobs = jobs;
      opts.scenario = entry.name;
      opts.out_path = out_path.empty() ? entry.name + ".h5" : out_path;
      opts.stop = &g_stop;
      if (!quiet) {
        opts.progress = [](int done, int total, int idx, const tactip::RailRunSummary& s) {
          std::fprintf(stderr,
                       "[%d/%d] run %d: incipient %s s, onset %s s, fall %s s, Coulomb %s s, %.1f s simulated in "
                       "%.1f s%s\n",
                       done, total, idx, Fmt(s.incipient_onset_s).c_str(), Fmt(s.gross_slip_onset_s).c_str(),
                       Fmt(s.object_fall_s).c_str(), Fmt(s.predicted_onset_s).c_str(), s.sim_time_s, s.wall_time_s,
                       s.held ? "" : " (not held: slipped during the lift; press deeper or lighten the object)");
        };
        std::fprintf(stderr, "generating %d %s run(s) into %s\n", runs, entry.name.c_str(), opts.out_path.c_str());
      }
      const tactip::GenerateResult r = entry.generate(src, opts);
      std::fprintf(stderr, "done: %d runs, %.1f s simulated in %.1f s wall (%.1fx real time overall)\n", r.runs,
                   r.sim_time_s, r.wall_time_s, r.sim_time_s / r.wall_time_s);
      PrintDatasetSummary(opts.out_path, false);
      return 0;
    }
  } catch (const tactip::InputError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 2;
  } catch (const tactip::DetectorInputError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 2;
  } catch (const tactip::ModelError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 2;
  } catch (const tactip::SimulationError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 3;
  } catch (const tactip::Interrupted&) {
    std::fprintf(stderr, "tactip: interrupted; no output written\n");
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tactip: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
