#include "sensors/friction_law.h"

#include <cmath>

#include "sim/base/random.h"

namespace tactip {

FrictionLaw::FrictionLaw(const ContactConfig& contact, const LabelConfig& labels, double mu,
                         const std::vector<int>& pin_geom, int stimulus_geom, std::uint64_t seed,
                         CompiledModel& model)
    : contact_(contact), slip_speed_m_s_(labels.slip_speed_m_s), pin_geom_(pin_geom) {
  // Static coefficients with their per-pin spread; the stimulus at the lowest kinetic value.
  const size_t n = pin_geom.size();
  const double mu_k = mu * contact.kinetic_ratio;
  mu_pin_.assign(n, mu);
  Rng pin_rng(seed);
  for (double& m : mu_pin_) m *= 1.0 + contact.pin_friction_spread * pin_rng.Uniform(-1.0, 1.0);
  model.SetGeomFriction(stimulus_geom, mu_k * (1.0 - contact.pin_friction_spread));
  for (size_t i = 0; i < n; ++i) {
    if (pin_geom_[i] >= 0) model.SetGeomFriction(pin_geom_[i], mu_pin_[i]);
  }
  sliding_.assign(n, 0);
  mu_cur_ = mu_pin_;
}

void FrictionLaw::Update(const std::vector<PinContactSample>& samples, const std::vector<std::uint8_t>& pin_slip,
                         CompiledModel& model) {
  const bool weakening = contact_.weakening_speed_mm_s > 0.0;
  const double memory_m = contact_.slip_memory_um * 1e-6;
  const double dt = model.timestep();
  for (size_t i = 0; i < pin_geom_.size(); ++i) {
    if (pin_geom_[i] < 0) continue;
    // A pin slides from the step it is labelled slipping until it sticks again (or leaves
    // contact).
    const bool now = pin_slip[i] || (sliding_[i] && samples[i].in_contact &&
                                     samples[i].slip_speed_m_s > slip_speed_m_s_);
    if (weakening) {
      // Velocity weakening from this step's slip speed (from the breakaway value once sliding),
      // at once or, with a slip memory, over the slip distance D_c; a pin out of contact
      // starts afresh.
      sliding_[i] = now ? 1 : 0;
      const double v = samples[i].in_contact ? samples[i].slip_speed_m_s : 0.0;
      const double target = contact_.WeakenedFriction(mu_pin_[i], v, now);
      const bool remembers = memory_m > 0.0 && samples[i].in_contact;
      mu_cur_[i] = remembers ? target + (mu_cur_[i] - target) * std::exp(-v * dt / memory_m) : target;
    } else {
      // Static -> kinetic when a pin slides, back when it sticks.
      if (now == static_cast<bool>(sliding_[i])) continue;
      sliding_[i] = now ? 1 : 0;
      mu_cur_[i] = now ? contact_.kinetic_ratio * mu_pin_[i] : mu_pin_[i];
    }
    model.SetGeomFriction(pin_geom_[i], mu_cur_[i]);
  }
}

}  // namespace tactip
