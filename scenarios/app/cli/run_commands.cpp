#include "scenarios/app/cli/run_commands.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "scenarios/incipient_stop/stop_trials.h"
#include "scenarios/rail_catch/catch_report.h"
#include "sim/base/progress.h"
#include "sim/config.h"
#include "sim/base/files.h"

namespace tactip::cli {

namespace {

// Where `tactip bench` leaves its RBF SVM with its default --out.
constexpr const char* kBenchDefaultModel = "bench-results/svm-rbf.model";

// The options both closed-loop commands take: how many trials, their seed, the cores, the
// output folder and the progress lines.
struct TrialArgs {
  int trials = 20;
  unsigned long long seed = 1;
  int jobs = 0;
  std::string out;   // --out DIR
  bool quiet = false;
};

// Registers TrialArgs' options on `c`; the help texts say what differs between the commands.
void AddTrialOptions(CLI::App* c, TrialArgs& t, const std::string& trials_help, const std::string& seed_help,
                     const std::string& out_help) {
  c->add_option("--trials", t.trials, trials_help)->check(CLI::Range(1, 10000));
  AddSeedOption(c, t.seed, seed_help);
  c->add_option("--jobs", t.jobs, "Trials run at once (default: all cores).")->check(CLI::Range(0, 256));
  c->add_option("--out", t.out, out_help)->type_name("DIR")->check(NonEmpty("a folder"));
  c->add_flag("--quiet", t.quiet, "No per-trial progress lines.");
}

// Options of `tactip run rail-catch` (owned by the returned closure).
struct CatchArgs {
  ConfigArgs config;                  // --config, --set, --skin (the rail scenario's config)
  std::string model;                  // --model FILE
  CatchOptions loop;                  // --response, latencies, catch speed, hold
  std::string speeds = "1";           // --speed-mm-s LIST
  std::string stimuli = "flat";       // --stimulus LIST
  TrialArgs trial;                    // --trials, --seed, --jobs, --out, --quiet
};

// "a,b,c" -> its non-empty items; throws InputError naming `option` for an empty item.
std::vector<std::string> SplitList(const std::string& option, const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) throw InputError(fmt::format("{} '{}': empty item in the list", option, text));
    items.push_back(item);
  }
  if (items.empty() || text.back() == ',') throw InputError(fmt::format("{} '{}': empty item in the list", option, text));
  return items;
}

// The retraction speeds of --speed-mm-s, each in the hardware's range 0.1-20 mm/s.
std::vector<double> ParseSpeeds(const std::string& text) {
  std::vector<double> speeds;
  for (const std::string& item : SplitList("--speed-mm-s", text)) {
    const double v = config_detail::ParseReal("--speed-mm-s", item);
    if (!(v >= 0.1 && v <= 20.0)) {
      throw InputError(fmt::format("--speed-mm-s {}: must be in [0.1, 20] mm/s (the hardware's range)", item));
    }
    speeds.push_back(v);
  }
  return speeds;
}

// Writes each (name, text) into folder `out` (none when `out` is empty) and the closing
// "done: N trial(s) in S s wall; wrote NAMES in OUT" line on stderr.
void WriteTrialOutputs(const std::string& out, const std::vector<std::pair<std::string, std::string>>& files,
                       size_t trials, double wall_s) {
  std::string names;
  for (const auto& [name, text] : files) {
    if (!out.empty()) WriteFileAtomic((std::filesystem::path(out) / name).string(), text);
    names += (names.empty() ? "" : ", ") + name;
  }
  ProgressF("done: %zu trial(s) in %.1f s wall%s\n", trials, wall_s,
               out.empty() ? "" : ("; wrote " + names + " in " + out).c_str());
}

// The config of one (stimulus, speed) row: the user's config with the two shortcuts set.
RailScenarioConfig RowConfig(const CatchArgs& a, const std::string& stimulus, double speed) {
  ConfigArgs row = a.config;
  row.stimulus = stimulus;
  row.speed_mm_s = speed;
  return RailFamily(FindScenario("rail")).Load(row.Source());
}

