// The threshold gross-slip detector: training by an F1 sweep, streaming decisions and a
// one-parameter text model.

#include "detectors/threshold.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "detectors/model_text.h"
#include "detectors/text_io.h"
#include "sim/base/files.h"
#include "sim/base/number_text.h"

namespace tactip {
namespace {

constexpr const char* kThresholdModelHeader = "tactip-detector threshold 1";

/// F1 = 2 tp / (2 tp + fp + fn); 0 when undefined.
double F1Score(long tp, long fp, long fn) {
  const long den = 2 * tp + fp + fn;
  return den > 0 ? 2.0 * static_cast<double>(tp) / static_cast<double>(den) : 0.0;
}

}  // namespace

ThresholdDetector::ThresholdDetector(double threshold_px) : threshold_px_(threshold_px) {
  if (!std::isfinite(threshold_px) || threshold_px < 0.0) {
    throw InputError("threshold_px = " + RoundTripText(threshold_px) + ": must be finite and >= 0");
  }
}

void ThresholdDetector::Reset() { features_.Reset(); }

Decision ThresholdDetector::Update(const PinFrame& frame) {
  Decision d;
  if (!features_.Update(frame, scratch_)) return d;  // first frame: no velocity yet
  d.score = static_cast<double>(features_.mean_velocity().norm());
  d.slip = d.score >= threshold_px_;
  return d;
}

void ThresholdDetector::Save(const std::string& path) const {
  WriteFileAtomic(path, std::string(kThresholdModelHeader) + "\nthreshold_px " + RoundTripText(threshold_px_) + "\n");
}

std::unique_ptr<ThresholdDetector> ThresholdDetector::Load(const std::string& path) {
  double t = 0.0;
  ReadKeyValueModel(ReadText(path), path, kThresholdModelHeader,
                    {{"threshold_px", [&](const std::string& v) { return ParseWhole(v, t); }}});
  const std::string where = "model '" + path + "': ";
  try {
    return std::make_unique<ThresholdDetector>(t);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
}

std::unique_ptr<ThresholdDetector> ThresholdDetector::Train(const std::vector<LabeledRun>& runs,
                                                            const TrainOptions& opts) {
  // The frames BuildTrainingSet would select (same draws), as (|mean velocity|, label).
  std::vector<std::pair<double, int>> samples;
  long n_pos = 0;
  TrainOptions dr = opts;
  dr.features = FeatureSet::kDr;  // the cheapest variant; only the mean velocity is used
  ForEachTrainingFrame(runs, dr, [&](const LabeledRun&, const VelocityFeatures& feat, const Eigen::VectorXf&, bool slip) {
    samples.emplace_back(static_cast<double>(feat.mean_velocity().norm()), slip ? 1 : 0);
    n_pos += slip ? 1 : 0;
  });
  if (n_pos == 0) throw InputError("threshold training: the selected frames hold no slip frame");
  for (const auto& [v, label] : samples) {
    if (!std::isfinite(v)) throw InputError("threshold training: a frame has a non-finite pin velocity");
  }

  // Sweep T upward over the sorted distinct values. Candidate j puts T at the lowest
  // distinct value (everything slip) or midway between distinct values j-1 and j.
  std::sort(samples.begin(), samples.end());
  long tp = n_pos, fp = static_cast<long>(samples.size()) - n_pos, fn = 0;
  double best_t = samples.front().first, best_f1 = F1Score(tp, fp, fn);
  size_t i = 0;
  while (i < samples.size()) {
    // Move every sample equal to the current value below the threshold.
    const double value = samples[i].first;
    while (i < samples.size() && samples[i].first == value) {
      if (samples[i].second == 1) {
        --tp;
        ++fn;
      } else {
        --fp;
      }
      ++i;
    }
    if (i == samples.size()) break;  // "nothing is slip" never beats a slip frame caught
    const double t = 0.5 * (value + samples[i].first);
    const double f1 = F1Score(tp, fp, fn);
    if (f1 > best_f1) {  // strict: ties keep the smaller T
      best_f1 = f1;
      best_t = t;
    }
  }
  return std::make_unique<ThresholdDetector>(best_t);
}

}  // namespace tactip
