#pragma once
// The streaming detector interface and the data types shared by training and
// evaluation. Detectors see PinFrames only — exactly what TacTip hardware delivers.

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "detectors/pin_frame.h"
#include "sim/base/errors.h"

namespace tactip {

/// One per-frame decision.
struct Decision {
  bool slip = false;                 ///< slip declared in this frame
  double score = 0.0;                ///< detector-specific confidence (decision value, mean speed, ...)
  int n_slipping = 0;                ///< incipient detector: size of the slipping set
  std::vector<int> slipping_pins;    ///< incipient detector: pins judged to slip independently
};

/// A streaming slip detector: feed frames in order, one at a time; the same object runs
/// offline on recorded data and online in a closed loop.
class Detector {
 public:
  virtual ~Detector() = default;
  /// Short name used in tables and files ("threshold", "svm-rbf", ...).
  virtual std::string name() const = 0;
  /// Forgets all history (call between runs).
  virtual void Reset() = 0;
  /// Consumes the next frame and returns the decision for it. The first frame after
  /// Reset() has no velocity and is never a slip.
  virtual Decision Update(const PinFrame& frame) = 0;
  /// Writes the trained model to a text file (atomically); throws InputError if
  /// it cannot be written.
  virtual void Save(const std::string& path) const = 0;
};

/// Loads any model written by Detector::Save; throws InputError naming the file
/// on a missing, unreadable or corrupt model.
std::unique_ptr<Detector> LoadDetector(const std::string& path);

/// Which per-pin velocity features a classifier uses.
enum class FeatureSet {
  kDrDtheta,  ///< (dr_i, dtheta_i) for every pin: 2N values
  kDr,        ///< dr_i only: N values
  kDtheta,    ///< dtheta_i only: N values
};
/// "drdtheta", "dr", "dtheta".
std::string ToString(FeatureSet f);
/// Parses the names above; throws InputError otherwise.
FeatureSet ParseFeatureSet(const std::string& s);

/// Streaming pin-velocity features. Velocity of pin i = p_i(t) - p_i(t-1) in pixels;
/// dr_i = |v_i|, dtheta_i = atan2(v_y, v_x) minus the frame's circular mean angle over
/// the pins used (removes the slip direction; the circular mean keeps a slip towards
/// +-pi from splitting into two clusters), wrapped to (-pi, pi]. A pin not
/// detected in this or the previous frame has no velocity: it contributes dr = 0 and
/// dtheta = 0 and is left out of the dtheta mean.
class VelocityFeatures {
 public:
  explicit VelocityFeatures(FeatureSet set = FeatureSet::kDrDtheta) : set_(set) {}
  /// Forgets the previous frame.
  void Reset();
  /// Consumes a frame. Returns false for the first frame (no velocity yet); otherwise
  /// fills `out` with Dim(set, N) values. Throws InputError if N changes.
  bool Update(const PinFrame& frame, Eigen::VectorXf& out);
  /// Mean velocity vector over the pins with a velocity in the last Update (px/frame).
  const Eigen::Vector2f& mean_velocity() const { return mean_velocity_; }
  /// Feature dimension for N pins.
  static int Dim(FeatureSet set, int n_pins);
  FeatureSet set() const { return set_; }

 private:
  FeatureSet set_;
  bool has_prev_ = false;
  PinFrame prev_;
  Eigen::Vector2f mean_velocity_ = Eigen::Vector2f::Zero();
  Eigen::VectorXf dr_, dth_;           // per-pin scratch, reused every frame
  std::vector<unsigned char> seen_;    // per pin: velocity available this frame
};

/// One recorded run converted to frames, with its ground truth (for training and
/// evaluation). Frames before `first_frame` (pressing, lifting) are streamed through
/// detectors but neither trained on nor scored.
struct LabeledRun {
  int run = 0;                     ///< run index in its dataset
  std::vector<PinFrame> frames;    ///< all frames in order
  int first_frame = 0;             ///< first frame of the labelled window (retraction start)
  int onset_frame = -1;            ///< first frame of gross slip (-1: the run has none)
  /// First frame labelled slip for training and scoring (-1: onset_frame). Frames from
  /// onset_frame up to it are transition frames, neither trained on nor scored.
  int slip_start_frame = -1;
  double frame_rate_hz = 100.0;    ///< camera rate
};

/// How a frame takes part in training and scoring.
enum class FrameRole {
  kUnscored,  ///< before the labelled window, a transition frame, or past the slip frames
  kStatic,    ///< before the onset
  kSlip,      ///< one of the n_slip frames from the slip start
};
/// The role of frame k of `run` with n_slip labelled slip frames.
FrameRole RoleOf(const LabeledRun& run, int k, int n_slip);

/// How training frames are chosen and how hyperparameters are searched.
struct TrainOptions {
  FeatureSet features = FeatureSet::kDrDtheta;  ///< feature variant
  int n_slip = 4;                ///< frames after the onset labelled slip (1..15); later ones dropped
  double static_fraction = 0.4;  ///< fraction of static frames kept (seeded downsampling), (0, 1]
  std::uint64_t seed = 1;        ///< seed of the downsampling
  int cv_folds = 4;              ///< folds of the grouped cross-validation (runs never split)
  std::vector<double> c_grid = {0.1, 1.0, 10.0, 100.0};      ///< SVM / logistic C candidates
  std::vector<double> gamma_scale_grid = {0.0625, 0.25, 1.0};  ///< RBF gamma candidates x 1/dim
  /// Progress of the training (a fold of the cross-validation done, the final fit begun);
  /// called from any thread, one line at a time. Empty: silent.
  std::function<void(const std::string&)> progress;
};

/// Feature matrix with labels and run groups, one row per selected frame.
struct TrainingSet {
  Eigen::MatrixXf x;         ///< rows = frames, cols = feature dimension
  std::vector<int> y;        ///< 1 = slip, 0 = static
  std::vector<int> group;    ///< run index of each row (for grouped CV)
};

/// Streams every run's frames through VelocityFeatures(opts.features) and calls
/// `visit(run, features, feature_vector, slip)` for each selected training frame: static
/// frames from first_frame up to the onset, kept with probability static_fraction (one
/// seeded draw per static frame), and the n_slip slip frames. Throws InputError
/// for n_slip outside [1, 15] or static_fraction outside (0, 1].
void ForEachTrainingFrame(
    const std::vector<LabeledRun>& runs, const TrainOptions& opts,
    const std::function<void(const LabeledRun&, const VelocityFeatures&, const Eigen::VectorXf&, bool)>& visit);

/// Builds the training set: for every run, static frames from first_frame up to the
/// onset (downsampled to static_fraction with a seeded generator), the first n_slip
/// frames from the onset labelled slip, later frames dropped. Deterministic.
TrainingSet BuildTrainingSet(const std::vector<LabeledRun>& runs, const TrainOptions& opts);

}  // namespace tactip
