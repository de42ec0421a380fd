// Response strategies (consecutive frames x agreeing sensors) and the contact measure.

#include "detectors/response.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace tactip {
namespace {

/// Reads a positive decimal integer at s[pos...]; advances pos. False if none.
bool ReadCount(const std::string& s, size_t& pos, int& out) {
  const char* begin = s.data() + pos;
  const char* end = s.data() + s.size();
  if (begin == end || !std::isdigit(static_cast<unsigned char>(*begin))) return false;
  const auto [p, ec] = std::from_chars(begin, end, out);
  if (ec != std::errc()) return false;
  pos += static_cast<size_t>(p - begin);
  return true;
}

/// Matches `word` case-insensitively at s[pos...]; advances pos. False otherwise.
bool ReadWord(const std::string& s, size_t& pos, const std::string& word) {
  if (s.size() - pos < word.size()) return false;
  for (size_t k = 0; k < word.size(); ++k) {
    if (std::tolower(static_cast<unsigned char>(s[pos + k])) != word[k]) return false;
  }
  pos += word.size();
  return true;
}

/// Why (NFr, NSen, total) is unusable, or "" if it is fine.
std::string CheckCounts(int n_frames, int n_sensors_required, int n_sensors_total) {
  if (n_frames < 1) return "NFr = " + std::to_string(n_frames) + ": must be >= 1";
  if (n_sensors_total < 1) return std::to_string(n_sensors_total) + " sensors: must be >= 1";
  if (n_sensors_required < 1 || n_sensors_required > n_sensors_total) {
    return "NSen = " + std::to_string(n_sensors_required) + ": must be in [1, " + std::to_string(n_sensors_total) +
           "] (the number of sensors)";
  }
  return "";
}

}  // namespace

ResponseStrategy::ResponseStrategy(int n_frames, int n_sensors_required, int n_sensors_total)
    : n_frames_(n_frames), n_sensors_required_(n_sensors_required), n_sensors_total_(n_sensors_total) {
  const std::string why = CheckCounts(n_frames, n_sensors_required, n_sensors_total);
  if (!why.empty()) throw InputError("response strategy: " + why);
  streak_.assign(n_sensors_total, 0);
}

ResponseStrategy ResponseStrategy::Parse(const std::string& s, int n_sensors_total) {
  size_t pos = 0;
  int n_frames = 0, n_sensors = 0;
  const bool ok = ReadCount(s, pos, n_frames) && ReadWord(s, pos, "fr") && ReadCount(s, pos, n_sensors) &&
                  ReadWord(s, pos, "sen") && pos == s.size();
  if (!ok) throw InputError("response strategy '" + s + "': expected <NFr>Fr<NSen>Sen, e.g. 2Fr1Sen");
  const std::string why = CheckCounts(n_frames, n_sensors, n_sensors_total);
  if (!why.empty()) throw InputError("response strategy '" + s + "': " + why);
  return ResponseStrategy(n_frames, n_sensors, n_sensors_total);
}

bool ResponseStrategy::Update(const std::vector<bool>& per_sensor_slip) {
  if (static_cast<int>(per_sensor_slip.size()) != n_sensors_total_) {
    throw InputError("response strategy " + ToString() + ": got " + std::to_string(per_sensor_slip.size()) +
                     " sensor decisions, expected " + std::to_string(n_sensors_total_));
  }
  // Extend or break each sensor's streak, then count the sensors whose streak is long enough.
  int agreeing = 0;
  for (int s = 0; s < n_sensors_total_; ++s) {
    streak_[s] = per_sensor_slip[s] ? streak_[s] + 1 : 0;
    if (streak_[s] >= n_frames_) ++agreeing;
  }
  return agreeing >= n_sensors_required_;
}

void ResponseStrategy::Reset() { std::fill(streak_.begin(), streak_.end(), 0); }

std::string ResponseStrategy::ToString() const {
  return std::to_string(n_frames_) + "Fr" + std::to_string(n_sensors_required_) + "Sen";
}

void ContactMeasure::Reset() { has_ref_ = false; }

double ContactMeasure::Update(const PinFrame& frame) {
  if (!has_ref_) {
    ref_ = frame;
    has_ref_ = true;
    return 0.0;
  }
  const int n = frame.size();
  if (n != ref_.size()) {
    throw InputError("frame at t = " + std::to_string(frame.time_s) + " s has " + std::to_string(n) +
                     " pins, the reference frame " + std::to_string(ref_.size()));
  }
  // Mean displacement from the reference over the pins detected in both frames.
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < n; ++i) {
    const bool ok = (frame.valid.empty() || frame.valid[i]) && (ref_.valid.empty() || ref_.valid[i]);
    if (!ok) continue;
    const double dx = static_cast<double>(frame.pos_px(i, 0)) - ref_.pos_px(i, 0);
    const double dy = static_cast<double>(frame.pos_px(i, 1)) - ref_.pos_px(i, 1);
    sum += std::sqrt(dx * dx + dy * dy);
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

ResponseDetector::ResponseDetector(std::unique_ptr<Detector> inner, ResponseStrategy strategy)
    : inner_(std::move(inner)), strategy_(strategy), one_(1, false) {
  if (strategy_.n_sensors_total() != 1) {
    throw InputError("response " + strategy_.ToString() + ": a single-sensor detector needs NSen = 1");
  }
}

std::string ResponseDetector::name() const { return inner_->name() + "+" + strategy_.ToString(); }

void ResponseDetector::Reset() {
  inner_->Reset();
  strategy_.Reset();
}

Decision ResponseDetector::Update(const PinFrame& frame) {
  // The inner decision goes through the strategy; everything else is passed on.
  Decision d = inner_->Update(frame);
  one_[0] = d.slip;
  d.slip = strategy_.Update(one_);
  return d;
}

}  // namespace tactip
