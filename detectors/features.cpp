// Pin-velocity features and training-set construction.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "detectors/detector.h"
#include "sim/base/random.h"

namespace tactip {

std::string ToString(FeatureSet f) {
  switch (f) {
    case FeatureSet::kDrDtheta: return "drdtheta";
    case FeatureSet::kDr: return "dr";
    case FeatureSet::kDtheta: return "dtheta";
  }
  return "drdtheta";
}

FeatureSet ParseFeatureSet(const std::string& s) {
  if (s == "drdtheta") return FeatureSet::kDrDtheta;
  if (s == "dr") return FeatureSet::kDr;
  if (s == "dtheta") return FeatureSet::kDtheta;
  throw InputError("features '" + s + "': must be one of drdtheta, dr, dtheta");
}

int VelocityFeatures::Dim(FeatureSet set, int n_pins) { return set == FeatureSet::kDrDtheta ? 2 * n_pins : n_pins; }

void VelocityFeatures::Reset() {
  has_prev_ = false;
  mean_velocity_.setZero();
}

bool VelocityFeatures::Update(const PinFrame& frame, Eigen::VectorXf& out) {
  const int n = frame.size();
  if (has_prev_ && prev_.size() != n) {
    throw InputError("frame at t = " + std::to_string(frame.time_s) + " s has " + std::to_string(n) +
                     " pins, the previous frame " + std::to_string(prev_.size()));
  }
  if (!has_prev_) {
    prev_ = frame;
    has_prev_ = true;
    mean_velocity_.setZero();
    return false;
  }
  // Velocities of the pins seen in both frames (scratch buffers sized once).
  dr_.setZero(n);
  dth_.setZero(n);
  seen_.assign(n, 0);
  Eigen::Vector2f sum = Eigen::Vector2f::Zero();
  double sin_sum = 0.0, cos_sum = 0.0;
  int n_seen = 0;
  for (int i = 0; i < n; ++i) {
    const bool ok = (frame.valid.empty() || frame.valid[i]) && (prev_.valid.empty() || prev_.valid[i]);
    if (!ok) continue;
    const float vx = frame.pos_px(i, 0) - prev_.pos_px(i, 0);
    const float vy = frame.pos_px(i, 1) - prev_.pos_px(i, 1);
    dr_[i] = std::sqrt(vx * vx + vy * vy);
    dth_[i] = std::atan2(vy, vx);
    sin_sum += std::sin(dth_[i]);
    cos_sum += std::cos(dth_[i]);
    sum += Eigen::Vector2f(vx, vy);
    seen_[i] = 1;
    ++n_seen;
  }
  mean_velocity_ = n_seen > 0 ? Eigen::Vector2f(sum / static_cast<float>(n_seen)) : Eigen::Vector2f::Zero();
  // Subtract the circular mean angle of the seen pins and wrap to (-pi, pi].
  const float th_mean = n_seen > 0 ? static_cast<float>(std::atan2(sin_sum, cos_sum)) : 0.0f;
  const float pi = std::numbers::pi_v<float>;
  for (int i = 0; i < n; ++i) {
    if (!seen_[i]) continue;
    float a = dth_[i] - th_mean;
    while (a <= -pi) a += 2.0f * pi;
    while (a > pi) a -= 2.0f * pi;
    dth_[i] = a;
  }
  // Assemble the requested variant: (dr_0, dtheta_0, dr_1, dtheta_1, ...) or one of them.
  out.resize(Dim(set_, n));
  for (int i = 0; i < n; ++i) {
    switch (set_) {
      case FeatureSet::kDrDtheta:
        out[2 * i] = dr_[i];
        out[2 * i + 1] = dth_[i];
        break;
      case FeatureSet::kDr: out[i] = dr_[i]; break;
      case FeatureSet::kDtheta: out[i] = dth_[i]; break;
    }
  }
  // Keep the previous frame in place (no reallocation when sizes match).
  prev_.time_s = frame.time_s;
  prev_.pos_px = frame.pos_px;
  prev_.valid.assign(frame.valid.begin(), frame.valid.end());
  return true;
}

FrameRole RoleOf(const LabeledRun& run, int k, int n_slip) {
  if (k < run.first_frame) return FrameRole::kUnscored;
  if (run.onset_frame < 0 || k < run.onset_frame) return FrameRole::kStatic;
  const int start = run.slip_start_frame < 0 ? run.onset_frame : run.slip_start_frame;
  return k >= start && k < start + n_slip ? FrameRole::kSlip : FrameRole::kUnscored;
}

void ForEachTrainingFrame(
    const std::vector<LabeledRun>& runs, const TrainOptions& opts,
    const std::function<void(const LabeledRun&, const VelocityFeatures&, const Eigen::VectorXf&, bool)>& visit) {
  if (opts.n_slip < 1 || opts.n_slip > 15) {
    throw InputError("n_slip = " + std::to_string(opts.n_slip) + ": must be in [1, 15]");
  }
  if (!(opts.static_fraction > 0.0 && opts.static_fraction <= 1.0)) {
    throw InputError("static fraction = " + std::to_string(opts.static_fraction) + ": must be in (0, 1]");
  }
  Rng gen(opts.seed);
  for (const LabeledRun& run : runs) {
    // Stream every frame (features need the previous one), keep the labelled window.
    VelocityFeatures feat(opts.features);
    Eigen::VectorXf f;
    for (int k = 0; k < static_cast<int>(run.frames.size()); ++k) {
      const FrameRole role = RoleOf(run, k, opts.n_slip);
      if (!feat.Update(run.frames[k], f) || role == FrameRole::kUnscored) continue;
      const bool slip = role == FrameRole::kSlip;
      // Seeded downsampling of static frames: draw for every static frame.
      if (!slip) {
        if (gen.Uniform() >= opts.static_fraction) continue;
      }
      visit(run, feat, f, slip);
    }
  }
}

TrainingSet BuildTrainingSet(const std::vector<LabeledRun>& runs, const TrainOptions& opts) {
  std::vector<Eigen::VectorXf> rows;
  TrainingSet ts;
  ForEachTrainingFrame(runs, opts,
                       [&](const LabeledRun& run, const VelocityFeatures&, const Eigen::VectorXf& f, bool slip) {
                         rows.push_back(f);
                         ts.y.push_back(slip ? 1 : 0);
                         ts.group.push_back(run.run);
                       });
  const int dim = rows.empty() ? 0 : static_cast<int>(rows.front().size());
  ts.x.resize(static_cast<Eigen::Index>(rows.size()), dim);
  for (size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].size() != dim) throw InputError("runs have different pin counts");
    ts.x.row(static_cast<Eigen::Index>(r)) = rows[r].transpose();
  }
  return ts;
}

}  // namespace tactip
