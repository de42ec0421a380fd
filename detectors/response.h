#pragma once
// Response strategies that turn per-sensor slip decisions into one action ("2Fr1Sen":
// two consecutive slip frames on at least one sensor), and the contact measure d(t).

#include <memory>
#include <string>
#include <vector>

#include "detectors/detector.h"

namespace tactip {

/// "NFr consecutive slip frames per sensor, NSen sensors agreeing": fires in a frame in
/// which at least NSen sensors have a streak of >= NFr consecutive slip frames ending in
/// that frame. Does not latch: a broken streak must be rebuilt.
class ResponseStrategy {
 public:
  /// Throws InputError unless n_frames >= 1 and 1 <= n_sensors_required <= n_sensors_total.
  ResponseStrategy(int n_frames, int n_sensors_required, int n_sensors_total);

  /// Parses "<NFr>Fr<NSen>Sen" (e.g. "2Fr1Sen"; "fr"/"sen" in any case); throws
  /// InputError naming the string if malformed or NSen > n_sensors_total.
  static ResponseStrategy Parse(const std::string& s, int n_sensors_total);

  /// Consumes one frame of per-sensor decisions (size n_sensors_total, else
  /// InputError); true when the strategy fires in this frame.
  bool Update(const std::vector<bool>& per_sensor_slip);
  /// Clears every streak.
  void Reset();

  /// Canonical name, e.g. "2Fr1Sen".
  std::string ToString() const;
  /// NFr: consecutive slip frames needed per sensor.
  int n_frames() const { return n_frames_; }
  /// NSen: sensors that must agree.
  int n_sensors_required() const { return n_sensors_required_; }
  /// Number of sensors fed to Update.
  int n_sensors_total() const { return n_sensors_total_; }

 private:
  int n_frames_;
  int n_sensors_required_;
  int n_sensors_total_;
  std::vector<int> streak_;  // consecutive slip frames per sensor, ending at the last frame
};

/// Contact measure d(t) = mean_i |p_i(t) - p_i(0)| in pixels, relative to the first
/// frame after Reset (the no-contact frame), over the pins detected in both frames.
class ContactMeasure {
 public:
  /// Forgets the reference frame.
  void Reset();
  /// Consumes a frame and returns d(t): 0 for the reference frame itself and when no pin
  /// is detected in both frames. Throws InputError if the pin count changes.
  double Update(const PinFrame& frame);
  /// True once a reference frame has been seen.
  bool has_reference() const { return has_ref_; }

 private:
  bool has_ref_ = false;
  PinFrame ref_;
};

/// A single-sensor detector whose decisions pass through a response strategy (e.g.
/// "2Fr1Sen": act on two consecutive slip frames). Wraps, does not own, the inner model's
/// training; Save writes the inner model only.
class ResponseDetector : public Detector {
 public:
  /// Takes ownership of `inner`; `strategy` must be for one sensor.
  ResponseDetector(std::unique_ptr<Detector> inner, ResponseStrategy strategy);
  /// "<inner name>+<strategy>", e.g. "svm-rbf+2Fr1Sen".
  std::string name() const override;
  void Reset() override;
  Decision Update(const PinFrame& frame) override;
  void Save(const std::string& path) const override { inner_->Save(path); }

 private:
  std::unique_ptr<Detector> inner_;
  ResponseStrategy strategy_;
  std::vector<bool> one_;  // the single sensor's decision
};

}  // namespace tactip
