#include "scenarios/app/cli/accuracy_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "scenarios/studies/accuracy/study.h"
#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "scenarios/figures/plot.h"
#include "sim/base/files.h"
#include "sim/base/progress.h"

namespace tactip::cli {

namespace {

struct AccuracyArgs {
  ConfigArgs config;
  int runs = 2, jobs = 0;
  unsigned long long seed = 1;
  std::string out;
  std::vector<std::string> settings;
  bool list = false, no_plots = false, quiet = false;
};

// --list: the settings of the scene, with their overrides.
int ListSettings(const AccuracyOptions& o) {
  for (const auto& s : AccuracySettings(o)) {
    std::string o;
    for (const auto& k : s.overrides) o += (o.empty() ? "" : " ") + k;
    std::printf("%-20s %s%s\n", s.label.c_str(), o.empty() ? "(built-in defaults)" : o.c_str(),
                s.is_reference ? "  [reference]" : (s.is_default ? "  [default]" : ""));
  }
  return 0;
}

// Writes accuracy.csv and, unless --no-plots, accuracy.png into the output folder.
void WriteOutputs(const AccuracyReport& report, const AccuracyArgs& a) {
  const std::filesystem::path dir(a.out);
  const std::string csv = (dir / "accuracy.csv").string();
  WriteFileAtomic(csv, AccuracyCsv(report));
  ProgressF("wrote %s\n", csv.c_str());
  if (a.no_plots) return;
  ParetoPlot p;
  p.csv = csv;
  p.y_columns = AccuracyErrorColumns(report.scene);
  p.title = "tactip accuracy " + report.scene + ": error against run time";
  p.out_png = (dir / "accuracy.png").string();
  PlotPareto(p);
  ProgressF("wrote %s\n", p.out_png.c_str());
}

int RunAccuracyCommand(const AccuracyArgs& a, const std::atomic<bool>* stop) {
  const std::string scene = a.config.scenario;
  AccuracyOptions o;
  o.scene = scene;
  o.base = a.config.Source();
  if (a.list) return ListSettings(o);
  o.runs = a.runs;
  o.seed = a.seed;
  o.jobs = a.jobs;
  o.only = a.settings;
  o.stop = stop;
  // Everything that can be wrong is found before the first run: the scene, the settings,
  // the config, the output folder and the plotting tool.
  if (!a.out.empty()) {
    CheckOutputsAreNotInputs(FilesInFolder("--out", a.out, {"accuracy.csv", "accuracy.png"}),
                             {{"--config", a.config.config_path}});
  }
  CheckAccuracyOptions(o);
  NewFolderGuard folder(a.out);
  PrepareOutputFolder(a.out, "accuracy.csv");
  if (!a.out.empty() && !a.no_plots) CheckPlotting();
  if (!a.quiet) {
    o.progress = [](int done, int total, const AccuracyRow& row) {
      ProgressF("[%d/%d] %s: %s (%.3f s wall per simulated s)\n", done, total, row.setting.label.c_str(),
                   row.outcome.c_str(), row.wall_s_per_sim_s);
    };
    ProgressF("accuracy of %s: %d run(s) per setting, camera noise off\n", scene.c_str(), a.runs);
  }
  const AccuracyReport report = RunAccuracy(o);
  std::printf("%s", FormatAccuracyTable(report).c_str());
  if (!a.out.empty()) WriteOutputs(report, a);
  folder.Keep();
  return 0;
}

}  // namespace

std::function<int()> AddAccuracyCommand(CLI::App& app, const std::atomic<bool>* stop) {
  auto a = std::make_shared<AccuracyArgs>();
  auto* c = app.add_subcommand("accuracy",
                               "Error against run time: run a scene at every numerical setting (timestep, solver, "
                               "noslip pass, cone and impratio, contact softness) and compare each with the finest "
                               "setting and the analytic anchors.");
  a->config.Add(c);
  c->get_option("scenario")->description("Scene: rail, incipient (scenarios) or domes (the dome checks of 'validate "
                                         "contact').");
  c->add_option("--runs", a->runs, "Runs per setting, the same seeds for every setting (default 2).")
      ->check(CLI::Range(1, 1000));
  AddSeedOption(c, a->seed, "Master seed (default 1).");
  c->add_option("--jobs", a->jobs, "Worker threads (default: all cores).")->check(CLI::Range(0, 256));
  c->add_option("--out", a->out, "Folder for accuracy.csv and accuracy.png (created if missing).")
      ->check(NonEmpty("a folder"));
  c->add_option("--setting", a->settings, "Run only this setting (repeatable; the reference always runs); see --list.")
      ->check(NonEmpty("a setting name (see --list)"));
  c->add_flag("--list", a->list, "List the scene's settings and exit.");
  c->add_flag("--no-plots", a->no_plots, "With --out: write the CSV only.");
  c->add_flag("--quiet", a->quiet, "No per-setting progress lines.");
  return [a, c, stop]() -> int { return *c ? RunAccuracyCommand(*a, stop) : -1; };
}

}  // namespace tactip::cli
