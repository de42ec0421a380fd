#include "scenarios/scene/object_watch.h"

#include <algorithm>
#include <cmath>

namespace tactip {

namespace {
constexpr double kOffDropM = 10e-3;  // an object this far below its held position has left the skin
}  // namespace

ObjectWatch::ObjectWatch(const SceneObject& object, const ProtocolTimeline& timeline, const LabelConfig& labels,
                         double gravity_m_s2, size_t n_sensors)
    : object_(object),
      timeline_(timeline),
      slip_speed_m_s_(labels.slip_speed_m_s),
      fall_threshold_m_(labels.fall_threshold_mm * 1e-3),
      weight_N_(object.mass_kg * gravity_m_s2),
      slip_on_sensor_s_(n_sensors, kNaN) {}

void ObjectWatch::ReadContacts(double t, const std::vector<SensorChannel>& channels, const Simulation& sim,
                               int carrier_up_dof) {
  // Friction holds up to mu_s N along the vertical (it acts across the pressing axis); a
  // sloped contact's normal force also pushes along it.
  holding_N_ = 0.0;
  for (const SensorChannel& ch : channels) {
    const std::vector<double>& mu_pin = ch.friction.static_mu();
    const std::vector<GeomContact>& contacts = ch.sensor.contacts();
    for (size_t i = 0; i < contacts.size(); ++i) {
      holding_N_ += mu_pin[i] * contacts[i].normal_N - contacts[i].normal_N * contacts[i].normal_world[2];
    }
  }
  // Gross slip: every contacting pin of every sensor slides and the object moves relative to
  // the sensors (with support friction the skin alone may creep under a still object for a
  // few frames first). The object slips on sensor S when every contacting pin of S slides.
  n_contact_ = n_slip_ = 0;
  bool every_contact_slides = true;
  for (size_t k = 0; k < channels.size(); ++k) {
    const FrameLabels& labels = channels[k].sensor.labels();
    n_contact_ += labels.n_contact;
    n_slip_ += labels.n_slip;
    if (labels.n_contact > 0 && !labels.gross_slip) every_contact_slides = false;
    const bool slips_on_it = labels.n_contact > 0 && labels.gross_slip;
    if (slips_on_it && t >= timeline_.load_s && std::isnan(slip_on_sensor_s_[k])) slip_on_sensor_s_[k] = t;
  }
  all_slide_ = n_contact_ > 0 && every_contact_slides;
  const double carrier = carrier_up_dof >= 0 ? sim.Qvel(carrier_up_dof) : 0.0;
  const double obj_speed = std::abs(sim.Qvel(object_.up_dof) - carrier);
  gross_ = all_slide_ && obj_speed > slip_speed_m_s_ ? 1 : 0;
}

OnsetStep ObjectWatch::TrackOnset(double t, bool seek, long long frame) {
  // Gross onset, once the load is on: the first step of the uninterrupted run of steps in
  // which every contacting pin slides that brings the object into motion. The skin often lets
  // go a step before the object follows (its released shear springs back under the still
  // object); those steps and their frames are gross slip too.
  OnsetStep out;
  if (!seek) return out;
  if (!all_slide_) {
    all_slide_since_ = kNaN;
    return out;
  }
  if (std::isnan(all_slide_since_)) {
    all_slide_since_ = t;
    all_slide_frame_ = frame;
    out.all_slide_began = true;
  }
  if (!gross_) return out;
  onset_s_ = all_slide_since_;
  out.gross_from_frame = all_slide_frame_;
  return out;
}

void ObjectWatch::TrackPrediction(double t) {
  // Coulomb prediction from the simulated normal forces: the holding margin sum(mu_i N_i) +
  // normal push along the vertical + support friction - m g crosses zero between two steps.
  // The support's static friction (either sign, up to F) shares the load in a statically
  // undetermined way, so the skin may start sliding anywhere between sum(mu_i N_i) = m g + F
  // and sum(mu_i N_i) = m g - F.
  const double margin = holding_N_ + object_.support_friction_N - weight_N_;
  const double skin_margin = margin - 2.0 * object_.support_friction_N;
  if (!std::isnan(prev_margin_) && prev_margin_ >= 0.0 && margin < 0.0) {
    predicted_s_ = prev_t_ + (t - prev_t_) * prev_margin_ / (prev_margin_ - margin);
  }
  if (std::isnan(coulomb_early_s_) && !std::isnan(prev_skin_) && prev_skin_ >= 0.0 && skin_margin < 0.0) {
    coulomb_early_s_ = prev_t_ + (t - prev_t_) * prev_skin_ / (prev_skin_ - skin_margin);
  }
  prev_margin_ = margin;
  prev_skin_ = skin_margin;
  prev_t_ = t;
}

void ObjectWatch::TrackFirstSlips(double t, std::vector<SensorChannel>& channels) const {
  // At step resolution (the contacts are read at every step until the onset is found): the
  // frames alone cannot order pins that start to slip within one frame.
  if (t < timeline_.release_s || !std::isnan(onset_s_)) return;
  for (SensorChannel& ch : channels) {
    const std::vector<std::uint8_t>& slip = ch.sensor.pin_slip();
    for (size_t i = 0; i < slip.size(); ++i) {
      if (slip[i] && std::isnan(ch.first_slip_s[i])) ch.first_slip_s[i] = t;
    }
  }
}

void ObjectWatch::TrackIncipient(double t, std::vector<SensorChannel>& channels) {
  // Incipient slip: partial slip from the release on, before gross slip.
  if (t < timeline_.release_s || !std::isnan(onset_s_)) return;
  for (SensorChannel& ch : channels) {
    const std::vector<std::uint8_t>& slip = ch.sensor.pin_slip();
    if (!release_seen_) ch.contact_at_release = ch.sensor.pin_contact();
    for (size_t i = 0; i < slip.size(); ++i) {
      if (ch.contact_at_release[i] && slip[i] && std::isnan(ch.first_slip_frame_s[i])) ch.first_slip_frame_s[i] = t;
    }
  }
  release_seen_ = true;
  const bool partial = n_slip_ > 0 && n_slip_ < n_contact_;
  if (partial && std::isnan(incipient_s_)) incipient_s_ = t;
}

double ObjectWatch::TrackEvents(double t, double tf, double rel_z, double creep_z) {
  constexpr double kNotYet = std::numeric_limits<double>::infinity();
  // An object the skin cannot carry is left behind during the load (its contact may be lost
  // before every pin is seen sliding): the run ends, not held.
  if (t >= timeline_.load_s && t < timeline_.release_s && std::isnan(onset_s_)) {
    if (std::isnan(load_rel_ref_)) load_rel_ref_ = rel_z;
    if (load_rel_ref_ - rel_z > kOffDropM && !ending_) {
      left_behind_ = true;
      fall_s_ = tf;
      ending_ = true;
      return t + timeline_.after_loss_s;
    }
    return kNotYet;
  }
  // From the release on (or from the onset, if the object already slips during the load):
  // its drop relative to the sensor, and its sliding relative to the centre pin.
  if (t < timeline_.release_s && std::isnan(onset_s_)) return kNotYet;
  if (std::isnan(rel_ref_)) {
    rel_ref_ = rel_z;
    creep_ref_ = creep_z;
  }
  if (std::isnan(onset_s_)) creep_max_ = std::max(creep_max_, std::abs(creep_z - creep_ref_));
  if (std::isnan(fall_s_) && rel_ref_ - rel_z > fall_threshold_m_) fall_s_ = tf;
  // The run ends after_loss_s after the fall once the object really slides off: a compliant
  // (fingerprint) skin can sag past the fall threshold while its centre still sticks, so the
  // fall alone does not end it unless the drop is large.
  const bool off = !std::isnan(onset_s_) || rel_ref_ - rel_z > kOffDropM;
  if (!std::isnan(fall_s_) && off && !ending_) {
    ending_ = true;
    return t + timeline_.after_loss_s;
  }
  return kNotYet;
}

double ObjectWatch::PreSlipFraction(const std::vector<SensorChannel>& channels) const {
  // The onset is dated back to the first step of its all-slide run; frames from that step on,
  // read while the onset was being confirmed, are gross slip, not slip before it (a frame on
  // the onset's own step too: every contacting pin slides there).
  if (!release_seen_) return kNaN;
  const auto before_gross = [&](double t) { return !std::isnan(t) && (std::isnan(onset_s_) || t < onset_s_); };
  int n_c = 0, n_s = 0;
  for (const SensorChannel& ch : channels) {
    for (size_t i = 0; i < ch.contact_at_release.size(); ++i) {
      n_c += ch.contact_at_release[i];
      n_s += before_gross(ch.first_slip_frame_s[i]) ? 1 : 0;
    }
  }
  return n_c > 0 ? static_cast<double>(n_s) / n_c : kNaN;
}

std::vector<double> ObjectWatch::FirstSlips(const SensorChannel& channel) const {
  // A pin first seen slipping after the onset's first step, while the onset was being
  // confirmed, slipped in gross slip.
  std::vector<double> first = channel.first_slip_s;
  for (double& t : first) {
    if (t > onset_s_) t = kNaN;
  }
  return first;
}

}  // namespace tactip
