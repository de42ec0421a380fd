// Offline evaluation of streaming detectors.

#include "detectors/metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "sim/base/nan.h"

namespace tactip {
namespace {

/// a / b, or 0 when b == 0.
double Ratio(long a, long b) { return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : 0.0; }

}  // namespace

double Confusion::Precision() const { return Ratio(tp, tp + fp); }
double Confusion::Recall() const { return Ratio(tp, tp + fn); }
double Confusion::F1() const { return Ratio(2 * tp, 2 * tp + fp + fn); }
double Confusion::Accuracy() const { return Ratio(tp + tn, Total()); }

Confusion& Confusion::operator+=(const Confusion& o) {
  tp += o.tp;
  fp += o.fp;
  tn += o.tn;
  fn += o.fn;
  return *this;
}

namespace {

// Counts frame k's decision into the run's confusion (the labelled window only).
void ScoreFrame(const LabeledRun& run, int k, int n_slip, bool slip, RunEvaluation& re) {
  const FrameRole role = RoleOf(run, k, n_slip);
  if (role == FrameRole::kStatic) {
    ++re.static_frames;
    if (slip) {
      ++re.confusion.fp;
      ++re.false_positive_frames;
    } else {
      ++re.confusion.tn;
    }
  } else if (role == FrameRole::kSlip) {
    if (slip) {
      ++re.confusion.tp;
    } else {
      ++re.confusion.fn;
    }
  }
}

// Streams one run through `det` (after a Reset), timing each Update into `us`.
RunEvaluation EvaluateRun(Detector& det, const LabeledRun& run, int n_slip, std::vector<double>& us) {
  if (!(run.frame_rate_hz > 0.0) || !std::isfinite(run.frame_rate_hz)) {
    throw InputError("run " + std::to_string(run.run) + ": frame rate " + std::to_string(run.frame_rate_hz) +
                     " Hz: must be > 0");
  }
  RunEvaluation re;
  re.run = run.run;
  re.onset_frame = run.onset_frame;
  const bool has_onset = run.onset_frame >= 0;
  det.Reset();
  for (int k = 0; k < static_cast<int>(run.frames.size()); ++k) {
    // Time the decision alone.
    const auto t0 = std::chrono::steady_clock::now();
    const Decision d = det.Update(run.frames[k]);
    const auto t1 = std::chrono::steady_clock::now();
    us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    // First slip decision at or after the onset.
    if (has_onset && k >= run.onset_frame && re.detection_frame < 0 && d.slip) re.detection_frame = k;
    ScoreFrame(run, k, n_slip, d.slip, re);
  }
  if (re.detection_frame >= 0) re.delay_frames = re.detection_frame - run.onset_frame;
  return re;
}

// Mean and nearest-rank 99th percentile (the ceil(0.99 n)-th smallest) of the Update times.
void TimeFigures(std::vector<double>& us, Evaluation& ev) {
  if (us.empty()) return;
  double sum = 0.0;
  for (double u : us) sum += u;
  ev.us_per_frame_mean = sum / static_cast<double>(us.size());
  const size_t rank = static_cast<size_t>(std::ceil(0.99 * static_cast<double>(us.size())));
  const size_t idx = std::max<size_t>(rank, 1) - 1;
  std::nth_element(us.begin(), us.begin() + static_cast<std::ptrdiff_t>(idx), us.end());
  ev.us_per_frame_p99 = us[idx];
}

}  // namespace

Evaluation Evaluate(Detector& det, const std::vector<LabeledRun>& runs, int n_slip) {
  if (n_slip < 1) throw InputError("n_slip = " + std::to_string(n_slip) + ": must be >= 1");
  Evaluation ev;
  ev.detector = det.name();
  size_t total_frames = 0;
  for (const LabeledRun& run : runs) total_frames += run.frames.size();
  std::vector<double> us;
  us.reserve(total_frames);

  double delay_frames_sum = 0.0, delay_ms_sum = 0.0, static_minutes = 0.0;
  int n_delays = 0, n_with_onset = 0;
  for (const LabeledRun& run : runs) {
    RunEvaluation re = EvaluateRun(det, run, n_slip, us);
    if (run.onset_frame >= 0) ++n_with_onset;
    if (re.detection_frame >= 0) {
      delay_frames_sum += re.delay_frames;
      delay_ms_sum += re.delay_frames * 1000.0 / run.frame_rate_hz;
      ++n_delays;
    }
    static_minutes += re.static_frames / run.frame_rate_hz / 60.0;
    ev.confusion += re.confusion;
    ev.runs.push_back(std::move(re));
  }

  // Aggregates.
  ev.frames_scored = static_cast<int>(ev.confusion.Total());
  ev.delay_frames_mean = n_delays > 0 ? delay_frames_sum / n_delays : kNaN;
  ev.delay_ms_mean = n_delays > 0 ? delay_ms_sum / n_delays : kNaN;
  ev.fp_per_min = static_minutes > 0.0 ? static_cast<double>(ev.confusion.fp) / static_minutes : kNaN;
  ev.detected_fraction = n_with_onset > 0 ? static_cast<double>(n_delays) / n_with_onset : kNaN;
  TimeFigures(us, ev);
  return ev;
}

std::string FormatConfusion(const Confusion& c) {
  char buf[256];
  std::snprintf(buf, sizeof(buf), "TP %ld FP %ld TN %ld FN %ld | precision %.4f recall %.4f F1 %.4f accuracy %.4f",
                c.tp, c.fp, c.tn, c.fn, c.Precision(), c.Recall(), c.F1(), c.Accuracy());
  return buf;
}

}  // namespace tactip
