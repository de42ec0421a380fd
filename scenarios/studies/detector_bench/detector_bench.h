#pragma once
// The slip benchmark: a standard rail dataset, every detector trained on one half of
// the runs and evaluated on the other, with the hardware figures beside.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "detectors/detector.h"
#include "detectors/metrics.h"
#include "scenarios/rail/rail.h"
#include "sensors/slip_data.h"

namespace tactip {

/// What `tactip bench` runs.
struct BenchOptions {
  std::string out_dir = "bench-results";  ///< where bench.json, bench.csv and models go
  std::string dataset;      ///< existing dataset to use; empty = generate the standard one
  /// The standard set generated: easy (the flat stimulus at one speed, 0.1 mm/s) or mixed
  /// (every rail stimulus, a quarter of the runs each, each run's speed drawn from 0.1-5 mm/s).
  std::string standard_set = "easy";
  OnsetLabels labels = OnsetLabels::kExact;  ///< onsets to train and score with
  std::string sensor;       ///< sensor of `dataset` whose pins to read; empty = its first
  int runs = 40;            ///< runs of the standard dataset (first half train, second half test)
  std::uint64_t seed = 2026;  ///< dataset and training seed
  int jobs = 0;             ///< generation threads (0 = all cores)
  TrainOptions train;       ///< training-set construction and CV grids
  bool score_onset_frame = false;  ///< label the frame spanning the onset as slip (else skipped)
  int incipient_window = 5;          ///< incipient detector W (hardware value)
  double incipient_speed_thr_px = 0.2;  ///< incipient detector s_thr (hardware value)
  int incipient_count_thr = 4;       ///< incipient detector I_thr (hardware value)
  std::function<void(const std::string&)> log;  ///< progress lines
  const std::atomic<bool>* stop = nullptr;       ///< cooperative interruption
};

/// Figures measured on TacTip hardware (mission.md), shown beside the simulated ones.
struct HardwareReference {
  std::string f1;        ///< F1 on hardware, with the sensor it was measured on
  std::string accuracy;  ///< frames correct on hardware
  std::string time;      ///< classification time per frame on hardware
};

/// One row of the benchmark table.
struct BenchRow {
  Evaluation eval;
  HardwareReference hardware;
  std::string model_path;  ///< saved model (empty for untrained detectors)
};

/// The benchmark's results.
struct BenchResult {
  std::string dataset_path;                ///< the dataset, or the mixed set's files joined by ", "
  std::vector<std::string> dataset_files;  ///< every file of the set
  std::string set_name;                    ///< easy, mixed or given (--dataset)
  std::string labels;                      ///< exact or marker
  std::vector<int> train_runs, test_runs;
  std::uint64_t seed = 0;
  double speed_mm_s = 0.0;
  long train_rows = 0, train_slip_rows = 0;
  std::vector<BenchRow> rows;
};

/// Runs the benchmark and writes DIR/bench.json, DIR/bench.csv and the models.
BenchResult RunBench(const RailScenarioConfig& cfg, const BenchOptions& opts);

/// The stimuli of the mixed set, in order.
const std::vector<std::string>& MixedSetStimuli();

/// The names of the files RunBench writes into opts.out_dir: bench.json, bench.csv, one
/// model per trained detector and, when it generates the dataset, bench-rail.h5 (easy) or
/// bench-mixed-STIMULUS.h5 (mixed).
std::vector<std::string> BenchOutputFiles(const BenchOptions& opts);

/// The table printed by `tactip bench` and `tactip evaluate`.
std::string FormatBenchTable(const BenchResult& r);
/// One-detector metrics table (for `tactip evaluate`).
std::string FormatEvaluation(const Evaluation& e, bool per_run);
/// The JSON document written to bench.json.
std::string BenchJson(const BenchResult& r);
/// The CSV written to bench.csv (one row per detector).
std::string BenchCsv(const BenchResult& r);

}  // namespace tactip
