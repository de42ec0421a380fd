#pragma once
// The incipient-slip detector by bulk subtraction (hardware method): pins that move
// faster than the bulk of the still-static pins join a growing slipping set.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "detectors/detector.h"

namespace tactip {

/// Parameters of the bulk-subtraction detector (hardware values by default).
struct IncipientParams {
  int window = 5;             ///< W: moving-average length in frames, >= 1
  double speed_thr_px = 0.2;  ///< s_thr: excess over the bulk speed to join the set, px/frame, > 0
  int count_thr = 4;          ///< I_thr: slipping-set size that declares incipient slip, >= 1
};

/// Bulk subtraction. Each frame: the velocity v_i = p_i(t) - p_i(t-1) (0 for a pin missed
/// in either frame) is smoothed by a moving average over the last W frames (fewer at the
/// start) and D_i = |smoothed v_i| — averaging the vectors, not the speeds, is what makes
/// the hardware's noise figures hold (0.5 px/frame unsmoothed, 0.1 px/frame with W = 5);
/// s(t) = mean smoothed D over the pins with a velocity this frame that were not in the
/// slipping set after the previous frame ("still judged static"); the set is then
/// re-judged: it holds every pin whose smoothed D_i - s(t) > speed_thr_px (a pin missed
/// this frame keeps its membership). Re-judging, rather than letting the set only grow,
/// keeps single noise excursions from accumulating: with i.i.d. noise of 0.28 px the
/// smoothed speed exceeds the bulk by 0.2 px in ~1e-3 of pin-frames, which a growing set
/// would turn into an alarm within a second on a still 127-pin sensor. Pins are judged
/// only once the window holds W velocity frames (from frame W after Reset): raw start-up
/// speeds are as noisy as unsmoothed ones. slip = set size >= count_thr, score = s(t),
/// n_slipping = set size, slipping_pins = the set in ascending order. A pin missed in
/// this or the previous frame is neither averaged into s(t) nor judged in that frame.
/// After the first frames the per-frame path allocates nothing except the copy of the
/// slipping set into the returned Decision.
class IncipientDetector : public Detector {
 public:
  /// Throws InputError naming the bad parameter ("window = 0: must be >= 1").
  explicit IncipientDetector(const IncipientParams& params = {});

  /// Reads a model written by Save; throws InputError("model 'PATH': ...") if corrupt.
  static std::unique_ptr<IncipientDetector> Load(const std::string& path);

  /// "incipient".
  std::string name() const override { return "incipient"; }
  /// Forgets all history and empties the slipping set.
  void Reset() override;
  /// Decision for the next frame; throws InputError if the pin count changes.
  Decision Update(const PinFrame& frame) override;
  /// Writes "tactip-detector incipient 1" and the three parameters atomically.
  void Save(const std::string& path) const override;

  /// The parameters in use.
  const IncipientParams& params() const { return params_; }
  /// Current slipping set, ascending pin indices.
  const std::vector<int>& slipping_pins() const { return slipping_; }

 private:
  // The steps of Update, in order.
  void CheckFrame(const PinFrame& frame) const;  // throws InputError on a pin-count change
  void StartRun(const PinFrame& frame);          // first frame of a run: size, remember
  void PushVelocities(const PinFrame& frame);    // velocities into the ring, moved_ flags
  void SmoothSpeeds();                           // smoothed_ from the ring
  double BulkSpeed() const;                      // s(t)
  void Judge(double bulk_speed);                 // re-judge the slipping set
  void Remember(const PinFrame& frame);          // positions and flags for the next frame

  IncipientParams params_;
  int n_pins_ = 0;                         // pin count of the current run (0 before the first frame)
  bool has_prev_ = false;                  // a previous frame exists
  int frames_in_ring_ = 0;                 // number of filled ring columns, <= window
  int ring_head_ = 0;                      // column the next D is written to
  Eigen::MatrixXf prev_pos_;               // N x 2 previous positions
  std::vector<unsigned char> prev_valid_;  // N previous detection flags
  Eigen::MatrixXd ring_x_, ring_y_;        // N x W past velocity components
  Eigen::VectorXd smoothed_;               // N smoothed speeds D
  std::vector<unsigned char> moved_;       // N: pin has a velocity in this frame
  std::vector<unsigned char> in_set_;      // N: pin is in the slipping set
  std::vector<int> slipping_;              // the set, ascending
};

}  // namespace tactip
