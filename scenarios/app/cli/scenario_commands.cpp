#include "scenarios/app/cli/scenario_commands.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "sensors/dataset_merge.h"
#include "sim/base/files.h"
#include "sim/base/progress.h"

namespace tactip::cli {

namespace {

// Options of the scenario subcommands (owned by the returned closure).
struct ScenarioArgs {
  ConfigArgs config;
  std::string out;
  int runs = 4, jobs = 0;
  unsigned long long seed = 1;
  bool quiet = false;
  std::string shard;                      // --shard i/n ("" = the whole job)
  std::vector<std::string> merge_inputs;  // shard files to merge
  std::string info_path;
  bool no_config = false;
  bool as_yaml = false, with_comments = false;
};

// tactip config: the table of keys, or the resolved config as (commented) YAML.
int RunConfig(const Scenario& scenario, const ConfigSource& src, const ScenarioArgs& a) {
  CheckAndReport(scenario, src);
  const auto fields = scenario.Describe(src);
  if (a.as_yaml && a.with_comments) {
    const std::string header = fmt::format(
        "# {} scenario: every config key with its meaning; values as resolved from the given options.\n"
        "# Use with: tactip generate {} --config FILE [--set key=value ...]\n"
        "# 'tactip config {}' prints the same keys with units and allowed ranges.\n",
        scenario.name(), scenario.name(), scenario.name());
    std::printf("%s", FieldsToCommentedYaml(fields, header).c_str());
    return 0;
  }
  if (a.as_yaml) {
    std::printf("%s", FieldsToYaml(fields).c_str());
    return 0;
  }
  for (const auto& f : fields) {
    std::printf("%-32s %-12s %-8s %-16s %s\n", f.key.c_str(), f.value.c_str(), f.unit.c_str(), f.allowed.c_str(),
                f.doc.c_str());
  }
  return 0;
}

// tactip export-mjcf: the scene's MJCF to a file or standard output.
int RunExport(const Scenario& scenario, const ConfigSource& src, const std::string& out) {
  CheckOutputsAreNotInputs({{"--out", out}}, {{"--config", src.yaml_path}});
  if (!out.empty()) CheckWritableLocation(out);
  CheckAndReport(scenario, src);
  const std::string xml = scenario.ExportMjcf(src);
  if (out.empty()) {
    std::printf("%s", xml.c_str());
  } else {
    WriteFileAtomic(out, xml);
    ProgressF("wrote %s (%zu bytes)\n", out.c_str(), xml.size());
  }
  return 0;
}

// One progress line per finished run.
void PrintRunProgress(int done, int total, int idx, const RailRunSummary& s) {
  const std::string health = s.health.ok ? "health ok" : "UNHEALTHY: " + s.health.reason;
  ProgressF(
               "[%d/%d] run %d: incipient %s s, onset %s s, fall %s s, Coulomb %s s, %.1f s simulated in %.1f s; "
               "%s%s\n",
               done, total, idx, Fmt(s.incipient_onset_s).c_str(), Fmt(s.gross_slip_onset_s).c_str(),
               Fmt(s.object_fall_s).c_str(), Fmt(s.predicted_onset_s).c_str(), s.sim_time_s, s.wall_time_s,
               health.c_str(), s.held ? "" : " (not held: slipped during the lift; press deeper or lighten the object)");
}

// tactip generate: simulate and write the dataset, then print its summary.
int RunGenerate(const Scenario& scenario, const ConfigSource& src, const ScenarioArgs& a,
                const std::atomic<bool>* stop) {
  GenerateOptions opts;
  opts.out_path = a.out.empty() ? scenario.name() + ".h5" : a.out;
  CheckOutputsAreNotInputs({{"--out", opts.out_path}}, {{"--config", src.yaml_path}});
  CheckAndReport(scenario, src);  // validates the config before anything is printed or written
  if (!a.shard.empty()) opts.shard = ParseShardOption(a.shard, a.runs);
  CheckWritableLocation(opts.out_path);
  opts.runs = a.runs;
  opts.seed = a.seed;
  opts.jobs = a.jobs;
  opts.scenario = scenario.name();
  opts.stop = stop;
  if (!a.quiet) {
    opts.progress = PrintRunProgress;
    if (opts.shard) {
      ProgressF("generating shard %s: %s %s into %s\n", opts.shard->text().c_str(),
                   scenario.name().c_str(), opts.shard->runs_text().c_str(), opts.out_path.c_str());
    } else {
      ProgressF("generating %d %s run(s) into %s\n", a.runs, scenario.name().c_str(), opts.out_path.c_str());
    }
  }
  const GenerateResult r = scenario.Generate(src, opts);
  ProgressF("done: %d runs, %.1f s simulated in %.1f s wall (%.1fx real time overall)\n", r.runs,
               r.sim_time_s, r.wall_time_s, r.sim_time_s / r.wall_time_s);
  PrintDatasetSummary(opts.out_path, false);
  return 0;
}

// tactip merge: join shard files into the whole job's dataset, then print its summary.
int RunMerge(const ScenarioArgs& a, const std::atomic<bool>* stop) {
  MergeOptions opts;
  opts.stop = stop;
  if (!a.quiet) {
    opts.progress = [](const std::string& path, const ShardSpec& s) {
      ProgressF("merged %s: shard %s, %s\n", path.c_str(), s.text().c_str(), s.runs_text().c_str());
    };
  }
  const MergeResult r = MergeShards(a.merge_inputs, a.out, opts);
  ProgressF("done: %d runs from %d shard file(s) into %s\n", r.runs, r.shards, a.out.c_str());
  PrintDatasetSummary(a.out, false);
  return 0;
}

}  // namespace

std::function<int()> AddScenarioCommands(CLI::App& app, const std::atomic<bool>* stop) {
  auto a = std::make_shared<ScenarioArgs>();

  auto* list = app.add_subcommand("scenarios", "List the registered scenarios with one-line descriptions.");

  auto* gen = app.add_subcommand("generate", "Simulate runs of a scenario and write a labelled HDF5 dataset.");
  a->config.Add(gen);
  a->config.AddAutoTimestep(gen);
  a->config.AddImages(gen);
  gen->add_option("--runs", a->runs, "Number of runs (default 4).")->check(CLI::Range(1, 100000));
  AddSeedOption(gen, a->seed, "Master seed; run i derives its own seed from it (default 1).");
  gen->add_option("--out", a->out, "Output HDF5 file (default SCENARIO.h5); written atomically.")
      ->check(NonEmpty("a file name"));
  gen->add_option("--jobs", a->jobs, "Worker threads (default: all cores); results do not depend on it.")
      ->check(CLI::Range(0, 256));
  gen->add_option("--shard", a->shard,
                  "Simulate only shard i of n: runs floor(i*R/n) to floor((i+1)*R/n)-1 of the R = --runs runs, "
                  "bit-identical to the same runs of the whole job; join the shard files with 'tactip merge'.")
      ->type_name("i/n")
      ->check(NonEmpty("i/n, e.g. 0/4"));
  gen->add_flag("--quiet", a->quiet, "No per-run progress lines.");

  auto* merge = app.add_subcommand(
      "merge", "Join shard files (generate --shard i/n) into the dataset one machine writes for the whole job.");
  merge->add_option("files", a->merge_inputs, "Shard files, any order; together they must hold every run once.")
      ->required()
      ->check(NonEmpty("a shard file"));
  merge->add_option("--out", a->out, "Output HDF5 file; written atomically; must not be one of the inputs.")
      ->required()
      ->check(NonEmpty("a file name"));
  merge->add_flag("--quiet", a->quiet, "No per-shard progress lines.");

  auto* info = app.add_subcommand("info", "Show the runs, frames, slip onsets and config of a dataset.");
  info->add_option("file", a->info_path, "HDF5 dataset written by 'tactip generate'.")
      ->required()
      ->check(NonEmpty("an HDF5 dataset"));
  info->add_flag("--no-config", a->no_config, "Do not print the stored config.");

  auto* exp = app.add_subcommand("export-mjcf", "Write the exact MuJoCo model (MJCF) a scenario builds.");
  a->config.Add(exp);
  a->config.AddAutoTimestep(exp);
  exp->add_option("--out", a->out, "Output XML file (default: standard output).")->check(NonEmpty("a file name"));

  auto* cfg = app.add_subcommand("config", "List every config key of a scenario with unit, range and meaning.");
  a->config.Add(cfg);
  a->config.AddAutoTimestep(cfg);
  cfg->add_flag("--yaml", a->as_yaml, "Print the resolved config as YAML instead of the table.");
  cfg->add_flag("--comments", a->with_comments, "With --yaml: each key's meaning and unit as a comment above it.");

  return [a, list, gen, merge, info, exp, cfg, stop]() -> int {
    if (*merge) return RunMerge(*a, stop);
    if (*list) {
      for (const auto& s : Scenarios()) std::printf("%-12s %s\n", s->name().c_str(), s->description().c_str());
      return 0;
    }
    if (*info) {
      PrintDatasetSummary(a->info_path, !a->no_config);
      return 0;
    }
    if (!*gen && !*exp && !*cfg) return -1;
    const Scenario& scenario = FindScenario(a->config.scenario);
    const ConfigSource src = a->config.Source();
    if (*cfg) return RunConfig(scenario, src, *a);
    if (*exp) return RunExport(scenario, src, a->out);
    return RunGenerate(scenario, src, *a, stop);
  };
}

}  // namespace tactip::cli
