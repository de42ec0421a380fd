// Incipient-slip detection by bulk subtraction, with ring buffers so the streaming path
// does not allocate once the first frame has sized them.

#include "detectors/incipient.h"

#include <algorithm>
#include <cmath>

#include "detectors/model_text.h"
#include "detectors/text_io.h"
#include "sim/base/files.h"
#include "sim/base/number_text.h"

namespace tactip {
namespace {

constexpr const char* kIncipientModelHeader = "tactip-detector incipient 1";

}  // namespace

IncipientDetector::IncipientDetector(const IncipientParams& params) : params_(params) {
  if (params.window < 1 || params.window > 1000) {
    throw InputError("window = " + std::to_string(params.window) + ": must be in [1, 1000]");
  }
  if (!(params.speed_thr_px > 0.0) || !std::isfinite(params.speed_thr_px)) {
    throw InputError("speed_thr_px = " + RoundTripText(params.speed_thr_px) + ": must be finite and > 0");
  }
  if (params.count_thr < 1 || params.count_thr > 1000000) {
    throw InputError("count_thr = " + std::to_string(params.count_thr) + ": must be in [1, 1000000]");
  }
}

void IncipientDetector::Reset() {
  // Keep the buffers (their sizes are reused if the next run has the same pin count).
  has_prev_ = false;
  frames_in_ring_ = 0;
  ring_head_ = 0;
  std::fill(in_set_.begin(), in_set_.end(), 0);
  slipping_.clear();
}

Decision IncipientDetector::Update(const PinFrame& frame) {
  CheckFrame(frame);
  Decision d;
  if (!has_prev_) {
    // First frame of a run: no velocity yet.
    StartRun(frame);
    d.n_slipping = static_cast<int>(slipping_.size());
    return d;
  }
  PushVelocities(frame);
  SmoothSpeeds();
  const double s = BulkSpeed();
  // Pins are judged once the window holds W velocity frames.
  if (frames_in_ring_ == params_.window) Judge(s);
  Remember(frame);
  d.score = s;
  d.n_slipping = static_cast<int>(slipping_.size());
  d.slip = d.n_slipping >= params_.count_thr;
  d.slipping_pins = slipping_;
  return d;
}

void IncipientDetector::CheckFrame(const PinFrame& frame) const {
  const int n = frame.size();
  if (!frame.valid.empty() && static_cast<int>(frame.valid.size()) != n) {
    throw InputError("frame at t = " + std::to_string(frame.time_s) + " s has " + std::to_string(n) +
                     " pins but " + std::to_string(frame.valid.size()) + " valid flags");
  }
  if (has_prev_ && n != n_pins_) {
    throw InputError("frame at t = " + std::to_string(frame.time_s) + " s has " + std::to_string(n) +
                     " pins, the previous frame " + std::to_string(n_pins_));
  }
}

void IncipientDetector::StartRun(const PinFrame& frame) {
  // Size the buffers (kept if the pin count and window are unchanged), then remember the
  // positions.
  const int n = frame.size();
  if (n != n_pins_ || ring_x_.cols() != params_.window) {
    n_pins_ = n;
    ring_x_.resize(n, params_.window);
    ring_y_.resize(n, params_.window);
    smoothed_.resize(n);
    moved_.assign(n, 0);
    in_set_.assign(n, 0);
    slipping_.reserve(n);
  }
  prev_valid_.resize(n);
  Remember(frame);
  has_prev_ = true;
}

void IncipientDetector::PushVelocities(const PinFrame& frame) {
  // This frame's velocity into the ring (0 for pins missed in either frame).
  for (int i = 0; i < n_pins_; ++i) {
    const bool ok = prev_valid_[i] && (frame.valid.empty() || frame.valid[i]);
    moved_[i] = ok ? 1 : 0;
    ring_x_(i, ring_head_) = ok ? static_cast<double>(frame.pos_px(i, 0)) - prev_pos_(i, 0) : 0.0;
    ring_y_(i, ring_head_) = ok ? static_cast<double>(frame.pos_px(i, 1)) - prev_pos_(i, 1) : 0.0;
  }
  ring_head_ = (ring_head_ + 1) % params_.window;
  if (frames_in_ring_ < params_.window) ++frames_in_ring_;
}

void IncipientDetector::SmoothSpeeds() {
  // Moving average of the velocity over the filled columns (order does not matter), then
  // its magnitude.
  for (int i = 0; i < n_pins_; ++i) {
    double ax = 0.0, ay = 0.0;
    for (int c = 0; c < frames_in_ring_; ++c) {
      ax += ring_x_(i, c);
      ay += ring_y_(i, c);
    }
    smoothed_[i] = std::sqrt(ax * ax + ay * ay) / frames_in_ring_;
  }
}

double IncipientDetector::BulkSpeed() const {
  // s(t): the mean smoothed speed of the still-static pins with a velocity this frame.
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < n_pins_; ++i) {
    if (moved_[i] && !in_set_[i]) {
      sum += smoothed_[i];
      ++count;
    }
  }
  return count > 0 ? sum / count : 0.0;
}

void IncipientDetector::Judge(double bulk_speed) {
  // A pin is in the set while its smoothed speed exceeds the bulk speed of the pins that
  // were static in the previous frame by more than s_thr; pins missed this frame keep
  // their membership.
  slipping_.clear();
  for (int i = 0; i < n_pins_; ++i) {
    if (moved_[i]) in_set_[i] = smoothed_[i] - bulk_speed > params_.speed_thr_px ? 1 : 0;
    if (in_set_[i]) slipping_.push_back(i);
  }
}

void IncipientDetector::Remember(const PinFrame& frame) {
  // The positions and detection flags for the next frame's velocity (same sizes after
  // the first frame: no reallocation).
  prev_pos_ = frame.pos_px;
  if (frame.valid.empty()) {
    std::fill(prev_valid_.begin(), prev_valid_.end(), 1);
  } else {
    std::copy(frame.valid.begin(), frame.valid.end(), prev_valid_.begin());
  }
}

void IncipientDetector::Save(const std::string& path) const {
  std::string text = std::string(kIncipientModelHeader) + "\n";
  text += "window " + std::to_string(params_.window) + "\n";
  text += "speed_thr_px " + RoundTripText(params_.speed_thr_px) + "\n";
  text += "count_thr " + std::to_string(params_.count_thr) + "\n";
  WriteFileAtomic(path, text);
}

std::unique_ptr<IncipientDetector> IncipientDetector::Load(const std::string& path) {
  IncipientParams p;
  ReadKeyValueModel(ReadText(path), path, kIncipientModelHeader,
                    {{"window", [&](const std::string& v) { return ParseWhole(v, p.window); }},
                     {"speed_thr_px", [&](const std::string& v) { return ParseWhole(v, p.speed_thr_px); }},
                     {"count_thr", [&](const std::string& v) { return ParseWhole(v, p.count_thr); }}});
  const std::string where = "model '" + path + "': ";
  try {
    return std::make_unique<IncipientDetector>(p);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
}

}  // namespace tactip
