#include "scenarios/cli/detect_commands.h"

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "detectors/incipient.h"
#include "detectors/logreg.h"
#include "detectors/metrics.h"
#include "detectors/response.h"
#include "detectors/svm.h"
#include "detectors/threshold.h"
#include "scenarios/bench.h"
#include "scenarios/cli/lean_command.h"
#include "scenarios/slip_data.h"
#include "scenarios/speed.h"
#include "sim/files.h"

namespace tactip::cli {

namespace {

// Parses "0.1,1,10" into numbers; throws InputError naming the option.
std::vector<double> ParseGrid(const std::string& opt, const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      const double v = std::stod(item, &used);
      if (used != item.size() || !(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument("bad");
      out.push_back(v);
    } catch (const std::exception&) {
      throw InputError(fmt::format("{} '{}': expected positive numbers separated by commas", opt, text));
    }
  }
  if (out.empty()) throw InputError(fmt::format("{} '{}': expected at least one value", opt, text));
  return out;
}

// Options shared by commands that build training sets.
struct TrainArgs {
  std::string features = "drdtheta";
  int n_slip = 4;
  double downsample = 0.4;
  unsigned long long seed = 1;
  int folds = 4;
  std::string c_grid, gamma_grid;
  bool score_onset_frame = false;

  void Add(CLI::App* c, bool with_seed = true) {
    c->add_flag("--score-onset-frame", score_onset_frame,
                "Label the frame whose velocity spans the onset as slip (default: it is a transition frame, "
                "neither trained on nor scored).");
    c->add_option("--features", features, "Velocity features: drdtheta (default), dr or dtheta.");
    c->add_option("--n-slip", n_slip, "Frames after the ground-truth onset labelled slip (1-15, default 4).")
        ->check(CLI::Range(1, 15));
    c->add_option("--downsample", downsample, "Fraction of static frames kept for training (default 0.4).")
        ->check(CLI::Range(1e-6, 1.0));
    if (with_seed) c->add_option("--seed", seed, "Seed of the static-frame downsampling (default 1).");
    c->add_option("--folds", folds, "Folds of the cross-validation grouped by run (default 4).")
        ->check(CLI::Range(2, 50));
    c->add_option("--c-grid", c_grid, "SVM / logistic C candidates, e.g. 0.1,1,10,100.");
    c->add_option("--gamma-grid", gamma_grid, "RBF gamma candidates in units of 1/dim, e.g. 0.25,1,4.");
  }
  TrainOptions Options() const {
    TrainOptions o;
    o.features = ParseFeatureSet(features);
    o.n_slip = n_slip;
    o.static_fraction = downsample;
    o.seed = seed;
    o.cv_folds = folds;
    if (!c_grid.empty()) o.c_grid = ParseGrid("--c-grid", c_grid);
    if (!gamma_grid.empty()) o.gamma_scale_grid = ParseGrid("--gamma-grid", gamma_grid);
    return o;
  }
};

// Writes one CSV row per frame of every run: run,frame,time_s,slip[,n_slipping][,d_px].
std::string DecisionsCsv(Detector& det, const std::vector<LabeledRun>& runs, bool with_count, bool with_contact) {
  std::string out = std::string("run,frame,time_s,slip") + (with_count ? ",n_slipping" : "") +
                    (with_contact ? ",d_px" : "") + "\n";
  ContactMeasure contact;
  for (const LabeledRun& run : runs) {
    det.Reset();
    contact.Reset();
    for (size_t k = 0; k < run.frames.size(); ++k) {
      const Decision d = det.Update(run.frames[k]);
      out += fmt::format("{},{},{},{}", run.run, k, run.frames[k].time_s, d.slip ? 1 : 0);
      if (with_count) out += fmt::format(",{}", d.n_slipping);
      if (with_contact) out += fmt::format(",{}", contact.Update(run.frames[k]));
      out += "\n";
    }
  }
  return out;
}

// Wraps a detector in a response strategy when one is given ("2Fr1Sen").
std::unique_ptr<Detector> WithResponse(std::unique_ptr<Detector> det, const std::string& response) {
  if (response.empty()) return det;
  return std::make_unique<ResponseDetector>(std::move(det), ResponseStrategy::Parse(response, 1));
}

// tactip bench --speed: the speed study's table, and DIR/speed.csv when an output folder is given.
int RunSpeedStudy(const std::vector<std::string>& scenes, const std::vector<std::string>& sets,
                  const std::string& out_dir, std::uint64_t seed) {
  ChooseSpeedScenes(scenes);  // an unknown scene is named before anything runs
  if (!out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    CheckWritableLocation((std::filesystem::path(out_dir) / "speed.csv").string());
  }
  std::fprintf(stderr, "bench --speed: one run per scene on one core, every step timed\n");
  const std::vector<SpeedRow> rows = MeasureSpeed(scenes, sets, seed);
  std::printf("%s", FormatSpeedTable(rows).c_str());
  if (!out_dir.empty()) {
    const std::string path = (std::filesystem::path(out_dir) / "speed.csv").string();
    WriteFileAtomic(path, SpeedCsv(rows));
    std::fprintf(stderr, "wrote %s\n", path.c_str());
  }
  return 0;
}

}  // namespace

std::function<int()> AddDetectorCommands(CLI::App& app, const std::atomic<bool>* stop) {
  // Shared state for the handlers below (owned by the returned closure).
  struct State {
    std::string kind, kernel = "rbf", data, runs, out, model;
    TrainArgs train;
    int window = 5, count_thr = 4;
    double speed_thr = 0.2;
    bool per_run = false;
    bool score_onset_frame = false;
    bool contact_measure = false;
    std::string response;
    // bench
    std::string bench_out = "bench-results", bench_dataset, config;
    std::vector<std::string> sets;
    int bench_runs = 40, jobs = 0;
    double speed = std::nan("");
    unsigned long long bench_seed = 2026;
    bool speed_study = false, lean_study = false;
    int repeats = 1;
    std::vector<std::string> speed_scenes;
  };
  auto s = std::make_shared<State>();

  // tactip train
  auto* train = app.add_subcommand("train", "Train a gross-slip detector on runs of a dataset and save the model.");
  train->add_option("kind", s->kind, "threshold, logreg, svm (kernel from --kernel), svm-linear or svm-rbf.")
      ->required()
      ->check(CLI::IsMember({"threshold", "logreg", "svm", "svm-linear", "svm-rbf"}));
  train->add_option("--data", s->data, "HDF5 dataset written by 'tactip generate'.")->required();
  train->add_option("--runs", s->runs, "Runs to train on, e.g. 0-19 (default: all).");
  train->add_option("--out", s->out, "Model file to write.")->required();
  train->add_option("--kernel", s->kernel, "SVM kernel for 'svm': rbf (Gaussian, default) or linear.")
      ->check(CLI::IsMember({"rbf", "linear"}));
  s->train.Add(train);

  // tactip evaluate
  auto* eval = app.add_subcommand("evaluate", "Score a trained model on runs of a dataset (metrics table).");
  eval->add_option("--model", s->model, "Model written by 'tactip train'.")->required();
  eval->add_option("--data", s->data, "HDF5 dataset with ground truth.")->required();
  eval->add_option("--runs", s->runs, "Runs to score, e.g. 20-39 (default: all).");
  eval->add_option("--n-slip", s->train.n_slip, "Frames after the onset scored as slip (default 4).")
      ->check(CLI::Range(1, 15));
  eval->add_flag("--per-run", s->per_run, "Also print one line per run.");
  eval->add_option("--response", s->response,
                   "Act only on a response strategy, e.g. 2Fr1Sen (two consecutive slip frames).");
  eval->add_flag("--score-onset-frame", s->score_onset_frame,
                 "Score the frame whose velocity spans the onset as slip (default: not scored).");

  // tactip detect
  auto* detect = app.add_subcommand(
      "detect", "Run a detector over recorded frames (HDF5 dataset or real-TacTip CSV) and write its decisions.");
  detect->add_option("kind", s->kind, "'incipient' for the bulk-subtraction incipient detector; omit with --model.")
      ->check(CLI::IsMember({"incipient"}));
  detect->add_option("--model", s->model, "Model written by 'tactip train'.");
  detect->add_option("--data", s->data,
                     "Input frames: a .h5 dataset or a .csv recording with columns frame,time_s,pin,x_px,y_px.")
      ->required();
  detect->add_option("--runs", s->runs, "Runs of an HDF5 dataset (default: all).");
  detect->add_option("--out", s->out, "Output CSV: run,frame,time_s,slip (and n_slipping for incipient).")->required();
  detect->add_option("--window", s->window, "Incipient: moving-average window W in frames (default 5).");
  detect->add_option("--speed-thr-px", s->speed_thr, "Incipient: speed threshold s_thr in px/frame (default 0.2).");
  detect->add_option("--count-thr", s->count_thr, "Incipient: pins needed to declare incipient slip (default 4).");
  detect->add_option("--response", s->response,
                     "Act only on a response strategy, e.g. 2Fr1Sen (two consecutive slip frames).");
  detect->add_flag("--contact-measure", s->contact_measure,
                   "Add a column d_px: mean pin displacement from the run's first (no-contact) frame.");

  // tactip bench
  auto* bench = app.add_subcommand(
      "bench", "The slip benchmark: standard rail dataset, every detector trained and evaluated, hardware beside.");
  bench->add_option("--out", s->bench_out, "Output folder for bench.json, bench.csv and models (default bench-results).");
  bench->add_option("--dataset", s->bench_dataset, "Use this dataset instead of generating the standard one.");
  bench->add_option("--runs", s->bench_runs, "Runs of the standard dataset (default 40; half train, half test).")
      ->check(CLI::Range(4, 10000));
  bench->add_option("--speed-mm-s", s->speed,
                    "Shortcut for --set rail.retract_speed_mm_s=V for the generated dataset (default 0.1).");
  bench->add_option("--seed", s->bench_seed, "Dataset and training seed (default 2026).");
  bench->add_option("--jobs", s->jobs, "Generation threads (default: all cores).");
  bench->add_option("--config", s->config, "YAML rail config for the generated dataset.")->check(CLI::ExistingFile);
  bench->add_option("--set", s->sets, "Override a rail config key (repeatable).")->type_name("KEY=VALUE");
  auto* speed = bench->add_flag("--speed", s->speed_study,
                  "Instead of the slip benchmark: the speed study (real-time factor of each scene, the cost split of "
                  "a step, the scenario's overhead over its physics and bare mj_step on the same model); "
                  "single-threaded, one run per scene. With --out, also DIR/speed.csv.");
  bench->add_flag("--lean", s->lean_study,
                  "Instead of the slip benchmark: the lean-scene study (the rail scene as simulated, and with each part "
                  "it leaves out put back: time per step, constraint rows, contacts, memory); single-threaded, one run "
                  "per variant (rail flat and rail curved40 unless --scene). With --out, also DIR/lean.csv.")
      ->excludes(speed);
  bench->add_option("--scene", s->speed_scenes,
                    "With --speed or --lean: measure only this scene (repeatable; the speed study's scene names).");
  bench->add_option("--repeats", s->repeats, "With --lean: rounds over the variants, each keeping its fastest run (default 1).")
      ->check(CLI::Range(1, 100));
  s->train.Add(bench, false);

  return [s, train, eval, detect, bench, stop]() -> int {
    const std::vector<int> runs = s->runs.empty() ? std::vector<int>{} : ParseRunList(s->runs);
    if (*train) {
      const TrainOptions opts = s->train.Options();
      CheckWritableLocation(s->out);
      const std::vector<LabeledRun> data = LoadDatasetRuns(s->data, runs, s->train.score_onset_frame);
      std::unique_ptr<Detector> det;
      std::string kind = s->kind == "svm" ? "svm-" + s->kernel : s->kind;
      if (kind == "threshold") {
        det = ThresholdDetector::Train(data, opts);
      } else {
        const TrainingSet ts = BuildTrainingSet(data, opts);
        long slip = 0;
        for (int y : ts.y) slip += y;
        std::fprintf(stderr, "training set: %zu frames (%ld slip) from %zu runs\n", ts.y.size(), slip, data.size());
        if (kind == "logreg") {
          det = LogRegDetector::Train(ts, opts);
        } else {
          auto svm = SvmDetector::Train(ts, kind == "svm-rbf" ? SvmDetector::Kernel::kRbf : SvmDetector::Kernel::kLinear,
                                        opts);
          const auto& cv = svm->cv_report();
          std::fprintf(stderr, "grouped %d-fold CV: best C %g, gamma %g, F1 %.4f\n", opts.cv_folds, cv.best_c,
                       cv.best_gamma, cv.best_f1);
          det = std::move(svm);
        }
      }
      det->Save(s->out);
      std::fprintf(stderr, "wrote %s (%s)\n", s->out.c_str(), det->name().c_str());
      return 0;
    }
    if (*eval) {
      std::unique_ptr<Detector> det = WithResponse(LoadDetector(s->model), s->response);
      const Evaluation e = Evaluate(*det, LoadDatasetRuns(s->data, runs, s->score_onset_frame), s->train.n_slip);
      std::printf("%s", FormatEvaluation(e, s->per_run).c_str());
      return 0;
    }
    if (*detect) {
      CheckWritableLocation(s->out);
      std::unique_ptr<Detector> det;
      if (s->kind == "incipient") {
        if (!s->model.empty()) throw InputError("detect incipient takes --window/--speed-thr-px/--count-thr, not --model");
        IncipientParams p;
        p.window = s->window;
        p.speed_thr_px = s->speed_thr;
        p.count_thr = s->count_thr;
        det = std::make_unique<IncipientDetector>(p);
      } else {
        if (s->model.empty()) throw InputError("detect needs --model, or 'incipient' as the detector kind");
        det = LoadDetector(s->model);
      }
      const bool incipient = det->name() == "incipient";
      det = WithResponse(std::move(det), s->response);
      const std::vector<LabeledRun> data = LoadFrames(s->data, runs);
      size_t frames = 0;
      for (const auto& r : data) frames += r.frames.size();
      WriteFileAtomic(s->out, DecisionsCsv(*det, data, incipient, s->contact_measure));
      std::fprintf(stderr, "wrote %s: %zu frames of %zu run(s) through %s\n", s->out.c_str(), frames, data.size(),
                   det->name().c_str());
      return 0;
    }
    if (*bench && s->lean_study) {
      LeanOptions o;
      o.overrides = s->sets;
      o.seed = s->bench_seed;
      o.repeats = s->repeats;
      o.stop = stop;
      const bool write = bench->get_option("--out")->count() > 0;
      return RunLeanStudy(s->speed_scenes, o, write ? s->bench_out : std::string());
    }
    if (*bench && s->speed_study) {
      const bool write = bench->get_option("--out")->count() > 0;
      return RunSpeedStudy(s->speed_scenes, s->sets, write ? s->bench_out : std::string(), s->bench_seed);
    }
    if (*bench) {
      BenchOptions o;
      o.out_dir = s->bench_out;
      o.dataset = s->bench_dataset;
      o.runs = s->bench_runs;
      o.seed = s->bench_seed;
      o.jobs = s->jobs;
      o.train = s->train.Options();
      o.score_onset_frame = s->train.score_onset_frame;
      o.stop = stop;
      o.log = [](const std::string& line) { std::fprintf(stderr, "bench: %s\n", line.c_str()); };
      std::vector<std::string> sets;
      if (!std::isnan(s->speed)) sets.push_back(fmt::format("rail.retract_speed_mm_s={}", s->speed));
      sets.insert(sets.end(), s->sets.begin(), s->sets.end());
      const RailScenarioConfig cfg = LoadConfig<RailScenarioConfig>(s->config, sets);
      const BenchResult r = RunBench(cfg, o);
      std::printf("%s", FormatBenchTable(r).c_str());
      std::printf("wrote %s/bench.json and %s/bench.csv\n", o.out_dir.c_str(), o.out_dir.c_str());
      return 0;
    }
    return -1;
  };
}

}  // namespace tactip::cli
