#include "scenarios/scene/run_health.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace tactip {

RunHealthMonitor::RunHealthMonitor(int n_pins, const HealthConfig& cfg)
    : cfg_(cfg),
      n_(n_pins),
      prev_px_(2 * static_cast<size_t>(n_pins)),
      prev_contact_(n_pins, 0),
      transitions_(n_pins, 0),
      creep_ref_m_(std::numeric_limits<double>::quiet_NaN()) {}

void RunHealthMonitor::Frame(bool held, bool retracting, const float* clean_px, const std::uint8_t* pin_contact,
                             bool any_slip, double creep_m, double quasi_static_px) {
  if (!held) {
    have_prev_ = false;
    return;
  }
  // Contact transitions and pin speed, frame to frame, while held (speed only until a pin slips).
  if (any_slip) slipped_ = true;
  if (have_prev_) {
    for (int i = 0; i < n_; ++i) {
      transitions_[i] += pin_contact[i] != prev_contact_[i] ? 1 : 0;
      if (slipped_) continue;
      const double du = clean_px[2 * i] - prev_px_[2 * i], dv = clean_px[2 * i + 1] - prev_px_[2 * i + 1];
      pin_speed_px_ = std::max(pin_speed_px_, std::hypot(du, dv) - quasi_static_px);
    }
  }
  std::copy(clean_px, clean_px + 2 * n_, prev_px_.begin());
  std::copy(pin_contact, pin_contact + n_, prev_contact_.begin());
  have_prev_ = true;
  // Creep: from the retraction on, until a pin slips.
  if (!retracting || slipped_ || std::isnan(creep_m)) return;
  if (std::isnan(creep_ref_m_)) creep_ref_m_ = creep_m;
  creep_max_m_ = std::max(creep_max_m_, std::abs(creep_m - creep_ref_m_));
}

void RunHealthMonitor::Step(double created_J, double stored_J) {
  if (created_J > 0.0) created_J_ += created_J;
  stored_max_J_ = std::max(stored_max_J_, stored_J);
}

RunHealth RunHealthMonitor::Result() const {
  RunHealth h;
  for (int i = 0; i < n_; ++i) {
    if (transitions_[i] > h.flicker_max) {
      h.flicker_max = transitions_[i];
      h.flicker_pin = i;
    }
  }
  h.pin_speed_px = pin_speed_px_;
  h.stick_creep_um = creep_max_m_ * 1e6;
  h.energy_gain = stored_max_J_ > 0.0 ? created_J_ / stored_max_J_ : 0.0;
  // Every figure over its threshold goes into the reason.
  const auto flag = [&](bool bad, const std::string& why) {
    if (!bad) return;
    h.ok = false;
    h.reason += (h.reason.empty() ? "" : "; ") + why;
  };
  flag(h.flicker_max > cfg_.max_flicker, fmt::format("pin {} flickered in and out of contact {} times while held "
                                                     "(health.max_flicker = {})",
                                                     h.flicker_pin, h.flicker_max, cfg_.max_flicker));
  flag(h.pin_speed_px > cfg_.max_pin_speed_px,
       fmt::format("pins moved {:.3g} px/frame more than the sensor's motion explains while held with nothing "
                   "slipping (health.max_pin_speed_px = {})",
                   h.pin_speed_px, cfg_.max_pin_speed_px));
  flag(h.stick_creep_um > cfg_.max_stick_creep_um,
       fmt::format("the object crept {:.3g} um on the sticking contact (health.max_stick_creep_um = {})",
                   h.stick_creep_um, cfg_.max_stick_creep_um));
  flag(h.energy_gain > cfg_.max_energy_gain,
       fmt::format("the integration created {:.3g} x the stored elastic energy while held (health.max_energy_gain = "
                   "{})",
                   h.energy_gain, cfg_.max_energy_gain));
  return h;
}

}  // namespace tactip
