// Per-frame cost of the detectors on 127-pin frames (Google Benchmark). The models are
// trained on synthetic runs (noise 0.28 px, co-linear slip) so the benchmark needs no
// dataset; `tactip bench` reports the same timing on simulated data.

#include <benchmark/benchmark.h>

#include <random>

#include "detectors/detector.h"
#include "detectors/incipient.h"
#include "detectors/logreg.h"
#include "detectors/svm.h"
#include "detectors/threshold.h"

namespace {

constexpr int kPins = 127;

// Runs of 300 frames: noise only, then a co-linear slip of 3 px/frame from frame 250.
std::vector<tactip::LabeledRun> SyntheticRuns(int n_runs, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::normal_distribution<float> noise(0.0f, 0.28f);
  std::vector<tactip::LabeledRun> runs;
  for (int r = 0; r < n_runs; ++r) {
    tactip::LabeledRun run;
    run.run = r;
    run.onset_frame = 250;
    Eigen::Matrix<float, Eigen::Dynamic, 2> base(kPins, 2);
    for (int i = 0; i < kPins; ++i) base.row(i) << 320.0f + 15.0f * (i % 13), 240.0f + 15.0f * (i / 13);
    for (int k = 0; k < 300; ++k) {
      if (k >= 250) base.col(1).array() += 3.0f;
      tactip::PinFrame f;
      f.time_s = 0.01 * k;
      f.pos_px = base;
      for (int i = 0; i < kPins; ++i) f.pos_px.row(i) += Eigen::RowVector2f(noise(gen), noise(gen));
      f.valid.assign(kPins, 1);
      run.frames.push_back(std::move(f));
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

// Streams the frames of one run through Update, round and round.
void Stream(benchmark::State& state, tactip::Detector& det) {
  const auto runs = SyntheticRuns(1, 99);
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(det.Update(runs[0].frames[k]));
    if (++k == runs[0].frames.size()) {
      k = 0;
      det.Reset();
    }
  }
  state.SetItemsProcessed(state.iterations());
}

tactip::TrainOptions Options() {
  tactip::TrainOptions o;
  o.c_grid = {10.0};
  o.gamma_scale_grid = {0.25};
  o.cv_folds = 2;
  return o;
}

void BM_SvmRbfUpdate127Pins(benchmark::State& state) {
  const auto runs = SyntheticRuns(8, 1);
  auto det = tactip::SvmDetector::Train(tactip::BuildTrainingSet(runs, Options()), tactip::SvmDetector::Kernel::kRbf,
                                        Options());
  state.counters["support_vectors"] = det->n_support_vectors();
  Stream(state, *det);
}
BENCHMARK(BM_SvmRbfUpdate127Pins)->Unit(benchmark::kMicrosecond);

void BM_LogRegUpdate127Pins(benchmark::State& state) {
  const auto runs = SyntheticRuns(8, 1);
  auto det = tactip::LogRegDetector::Train(tactip::BuildTrainingSet(runs, Options()), Options());
  Stream(state, *det);
}
BENCHMARK(BM_LogRegUpdate127Pins)->Unit(benchmark::kMicrosecond);

void BM_ThresholdUpdate127Pins(benchmark::State& state) {
  tactip::ThresholdDetector det(0.5);
  Stream(state, det);
}
BENCHMARK(BM_ThresholdUpdate127Pins)->Unit(benchmark::kMicrosecond);

void BM_IncipientUpdate127Pins(benchmark::State& state) {
  tactip::IncipientDetector det;
  Stream(state, det);
}
BENCHMARK(BM_IncipientUpdate127Pins)->Unit(benchmark::kMicrosecond);

}  // namespace
