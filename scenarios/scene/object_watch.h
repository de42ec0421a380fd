#pragma once
// What a run follows of its object O: the labels that say O slips (on each sensor, on all of
// them together), the gross- and incipient-slip onsets and the pins that slid before, the
// Coulomb prediction of the onset, O's loss and its creep on the first sensor's centre pin.

#include <cstdint>
#include <limits>
#include <vector>

#include "scenarios/scene/scene.h"
#include "scenarios/scene/scene_controller.h"
#include "scenarios/scene/sensor_channel.h"
#include "sensors/labels.h"
#include "sim/simulation.h"

namespace tactip {

/// What TrackOnset found at a step.
struct OnsetStep {
  bool all_slide_began = false;  ///< every contacting pin began to slide at this step (the step may refine)
  long long gross_from_frame = -1;  ///< the onset was confirmed: frames from this one on are gross slip (-1: not now)
};

/// The events of one object in one run, step by step and frame by frame.
class ObjectWatch {
 public:
  /// `object`'s events along `timeline`, with `labels`' slip speed and fall threshold, held
  /// by `n_sensors` sensors, under gravity `gravity_m_s2`.
  ObjectWatch(const SceneObject& object, const ProtocolTimeline& timeline, const LabelConfig& labels,
              double gravity_m_s2, size_t n_sensors);

  /// After every sensor read its contacts at a step at time t: what the contacts hold along
  /// the vertical, and the labels (every contacting pin of every sensor slides; the object
  /// moves relative to the first sensor's carrier).
  void ReadContacts(double t, const std::vector<SensorChannel>& channels, const Simulation& sim, int carrier_up_dof);
  /// Gross onset, once the load is on (`seek`); `frame` is the next frame to be recorded.
  OnsetStep TrackOnset(double t, bool seek, long long frame);
  /// The Coulomb prediction of the onset, from the release on.
  void TrackPrediction(double t);
  /// Each pin's first slipping step from the release to the onset (at step resolution).
  void TrackFirstSlips(double t, std::vector<SensorChannel>& channels) const;
  /// At a frame at step time t: partial slip and the pins in contact at the release.
  void TrackIncipient(double t, std::vector<SensorChannel>& channels);
  /// At a frame (step time t, frame time tf): the object's loss and creep; `rel_z` is its
  /// height relative to the first sensor, `creep_z` relative to that sensor's centre pin's
  /// contact point, `obj_z` its own. Returns the time the run may end at (infinity: not yet).
  double TrackEvents(double t, double tf, double rel_z, double creep_z);

  /// The gross-slip label of this step, and the pins of all sensors in contact and slipping.
  std::uint8_t gross() const { return gross_; }
  int n_contact() const { return n_contact_; }
  int n_slip() const { return n_slip_; }
  /// The onset (NaN until found), the prediction's state.
  double onset_s() const { return onset_s_; }
  double predicted_onset_s() const { return predicted_s_; }
  /// True when the release has begun and the pins in contact then are known.
  bool release_seen() const { return release_seen_; }
  /// True when the object was left behind during the load (lost before the release).
  bool left_behind() const { return left_behind_; }

  /// The run's events so far, into `s` (its object fields; the rest is the run's).
  template <class Summary>
  void Fill(Summary& s, const std::vector<SensorChannel>& channels) const;
  /// Each pin's first slip from the release up to the onset (later ones are NaN), of sensor k.
  std::vector<double> FirstSlips(const SensorChannel& channel) const;

 private:
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double PreSlipFraction(const std::vector<SensorChannel>& channels) const;

  const SceneObject& object_;
  const ProtocolTimeline timeline_;
  const double slip_speed_m_s_, fall_threshold_m_;
  const double weight_N_;

  // Per step: what the contacts hold, the labels, the all-slide run.
  double holding_N_ = 0.0;  // sum of mu_s,i N_i + N_i n_i.up over every sensor's pins
  std::uint8_t gross_ = 0;
  bool all_slide_ = false;             // every contacting pin of every sensor slides
  double all_slide_since_ = kNaN;      // first step of the current uninterrupted all_slide_ run
  long long all_slide_frame_ = 0;      // the first frame recorded at or after that step
  int n_contact_ = 0, n_slip_ = 0;
  std::vector<double> slip_on_sensor_s_;  // per sensor: first step from the load on with all its contacts sliding

  // Onsets and the prediction.
  double onset_s_ = kNaN, incipient_s_ = kNaN;
  double predicted_s_ = kNaN, coulomb_early_s_ = kNaN;
  double prev_margin_ = kNaN, prev_skin_ = kNaN, prev_t_ = 0.0;
  bool release_seen_ = false;

  // Loss and creep.
  double fall_s_ = kNaN;
  double rel_ref_ = kNaN, load_rel_ref_ = kNaN, creep_ref_ = kNaN, creep_max_ = 0.0;
  bool ending_ = false, left_behind_ = false;
};

template <class Summary>
void ObjectWatch::Fill(Summary& s, const std::vector<SensorChannel>& channels) const {
  s.object = object_.name;
  s.gross_slip_onset_s = onset_s_;
  s.incipient_onset_s = incipient_s_;
  s.incipient_lead_s = !std::isnan(incipient_s_) && !std::isnan(onset_s_) ? onset_s_ - incipient_s_ : kNaN;
  s.pre_slip_fraction = PreSlipFraction(channels);
  s.object_fall_s = fall_s_;
  s.predicted_onset_s = predicted_s_;
  s.coulomb_early_s = coulomb_early_s_;
  s.creep_um = creep_max_ * 1e6;
  s.slip_on_sensor_s = slip_on_sensor_s_;
  s.held = !left_behind_ && (std::isnan(onset_s_) || onset_s_ >= timeline_.release_s);
}

}  // namespace tactip
