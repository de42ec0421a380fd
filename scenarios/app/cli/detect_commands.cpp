#include "scenarios/app/cli/detect_commands.h"

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
#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/lean_command.h"
#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "scenarios/studies/detector_bench/detector_bench.h"
#include "sensors/slip_data.h"
#include "scenarios/studies/speed/speed.h"
#include "sensors/dataset.h"
#include "sim/base/files.h"
#include "sim/base/progress.h"

namespace tactip::cli {

namespace {

// Parses "0.1,1,10" into numbers; throws InputError naming the option.
std::vector<double> ParseGrid(const std::string& opt, const std::string& text) {
  if (!text.empty() && text.back() == ',') {
    throw InputError(fmt::format("{} '{}': a value is missing after the last comma", opt, text));
  }
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
    c->add_option("--features", features, "Velocity features: drdtheta (default), dr or dtheta.")
        ->check(NonEmpty("drdtheta, dr or dtheta"));
    c->add_option("--n-slip", n_slip, "Frames after the ground-truth onset labelled slip (1-15, default 4).")
        ->check(CLI::Range(1, 15));
    c->add_option("--downsample", downsample, "Fraction of static frames kept for training (default 0.4).")
        ->check(NumberWithin(1e-6, 1.0));
    if (with_seed) AddSeedOption(c, seed, "Seed of the static-frame downsampling (default 1).");
    c->add_option("--folds", folds, "Folds of the cross-validation grouped by run (default 4).")
        ->check(CLI::Range(2, 50));
    c->add_option("--c-grid", c_grid, "SVM / logistic C candidates, e.g. 0.1,1,10,100.")
        ->check(NonEmpty("positive numbers separated by commas"));
    c->add_option("--gamma-grid", gamma_grid, "RBF gamma candidates in units of 1/dim, e.g. 0.25,1,4.")
        ->check(NonEmpty("positive numbers separated by commas"));
  }
  // Throws InputError when --folds was given and exceeds the runs a cross-validation can
  // group (runs are never split, so more folds than runs cannot be honoured).
  void CheckFolds(const CLI::App* c, size_t training_runs) const {
    if (c->get_option("--folds")->count() == 0 || static_cast<size_t>(folds) <= training_runs) return;
    const std::string fix = training_runs > 2    ? fmt::format("use --folds 2 to {}", training_runs)
                            : training_runs == 2 ? std::string("use --folds 2")
                                                 : std::string("cross-validation needs at least 2 training runs");
    throw InputError(fmt::format("--folds {}: more folds than the {} training run(s) (a fold holds whole runs); {}",
                                 folds, training_runs, fix));
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
  PrepareOutputFolder(out_dir, "speed.csv");
  ProgressF("bench --speed: one run per scene on one core, every step timed\n");
  const std::vector<SpeedRow> rows = MeasureSpeed(scenes, sets, seed);
  std::printf("%s", FormatSpeedTable(rows).c_str());
  if (!out_dir.empty()) {
    const std::string path = (std::filesystem::path(out_dir) / "speed.csv").string();
    WriteFileAtomic(path, SpeedCsv(rows));
    ProgressF("wrote %s\n", path.c_str());
  }
  return 0;
}

// Options of the detector subcommands (owned by the returned closure).
struct DetectArgs {
  std::string kind, kernel = "rbf", data, runs, out, model, sensor;
  std::string pins = "camera";  // --pins: camera or detected
  std::string labels = "exact";  // --labels: exact or marker
  std::string standard_set = "easy";  // bench --standard-set
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

// Registers --pins on `c` into `pins`.
void AddPinsOption(CLI::App* c, std::string& pins) {
  c->add_option("--pins", pins,
                "Pin positions of an HDF5 dataset: camera (pins/pos_px, the camera model; default) or detected "
                "(pins/detected_px, the blob pipeline on rendered images: generate --images).")
      ->check(CLI::IsMember({"camera", "detected"}));
}

// Registers --labels on `c` into `labels`.
void AddLabelsOption(CLI::App* c, std::string& labels) {
  c->add_option("--labels", labels,
                "Slip onsets to train and score with: exact (the simulator's gross-slip onset, events/gross_slip_onset_s; "
                "default) or marker (the hardware's way: a camera tracking a marker on the object, "
                "events/marker_onset_s, settings in the marker_camera section).")
      ->check(CLI::IsMember({"exact", "marker"}));
}

// The detector `kind` (threshold, logreg, svm-linear or svm-rbf) trained on `data`.
std::unique_ptr<Detector> TrainDetector(const std::string& kind, const std::vector<LabeledRun>& data,
                                        const TrainOptions& opts) {
  if (kind == "threshold") return ThresholdDetector::Train(data, opts);
  const TrainingSet ts = BuildTrainingSet(data, opts);
  long slip = 0;
  for (int y : ts.y) slip += y;
  ProgressF("training set: %zu frames (%ld slip) from %zu runs\n", ts.y.size(), slip, data.size());
  if (kind == "logreg") return LogRegDetector::Train(ts, opts);
  auto svm = SvmDetector::Train(ts, kind == "svm-rbf" ? SvmDetector::Kernel::kRbf : SvmDetector::Kernel::kLinear, opts);
  const auto& cv = svm->cv_report();
  ProgressF("grouped %d-fold CV: best C %g, gamma %g, F1 %.4f\n", opts.cv_folds, cv.best_c, cv.best_gamma,
               cv.best_f1);
  return svm;
}

// tactip train: the model from runs of a dataset, saved to --out.
int RunTrain(const DetectArgs& s, const CLI::App* train, const std::vector<int>& runs) {
  CheckOutputsAreNotInputs({{"--out", s.out}}, {{"--data", s.data}});
  TrainOptions opts = s.train.Options();
  opts.progress = [](const std::string& line) { Progress(line); };
  CheckWritableLocation(s.out);
  const std::vector<LabeledRun> data = LoadDatasetRuns(s.data, runs, s.train.score_onset_frame, s.sensor, ParsePinSource(s.pins),
                                                       ParseOnsetLabels(s.labels));
  NoteFlaggedRuns(s.data, runs);
  const std::string kind = s.kind == "svm" ? "svm-" + s.kernel : s.kind;
  if (kind != "threshold") s.train.CheckFolds(train, data.size());  // only the others cross-validate
  const std::unique_ptr<Detector> det = TrainDetector(kind, data, opts);
  det->Save(s.out);
  ProgressF("wrote %s (%s)\n", s.out.c_str(), det->name().c_str());
  return 0;
}

// tactip detect: one decision per frame of the input, written to --out as CSV.
int RunDetect(const DetectArgs& s, const std::vector<int>& runs) {
  CheckOutputsAreNotInputs({{"--out", s.out}}, {{"--data", s.data}, {"--model", s.model}});
  CheckWritableLocation(s.out);
  std::unique_ptr<Detector> det;
  if (s.kind == "incipient") {
    if (!s.model.empty()) throw InputError("detect incipient takes --window/--speed-thr-px/--count-thr, not --model");
    IncipientParams p;
    p.window = s.window;
    p.speed_thr_px = s.speed_thr;
    p.count_thr = s.count_thr;
    det = std::make_unique<IncipientDetector>(p);
  } else {
    if (s.model.empty()) throw InputError("detect needs --model, or 'incipient' as the detector kind");
    det = LoadDetector(s.model);
  }
  const bool incipient = det->name() == "incipient";
  det = WithResponse(std::move(det), s.response);
  const std::vector<LabeledRun> data = LoadFrames(s.data, runs, s.sensor, ParsePinSource(s.pins));
  NoteFlaggedRuns(s.data, runs);
  size_t frames = 0;
  for (const auto& r : data) frames += r.frames.size();
  WriteFileAtomic(s.out, DecisionsCsv(*det, data, incipient, s.contact_measure));
  ProgressF("wrote %s: %zu frames of %zu run(s) through %s\n", s.out.c_str(), frames, data.size(),
               det->name().c_str());
  return 0;
}

// tactip bench: the slip benchmark into its output folder. Inputs, folds and config are
// checked before the folder is created; a failed benchmark leaves no empty folder.
int RunSlipBench(const DetectArgs& s, const CLI::App* bench, const std::atomic<bool>* stop) {
  BenchOptions o;
  o.out_dir = s.bench_out;
  o.dataset = s.bench_dataset;
  o.standard_set = s.standard_set;
  o.labels = ParseOnsetLabels(s.labels);
  o.runs = s.bench_runs;
  o.seed = s.bench_seed;
  o.jobs = s.jobs;
  o.train = s.train.Options();
  o.score_onset_frame = s.train.score_onset_frame;
  o.sensor = s.sensor;
  o.stop = stop;
  o.log = [](const std::string& line) { ProgressF("bench: %s\n", line.c_str()); };
  CheckOutputsAreNotInputs(FilesInFolder("--out", o.out_dir, BenchOutputFiles(o)),
                           {{"--dataset", o.dataset}, {"--config", s.config}});
  const size_t runs = o.dataset.empty() ? static_cast<size_t>(o.runs) : DatasetReader(o.dataset).run_indices().size();
  if (!o.dataset.empty()) {
    CheckSensorOption(o.dataset, o.sensor);
    NoteFlaggedRuns(o.dataset);
  }
  s.train.CheckFolds(bench, runs / 2);  // the first half trains
  if (o.standard_set == "mixed" && !std::isnan(s.speed)) {
    throw InputError("--speed-mm-s: the mixed set draws every run's speed from 0.1-5 mm/s; use --standard-set easy");
  }
  std::vector<std::string> sets;
  if (!std::isnan(s.speed)) sets.push_back(fmt::format("rail.retract_speed_mm_s={}", s.speed));
  sets.insert(sets.end(), s.sets.begin(), s.sets.end());
  const RailScenarioConfig cfg = LoadConfig<RailScenarioConfig>(s.config, sets);
  NewFolderGuard folder(o.out_dir);
  const BenchResult r = RunBench(cfg, o);
  folder.Keep();
  std::printf("%s", FormatBenchTable(r).c_str());
  std::printf("wrote %s/bench.json and %s/bench.csv\n", o.out_dir.c_str(), o.out_dir.c_str());
  return 0;
}

// tactip bench --lean / --speed / the slip benchmark.
int RunBenchCommand(const DetectArgs& s, const CLI::App* bench, const std::atomic<bool>* stop) {
  const bool write = bench->get_option("--out")->count() > 0;
  if (s.lean_study) {
    LeanOptions o;
    o.overrides = s.sets;
    o.seed = s.bench_seed;
    o.repeats = s.repeats;
    o.stop = stop;
    NewFolderGuard folder(write ? s.bench_out : std::string());
    const int code = RunLeanStudy(s.speed_scenes, o, write ? s.bench_out : std::string());
    folder.Keep();
    return code;
  }
  if (s.speed_study) {
    NewFolderGuard folder(write ? s.bench_out : std::string());
    const int code = RunSpeedStudy(s.speed_scenes, s.sets, write ? s.bench_out : std::string(), s.bench_seed);
    folder.Keep();
    return code;
  }
  return RunSlipBench(s, bench, stop);
}

// Registers `tactip train`, `evaluate` and `detect` and their options.
void AddTrainEvaluateDetect(CLI::App& app, DetectArgs& s, CLI::App*& train, CLI::App*& eval, CLI::App*& detect) {
  train = app.add_subcommand("train", "Train a gross-slip detector on runs of a dataset and save the model.");
  train->add_option("kind", s.kind, "threshold, logreg, svm (kernel from --kernel), svm-linear or svm-rbf.")
      ->required()
      ->check(CLI::IsMember({"threshold", "logreg", "svm", "svm-linear", "svm-rbf"}));
  train->add_option("--data", s.data, "HDF5 dataset written by 'tactip generate'.")
      ->required()
      ->check(NonEmpty("an HDF5 dataset"));
  train->add_option("--runs", s.runs, "Runs to train on, e.g. 0-19 (default: all).")->check(NonEmpty("runs, e.g. 0-19"));
  train->add_option("--out", s.out, "Model file to write; not the --data file.")
      ->required()
      ->check(NonEmpty("a file name"));
  train->add_option("--kernel", s.kernel, "SVM kernel for 'svm': rbf (Gaussian, default) or linear.")
      ->check(CLI::IsMember({"rbf", "linear"}));
  AddSensorOption(train, s.sensor);
  AddPinsOption(train, s.pins);
  AddLabelsOption(train, s.labels);
  s.train.Add(train);

  eval = app.add_subcommand("evaluate", "Score a trained model on runs of a dataset (metrics table).");
  eval->add_option("--model", s.model, "Model written by 'tactip train'.")->required()->check(NonEmpty("a model file"));
  eval->add_option("--data", s.data, "HDF5 dataset with ground truth.")->required()->check(NonEmpty("an HDF5 dataset"));
  eval->add_option("--runs", s.runs, "Runs to score, e.g. 20-39 (default: all).")->check(NonEmpty("runs, e.g. 20-39"));
  eval->add_option("--n-slip", s.train.n_slip, "Frames after the onset scored as slip (default 4).")
      ->check(CLI::Range(1, 15));
  eval->add_flag("--per-run", s.per_run, "Also print one line per run.");
  eval->add_option("--response", s.response,
                   "Act only on a response strategy, e.g. 2Fr1Sen (two consecutive slip frames).")
      ->check(NonEmpty("a response strategy, e.g. 2Fr1Sen"));
  eval->add_flag("--score-onset-frame", s.score_onset_frame,
                 "Score the frame whose velocity spans the onset as slip (default: not scored).");
  AddSensorOption(eval, s.sensor);
  AddPinsOption(eval, s.pins);
  AddLabelsOption(eval, s.labels);

  detect = app.add_subcommand(
      "detect", "Run a detector over recorded frames (HDF5 dataset or real-TacTip CSV) and write its decisions.");
  detect->add_option("kind", s.kind, "'incipient' for the bulk-subtraction incipient detector; omit with --model.")
      ->check(CLI::IsMember({"incipient"}));
  detect->add_option("--model", s.model, "Model written by 'tactip train'.")->check(NonEmpty("a model file"));
  detect->add_option("--data", s.data,
                     "Input frames: a .h5 dataset or a .csv recording with columns frame,time_s,pin,x_px,y_px.")
      ->required()
      ->check(NonEmpty("a .h5 dataset or a .csv recording"));
  detect->add_option("--runs", s.runs, "Runs of an HDF5 dataset (default: all).")->check(NonEmpty("runs, e.g. 0-19"));
  AddSensorOption(detect, s.sensor);
  AddPinsOption(detect, s.pins);
  detect->add_option("--out", s.out, "Output CSV: run,frame,time_s,slip (and n_slipping for incipient).")
      ->required()
      ->check(NonEmpty("a file name"));
  detect->add_option("--window", s.window, "Incipient: moving-average window W in frames (default 5).");
  detect->add_option("--speed-thr-px", s.speed_thr, "Incipient: speed threshold s_thr in px/frame (default 0.2).")
      ->check(NumberAbove(0.0));
  detect->add_option("--count-thr", s.count_thr, "Incipient: pins needed to declare incipient slip (default 4).");
  detect->add_option("--response", s.response,
                     "Act only on a response strategy, e.g. 2Fr1Sen (two consecutive slip frames).")
      ->check(NonEmpty("a response strategy, e.g. 2Fr1Sen"));
  detect->add_flag("--contact-measure", s.contact_measure,
                   "Add a column d_px: mean pin displacement from the run's first (no-contact) frame.");
}

// Registers `tactip bench` and its options.
CLI::App* AddBench(CLI::App& app, DetectArgs& s) {
  auto* bench = app.add_subcommand(
      "bench", "The slip benchmark: standard rail dataset, every detector trained and evaluated, hardware beside.");
  bench->add_option("--out", s.bench_out, "Output folder for bench.json, bench.csv and models (default bench-results).")
      ->check(NonEmpty("a folder"));
  CLI::Option* dataset =
      bench->add_option("--dataset", s.bench_dataset, "Use this dataset instead of generating the standard one.")
          ->check(NonEmpty("an HDF5 dataset"));
  AddSensorOption(bench, s.sensor)->needs(dataset);
  bench->add_option("--runs", s.bench_runs, "Runs of the standard dataset (default 40; half train, half test).")
      ->check(CLI::Range(4, 10000));
  bench->add_option("--standard-set", s.standard_set,
                    "The standard set generated: easy (the flat stimulus at 0.1 mm/s; default) or mixed (flat, "
                    "curved80, curved40 and curved20, a quarter of the runs each, every run's retraction speed drawn "
                    "from 0.1-5 mm/s; half of each stimulus's runs train).")
      ->check(CLI::IsMember({"easy", "mixed"}))
      ->excludes(dataset);
  AddLabelsOption(bench, s.labels);
  bench->add_option("--speed-mm-s", s.speed,
                    "Shortcut for --set rail.retract_speed_mm_s=V for the generated dataset (default 0.1).")
      ->check(FiniteNumber());
  AddSeedOption(bench, s.bench_seed, "Dataset and training seed (default 2026).");
  bench->add_option("--jobs", s.jobs, "Generation threads (default: all cores).")->check(CLI::Range(0, 256));
  bench->add_option("--config", s.config, "YAML rail config for the generated dataset.")
      ->check(NonEmpty("a YAML file"))
      ->check(CLI::ExistingFile);
  bench->add_option("--set", s.sets, "Override a rail config key (repeatable).")
      ->type_name("KEY=VALUE")
      ->check(NonEmpty("KEY=VALUE"));
  auto* speed = bench->add_flag("--speed", s.speed_study,
                  "Instead of the slip benchmark: the speed study (real-time factor of each scene, the cost split of "
                  "a step, the scenario's overhead over its physics and bare mj_step on the same model); "
                  "single-threaded, one run per scene. With --out, also DIR/speed.csv.");
  bench->add_flag("--lean", s.lean_study,
                  "Instead of the slip benchmark: the lean-scene study (the rail scene as simulated, and with each part "
                  "it leaves out put back: time per step, constraint rows, contacts, memory); single-threaded, one run "
                  "per variant (rail flat and rail curved40 unless --scene). With --out, also DIR/lean.csv.")
      ->excludes(speed);
  bench->add_option("--scene", s.speed_scenes,
                    "With --speed or --lean: measure only this scene (repeatable; the speed study's scene names).")
      ->check(NonEmpty("a scene name"));
  bench->add_option("--repeats", s.repeats, "With --lean: rounds over the variants, each keeping its fastest run (default 1).")
      ->check(CLI::Range(1, 100));
  s.train.Add(bench, false);
  return bench;
}

}  // namespace

std::function<int()> AddDetectorCommands(CLI::App& app, const std::atomic<bool>* stop) {
  auto s = std::make_shared<DetectArgs>();
  CLI::App *train = nullptr, *eval = nullptr, *detect = nullptr;
  AddTrainEvaluateDetect(app, *s, train, eval, detect);
  CLI::App* bench = AddBench(app, *s);
  return [s, train, eval, detect, bench, stop]() -> int {
    const std::vector<int> runs = s->runs.empty() ? std::vector<int>{} : ParseRunList(s->runs);
    if (*train) return RunTrain(*s, train, runs);
    if (*eval) {
      std::unique_ptr<Detector> det = WithResponse(LoadDetector(s->model), s->response);
      const std::vector<LabeledRun> data =
          LoadDatasetRuns(s->data, runs, s->score_onset_frame, s->sensor, ParsePinSource(s->pins),
                          ParseOnsetLabels(s->labels));
      NoteFlaggedRuns(s->data, runs);
      const Evaluation e = Evaluate(*det, data, s->train.n_slip);
      std::printf("%s", FormatEvaluation(e, s->per_run).c_str());
      return 0;
    }
    if (*detect) return RunDetect(*s, runs);
    if (*bench) return RunBenchCommand(*s, bench, stop);
    return -1;
  };
}

}  // namespace tactip::cli