int RunRailCatch(const CatchArgs& a, const std::atomic<bool>* stop) {
  // Everything checked before the first trial: model, loop, lists, configs, output folder.
  const std::string model = a.model.empty() ? kBenchDefaultModel : a.model;
  if (a.model.empty() && !std::filesystem::exists(model)) {
    throw InputError(fmt::format("no detector model: '{}' does not exist; train one with 'tactip bench' (it writes "
                                 "it) or 'tactip train', or give --model FILE",
                                 model));
  }
  LoadDetector(model);
  a.loop.Validate();
  const std::vector<double> speeds = ParseSpeeds(a.speeds);
  std::vector<std::string> stimuli = SplitList("--stimulus", a.stimuli);
  if (stimuli == std::vector<std::string>{"all"}) stimuli = {"flat", "curved80", "curved40", "curved20"};
  std::vector<RailScenarioConfig> rows;
  for (const std::string& s : stimuli) {
    for (double v : speeds) rows.push_back(RowConfig(a, s, v));
  }
  for (const RailScenarioConfig& row : rows) a.loop.ValidateFor(row.rail);
  NewFolderGuard folder(a.trial.out);
  PrepareOutputFolder(a.trial.out, "trials.csv");
  // The trials, row by row, with a progress line per trial.
  CatchTrialOptions o;
  o.model_path = model;
  o.loop = a.loop;
  o.trials = a.trial.trials;
  o.seed = a.trial.seed;
  o.jobs = a.trial.jobs;
  o.stop = stop;
  if (!a.trial.quiet) {
    o.progress = [](const CatchTrial& t) {
      ProgressF("%s %g mm/s trial %d: %s, slip %.1f mm, declared %s s after onset %s s\n",
                   t.stimulus.c_str(), t.speed_mm_s, t.trial, ToString(t.outcome).c_str(), t.slip_distance_mm,
                   Fmt(t.declared_s).c_str(), Fmt(t.onset_s).c_str());
    };
  }
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<CatchTrial> trials;
  for (const RailScenarioConfig& cfg : rows) {
    const std::vector<CatchTrial> row = RunCatchTrials(cfg, o);
    trials.insert(trials.end(), row.begin(), row.end());
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  // The table, and in --out the trials and the summary.
  const std::vector<CatchSummaryRow> summary = SummariseCatch(trials);
  const std::string table = FormatCatchTable(summary);
  std::printf("rail catch: model %s, response %s, latency %g ms classify + %g ms arm, catch at %g mm/s\n%s",
              model.c_str(), a.loop.response.c_str(), a.loop.classify_ms, a.loop.arm_response_ms,
              a.loop.catch_speed_mm_s, table.c_str());
  WriteTrialOutputs(a.trial.out,
                    {{"trials.csv", CatchTrialsCsv(trials)}, {"summary.csv", CatchSummaryCsv(summary)},
                     {"summary.txt", table}},
                    trials.size(), wall);
  folder.Keep();
  return 0;
}

// Registers `tactip run rail-catch`.
CLI::App* AddRailCatch(CLI::App* run, CatchArgs& a) {
  auto* c = run->add_subcommand(
      "rail-catch",
      "The hardware's online slip detection and grasp recovery: the rail protocol with a trained detector reading "
      "every camera frame; when the response strategy fires, the arm (after the loop's latency) moves back in to "
      "catch the object. Scores each trial caught / false_positive / dropped with the slip distance.");
  a.config.AddFileAndSets(c, "YAML config file of the rail scenario.", "Override one rail config key (repeatable).");
  a.config.AddSkin(c, "Skin preset: smooth, fingerprint-v1 or fingerprint-v2.");
  a.config.AddCamera(c);
  c->add_option("--model", a.model, fmt::format("Trained detector (default: {}, which 'tactip bench' writes).",
                                                kBenchDefaultModel))
      ->check(NonEmpty("a model file"));
  c->add_option("--response", a.loop.response, "Response strategy NFr1Sen (default 2Fr1Sen, as on hardware).")
      ->check(NonEmpty("e.g. 2Fr1Sen"));
  c->add_option("--classify-ms", a.loop.classify_ms, "Classification time per frame, ms (default 3, hardware).")
      ->check(FiniteNumber());
  c->add_option("--arm-response-ms", a.loop.arm_response_ms, "From the command to the arm moving, ms (default 10).")
      ->check(FiniteNumber());
  c->add_option("--catch-speed-mm-s", a.loop.catch_speed_mm_s, "Speed of the arm moving back in (default 50).")
      ->check(FiniteNumber());
  c->add_option("--catch-extra-mm", a.loop.catch_extra_mm,
                "How far past the press depth the arm moves back in, 0-4 mm (default 0: to the press depth).")
      ->check(FiniteNumber());
  c->add_option("--hold-s", a.loop.hold_s, "How long the trial watches the object once the arm is back (default 0.5).")
      ->check(FiniteNumber());
  c->add_option("--speed-mm-s", a.speeds, "Retraction speeds, comma-separated, 0.1-20 mm/s (default 1).")
      ->type_name("LIST")
      ->check(NonEmpty("e.g. 0.1,1,3,5,10,20"));
  c->add_option("--stimulus", a.stimuli, "Stimuli, comma-separated, or all (default flat).")
      ->type_name("LIST")
      ->check(NonEmpty("e.g. flat,curved40 or all"));
  AddTrialOptions(c, a.trial, "Trials per stimulus and speed (default 20).",
                  "Seed: trial i is rail run i of this seed (default 1).",
                  "Write trials.csv, summary.csv and summary.txt into DIR (created).");
  return c;
}

// Options of `tactip run incipient-stop` (owned by the returned closure).
struct StopArgs {
  ConfigArgs config;   // --config, --set, --skin, --speed-mm-s (the incipient scenario's config)
  StopOptions loop;    // steps, pause, hold, markers, detector
  TrialArgs trial;     // --trials, --seed, --jobs, --out, --quiet
};

int RunIncipientStop(const StopArgs& a, const std::atomic<bool>* stop) {
  // Everything checked before the first trial: loop, config, output folder.
  a.loop.Validate();
  const RailScenarioConfig cfg = RailFamily(FindScenario("incipient")).Load(a.config.Source());
  NewFolderGuard folder(a.trial.out);
  PrepareOutputFolder(a.trial.out, "trials.csv");
  StopTrialOptions o;
  o.loop = a.loop;
  o.trials = a.trial.trials;
  o.seed = a.trial.seed;
  o.jobs = a.trial.jobs;
  o.stop = stop;
  if (!a.trial.quiet) {
    o.progress = [](const StopTrial& t) {
      ProgressF("%s trial %d: %s, stop %s s, gross onset %s s, fall %s s\n", t.skin.c_str(), t.trial,
                   ToString(t.outcome).c_str(), Fmt(t.stop_s).c_str(), Fmt(t.onset_s).c_str(), Fmt(t.fall_s).c_str());
    };
  }
  const auto wall0 = std::chrono::steady_clock::now();
  const std::vector<StopTrial> trials = RunStopTrials(cfg, o);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const std::string table = FormatStopTable(trials);
  std::printf("incipient stop: %s, steps of %g mm at %g mm/s with %g s pauses, %s markers, W=%d s_thr=%g px I_thr=%d\n%s",
              cfg.rail.stimulus.c_str(), a.loop.step_mm, cfg.rail.retract_speed_mm_s, a.loop.pause_s,
              a.loop.markers.c_str(), a.loop.detector.window, a.loop.detector.speed_thr_px, a.loop.detector.count_thr,
              table.c_str());
  WriteTrialOutputs(a.trial.out, {{"trials.csv", StopTrialsCsv(trials)}, {"summary.txt", table}}, trials.size(), wall);
  folder.Keep();
  return 0;
}

// Registers `tactip run incipient-stop`.
CLI::App* AddIncipientStop(CLI::App* run, StopArgs& a) {
  auto* c = run->add_subcommand(
      "incipient-stop",
      "The hardware's online incipient-slip detection on the transparent-acrylic rig: after the lift the arm retracts "
      "in small steps and stops when the incipient detector (bulk subtraction) fires. Scores each trial stopped / "
      "stopped_late / missed. Config: the incipient scenario's (fingerprint-v2 skin by default).");
  a.config.AddFileAndSets(c, "YAML config file of the incipient scenario.", "Override one config key (repeatable).");
  a.config.AddSkin(c, "Skin preset: smooth, fingerprint-v1 or fingerprint-v2 (default).");
  a.config.AddCamera(c);
  c->add_option("--speed-mm-s", a.config.speed_mm_s, "Speed of each retraction step (default 0.3 mm/s).")
      ->check(NumberWithin(0.1, 20.0));
  c->add_option("--step-mm", a.loop.step_mm, "Retraction per step (default 0.2 mm).")->check(FiniteNumber());
  c->add_option("--pause-s", a.loop.pause_s, "Still time after each step (default 0.3 s).")->check(FiniteNumber());
  c->add_option("--hold-s", a.loop.hold_s, "How long the trial watches the object after the stop (default 2 s).")
      ->check(FiniteNumber());
  c->add_option("--markers", a.loop.markers, "Markers the detector reads: internal (default) or external.")
      ->check(NonEmpty("internal or external"));
  c->add_option("--window", a.loop.detector.window, "Detector W: moving-average frames (default 5).");
  c->add_option("--speed-thr-px", a.loop.detector.speed_thr_px, "Detector s_thr, px/frame (default 0.2).")
      ->check(FiniteNumber());
  c->add_option("--count-thr", a.loop.detector.count_thr, "Detector I_thr: pins (default 4).");
  AddTrialOptions(c, a.trial, "Trials (default 20).", "Seed: trial i is run i of this seed (default 1).",
                  "Write trials.csv and summary.txt into DIR (created).");
  return c;
}

}  // namespace

std::function<int()> AddRunCommands(CLI::App& app, const std::atomic<bool>* stop) {
  auto* run = app.add_subcommand("run", "Closed-loop protocols: a detector reads every camera frame and acts.");
  run->require_subcommand(1);
  auto a = std::make_shared<CatchArgs>();
  auto* rail_catch = AddRailCatch(run, *a);
  auto b = std::make_shared<StopArgs>();
  auto* incipient_stop = AddIncipientStop(run, *b);
  return [a, b, rail_catch, incipient_stop, stop]() -> int {
    if (*rail_catch) return RunRailCatch(*a, stop);
    if (*incipient_stop) return RunIncipientStop(*b, stop);
    return -1;
  };
}

}  // namespace tactip::cli
