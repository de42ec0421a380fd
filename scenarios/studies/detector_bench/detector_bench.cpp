#include "scenarios/studies/detector_bench/detector_bench.h"

#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "sim/base/number_text.h"
#include "detectors/incipient.h"
#include "detectors/logreg.h"
#include "detectors/svm.h"
#include "detectors/threshold.h"
#include "sensors/slip_data.h"
#include "sim/base/files.h"

namespace tactip {

namespace {

// Hardware results from mission.md. The 127-pin TacTip reports frames correct; the
// mini TacTip (Model O fingertip, single finger on the rail) reports F1.
HardwareReference Reference(const std::string& name) {
  static const std::map<std::string, HardwareReference> table = {
      {"threshold", {"0.753 (mini)", "", ""}},
      {"logreg", {"0.957 (mini)", "", ""}},
      {"svm-linear", {"", "95.07 % (127-pin)", ""}},
      {"svm-linear/dr", {"", "94.66 % (127-pin)", ""}},
      {"svm-linear/dtheta", {"", "70.58 % (127-pin)", ""}},
      {"svm-rbf", {"0.972 (mini)", "99.11 % (127-pin)", "3000 us"}},
      {"svm-rbf/dr", {"", "98.95 % (127-pin)", ""}},
      {"svm-rbf/dtheta", {"", "97.21 % (127-pin)", ""}},
      {"incipient", {"", "", "17/20 caught (v2)"}},
  };
  auto it = table.find(name);
  return it == table.end() ? HardwareReference{} : it->second;
}

void Log(const BenchOptions& opts, const std::string& s) {
  if (opts.log) opts.log(s);
}

void CheckStop(const BenchOptions& opts) {
  if (opts.stop && opts.stop->load()) throw Interrupted();
}

// Generates `runs` runs of `cfg` with `seed` into `path`.
void GenerateSet(const RailScenarioConfig& cfg, const BenchOptions& opts, int runs, std::uint64_t seed,
                 const std::string& path) {
  GenerateOptions g;
  g.runs = runs;
  g.seed = seed;
  g.jobs = opts.jobs;
  g.out_path = path;
  g.stop = opts.stop;
  g.progress = [&](int done, int total, int, const RailRunSummary&) {
    if (done % 10 == 0 || done == total) Log(opts, fmt::format("dataset: {}/{} runs", done, total));
  };
  const std::string speed =
      cfg.rail.retract_speed_max_mm_s > cfg.rail.retract_speed_mm_s
          ? fmt::format("{}-{}", cfg.rail.retract_speed_mm_s, cfg.rail.retract_speed_max_mm_s)
          : fmt::format("{}", cfg.rail.retract_speed_mm_s);
  Log(opts, fmt::format("generating {} rail runs on {} at {} mm/s (seed {}) into {}", runs, cfg.rail.stimulus, speed,
                        seed, path));
  GenerateRailDataset(cfg, g);
}

// The mixed set's mm/s: every run's retraction speed drawn from this range.
constexpr double kMixedMinSpeed = 0.1, kMixedMaxSpeed = 5.0;

// The standard dataset(s): generated with a fixed seed unless one is given. Sets r's files
// and retraction speed (NaN for a given dataset or the mixed set's drawn speeds).
void ProvideDataset(const RailScenarioConfig& cfg, const BenchOptions& opts, BenchResult& r) {
  r.speed_mm_s = std::nan("");
  if (!opts.dataset.empty()) {
    r.set_name = "given";
    r.dataset_files = {opts.dataset};
  } else if (opts.standard_set == "mixed") {
    r.set_name = "mixed";
    const auto& stimuli = MixedSetStimuli();
    for (size_t k = 0; k < stimuli.size(); ++k) {
      RailScenarioConfig c = cfg;
      c.rail.stimulus = stimuli[k];
      c.rail.retract_speed_mm_s = kMixedMinSpeed;
      c.rail.retract_speed_max_mm_s = kMixedMaxSpeed;
      c.ValidateRules();
      const std::string path = (std::filesystem::path(opts.out_dir) / ("bench-mixed-" + stimuli[k] + ".h5")).string();
      GenerateSet(c, opts, opts.runs / static_cast<int>(stimuli.size()), opts.seed + k, path);
      r.dataset_files.push_back(path);
    }
  } else {
    r.set_name = "easy";
    r.dataset_files = {(std::filesystem::path(opts.out_dir) / "bench-rail.h5").string()};
    GenerateSet(cfg, opts, opts.runs, opts.seed, r.dataset_files[0]);
    r.speed_mm_s = cfg.rail.retract_speed_mm_s;
  }
  for (const std::string& f : r.dataset_files) r.dataset_path += (r.dataset_path.empty() ? "" : ", ") + f;
}

// The runs of every file of the set, split into halves per file: the first trains, the
// second tests. Runs of the k-th file are numbered k * 100000 + their index.
void LoadHalves(const BenchOptions& opts, const BenchResult& r, std::vector<LabeledRun>& train,
                std::vector<LabeledRun>& test) {
  constexpr int kFileStride = 100000;
  for (size_t k = 0; k < r.dataset_files.size(); ++k) {
    std::vector<LabeledRun> all = LoadDatasetRuns(r.dataset_files[k], {}, opts.score_onset_frame, opts.sensor,
                                                  PinSource::kCamera, opts.labels);
    if (all.size() < 2) throw InputError(fmt::format("dataset '{}' has fewer than 2 runs", r.dataset_files[k]));
    const size_t half = all.size() / 2;
    for (size_t i = 0; i < all.size(); ++i) {
      all[i].run += static_cast<int>(k) * kFileStride;
      (i < half ? train : test).push_back(std::move(all[i]));
    }
  }
}

// Saves a trained detector's model, evaluates it on the held-out runs and appends its row.
void Score(Detector& det, const std::string& label, bool trained, const std::vector<LabeledRun>& test, int n_slip,
           const BenchOptions& opts, BenchResult& r) {
  CheckStop(opts);
  BenchRow row;
  if (trained) {
    std::string file = label;
    for (char& ch : file) ch = ch == '/' ? '-' : ch;
    row.model_path = (std::filesystem::path(opts.out_dir) / (file + ".model")).string();
    det.Save(row.model_path);
  }
  row.eval = Evaluate(det, test, n_slip);
  row.eval.detector = label;
  row.hardware = Reference(label);
  Log(opts, fmt::format("{}: F1 {:.3f}", label, row.eval.confusion.F1()));
  r.rows.push_back(std::move(row));
}

// The SVMs (linear, then Gaussian) on the configured features, then on the other feature
// variants, labelled "name/features".
void ScoreSvms(const std::vector<LabeledRun>& train, const std::vector<LabeledRun>& test, const TrainingSet& ts,
               const TrainOptions& topt, const BenchOptions& opts, BenchResult& r) {
  std::vector<FeatureSet> variants = {topt.features};
  for (FeatureSet f : {FeatureSet::kDrDtheta, FeatureSet::kDr, FeatureSet::kDtheta}) {
    if (f != topt.features) variants.push_back(f);
  }
  for (auto kernel : {SvmDetector::Kernel::kLinear, SvmDetector::Kernel::kRbf}) {
    const std::string base = kernel == SvmDetector::Kernel::kRbf ? "svm-rbf" : "svm-linear";
    for (FeatureSet f : variants) {
      TrainOptions vopt = topt;
      vopt.features = f;
      const std::string label = f == topt.features ? base : base + "/" + ToString(f);
      CheckStop(opts);
      Log(opts, fmt::format("training {} (grouped CV over C{})", label,
                            kernel == SvmDetector::Kernel::kRbf ? " and gamma" : ""));
      const TrainingSet vts = f == topt.features ? TrainingSet{} : BuildTrainingSet(train, vopt);
      Score(*SvmDetector::Train(f == topt.features ? ts : vts, kernel, vopt), label, true, test, topt.n_slip, opts, r);
    }
  }
}

}  // namespace

BenchResult RunBench(const RailScenarioConfig& cfg, const BenchOptions& opts) {
  if (opts.runs < 4) {
    throw InputError(fmt::format("--runs = {}: the benchmark needs at least 4 (cross-validation needs 2 training runs)",
                                 opts.runs));
  }
  if (opts.standard_set != "easy" && opts.standard_set != "mixed") {
    throw InputError("--standard-set '" + opts.standard_set + "': must be easy or mixed");
  }
  if (opts.dataset.empty() && opts.standard_set == "mixed" && opts.runs < 4 * static_cast<int>(MixedSetStimuli().size())) {
    throw InputError(fmt::format("--runs = {}: the mixed set needs at least {} (4 per stimulus)", opts.runs,
                                 4 * MixedSetStimuli().size()));
  }
  CreateOutputFolder(opts.out_dir);

  BenchResult r;
  r.seed = opts.seed;
  r.labels = opts.labels == OnsetLabels::kMarker ? "marker" : "exact";
  ProvideDataset(cfg, opts, r);
  // Disjoint halves of every file: the first trains, the second tests.
  std::vector<LabeledRun> train, test;
  LoadHalves(opts, r, train, test);
  for (const auto& x : train) r.train_runs.push_back(x.run);
  for (const auto& x : test) r.test_runs.push_back(x.run);

  TrainOptions topt = opts.train;
  topt.seed = opts.seed;
  topt.progress = [&opts](const std::string& line) { Log(opts, "  " + line); };
  const TrainingSet ts = BuildTrainingSet(train, topt);
  r.train_rows = static_cast<long>(ts.y.size());
  for (int y : ts.y) r.train_slip_rows += y;
  Log(opts, fmt::format("training set: {} frames ({} slip, {} labels) from {} runs", r.train_rows, r.train_slip_rows,
                        r.labels, r.train_runs.size()));
  if (r.train_slip_rows == 0) {
    throw InputError(fmt::format("dataset '{}': no training run has a gross-slip onset after the retraction starts "
                                 "(objects slipping during the lift are not scored)", r.dataset_path));
  }
  // Train, save and evaluate every detector on the held-out runs.
  CheckStop(opts);
  Log(opts, "training threshold");
  Score(*ThresholdDetector::Train(train, topt), "threshold", true, test, topt.n_slip, opts, r);
  CheckStop(opts);
  Log(opts, "training logreg (grouped CV over C)");
  Score(*LogRegDetector::Train(ts, topt), "logreg", true, test, topt.n_slip, opts, r);
  ScoreSvms(train, test, ts, topt, opts, r);
  IncipientParams ip;
  ip.window = opts.incipient_window;
  ip.speed_thr_px = opts.incipient_speed_thr_px;
  ip.count_thr = opts.incipient_count_thr;
  IncipientDetector inc(ip);
  Score(inc, "incipient", false, test, topt.n_slip, opts, r);

  WriteFileAtomic((std::filesystem::path(opts.out_dir) / "bench.json").string(), BenchJson(r));
  WriteFileAtomic((std::filesystem::path(opts.out_dir) / "bench.csv").string(), BenchCsv(r));
  return r;
}

const std::vector<std::string>& MixedSetStimuli() {
  static const std::vector<std::string> stimuli = {"flat", "curved80", "curved40", "curved20"};
  return stimuli;
}

std::vector<std::string> BenchOutputFiles(const BenchOptions& opts) {
  std::vector<std::string> files = {"bench.json", "bench.csv", "threshold.model", "logreg.model"};
  if (opts.dataset.empty() && opts.standard_set == "mixed") {
    for (const std::string& s : MixedSetStimuli()) files.push_back("bench-mixed-" + s + ".h5");
  } else if (opts.dataset.empty()) {
    files.push_back("bench-rail.h5");
  }
  for (const std::string base : {"svm-linear", "svm-rbf"}) {
    files.push_back(base + ".model");
    for (FeatureSet f : {FeatureSet::kDrDtheta, FeatureSet::kDr, FeatureSet::kDtheta}) {
      if (f != opts.train.features) files.push_back(base + "-" + ToString(f) + ".model");
    }
  }
  return files;
}

std::string FormatBenchTable(const BenchResult& r) {
  std::string out = fmt::format("set {} | labels {} | dataset {}\ntrain: {} runs ({} frames, {} slip) | test: {} runs\n",
                                r.set_name, r.labels, r.dataset_path, r.train_runs.size(), r.train_rows,
                                r.train_slip_rows, r.test_runs.size());
  out += fmt::format("{:<17} {:>6} {:>6} {:>6} {:>7} {:>7} {:>7} {:>8} {:>9} {:>9} | {:>13} {:>17} {:>17}\n",
                     "detector", "F1", "prec", "recall", "acc %", "delay", "delay", "FP/min", "us/frame",
                     "us p99", "hw F1", "hw frames correct", "hw other");
  out += fmt::format("{:<17} {:>6} {:>6} {:>6} {:>7} {:>7} {:>7} {:>8} {:>9} {:>9} | {:>13} {:>17} {:>17}\n", "",
                     "", "", "", "", "frames", "ms", "static", "mean", "", "", "", "");
  for (const auto& row : r.rows) {
    const Evaluation& e = row.eval;
    out += fmt::format("{:<17} {:>6.3f} {:>6.3f} {:>6.3f} {:>7.2f} {:>7} {:>7} {:>8} {:>9.1f} {:>9.1f} | {:>13} {:>17} {:>17}\n",
                       e.detector, e.confusion.F1(), e.confusion.Precision(), e.confusion.Recall(),
                       100.0 * e.confusion.Accuracy(), NumberCell(e.delay_frames_mean, "{:.1f}"),
                       NumberCell(e.delay_ms_mean, "{:.0f}"), NumberCell(e.fp_per_min, "{:.2f}"), e.us_per_frame_mean,
                       e.us_per_frame_p99, row.hardware.f1, row.hardware.accuracy, row.hardware.time);
  }
  return out;
}

std::string FormatEvaluation(const Evaluation& e, bool per_run) {
  std::string out;
  if (per_run) {
    out += fmt::format("{:>5} {:>6} {:>6} {:>6} {:>6} {:>7} {:>8} {:>8}\n", "run", "TP", "FP", "TN", "FN", "onset",
                       "detect", "delay");
    for (const auto& x : e.runs) {
      out += fmt::format("{:>5} {:>6} {:>6} {:>6} {:>6} {:>7} {:>8} {:>8}\n", x.run, x.confusion.tp, x.confusion.fp,
                         x.confusion.tn, x.confusion.fn, x.onset_frame, x.detection_frame,
                         NumberCell(x.delay_frames, "{:.0f}"));
    }
  }
  const Confusion& c = e.confusion;
  out += fmt::format("detector {}: F1 {:.4f}, precision {:.4f}, recall {:.4f}, accuracy {:.2f} %\n", e.detector, c.F1(),
                     c.Precision(), c.Recall(), 100.0 * c.Accuracy());
  out += fmt::format("confusion (frames): TP {} FP {} TN {} FN {}\n", c.tp, c.fp, c.tn, c.fn);
  out += fmt::format("delay after onset: {} frames ({} ms), detected in {:.0f} % of runs; false positives {} per "
                     "minute of static data; {:.1f} us/frame mean, {:.1f} us p99\n",
                     NumberCell(e.delay_frames_mean, "{:.2f}"), NumberCell(e.delay_ms_mean, "{:.1f}"), 100.0 * e.detected_fraction,
                     NumberCell(e.fp_per_min, "{:.3f}"), e.us_per_frame_mean, e.us_per_frame_p99);
  return out;
}

std::string BenchJson(const BenchResult& r) {
  nlohmann::json j;
  j["dataset"] = {{"path", r.dataset_path},
                  {"files", r.dataset_files},
                  {"set", r.set_name},
                  {"labels", r.labels},
                  {"seed", r.seed},
                  {"retract_speed_mm_s", std::isnan(r.speed_mm_s) ? nlohmann::json() : nlohmann::json(r.speed_mm_s)},
                  {"train_runs", r.train_runs},
                  {"test_runs", r.test_runs},
                  {"train_frames", r.train_rows},
                  {"train_slip_frames", r.train_slip_rows}};
  auto num = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  j["detectors"] = nlohmann::json::array();
  for (const auto& row : r.rows) {
    const Evaluation& e = row.eval;
    j["detectors"].push_back({{"name", e.detector},
                              {"f1", e.confusion.F1()},
                              {"precision", e.confusion.Precision()},
                              {"recall", e.confusion.Recall()},
                              {"accuracy", e.confusion.Accuracy()},
                              {"delay_frames", num(e.delay_frames_mean)},
                              {"delay_ms", num(e.delay_ms_mean)},
                              {"fp_per_min", num(e.fp_per_min)},
                              {"us_per_frame_mean", e.us_per_frame_mean},
                              {"us_per_frame_p99", e.us_per_frame_p99},
                              {"detected_fraction", e.detected_fraction},
                              {"confusion", {{"tp", e.confusion.tp}, {"fp", e.confusion.fp},
                                             {"tn", e.confusion.tn}, {"fn", e.confusion.fn}}},
                              {"model", row.model_path},
                              {"hardware", {{"f1", row.hardware.f1}, {"frames_correct", row.hardware.accuracy},
                                            {"other", row.hardware.time}}}});
  }
  return j.dump(2) + "\n";
}

std::string BenchCsv(const BenchResult& r) {
  std::string out =
      "name,f1,precision,recall,accuracy,delay_frames,delay_ms,fp_per_min,us_per_frame_mean,us_per_frame_p99,tp,fp,tn,fn\n";
  auto num = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{}", v); };
  for (const auto& row : r.rows) {
    const Evaluation& e = row.eval;
    const Confusion& c = e.confusion;
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", e.detector, c.F1(), c.Precision(), c.Recall(),
                       c.Accuracy(), num(e.delay_frames_mean), num(e.delay_ms_mean), num(e.fp_per_min),
                       e.us_per_frame_mean, e.us_per_frame_p99, c.tp, c.fp, c.tn, c.fn);
  }
  return out;
}

}  // namespace tactip
