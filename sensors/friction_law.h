#pragma once
// Rubber friction of a skin's pins against the stimulus: a static coefficient per pin
// (the run's coefficient with a per-pin spread), dropping to kinetic while a pin slides
// (switched at the slip tolerance, or weakened continuously with the slip speed). MuJoCo
// takes the larger of two geoms' coefficients, so the stimulus carries the lowest kinetic
// value of any pin and each pin's own geom carries the coefficient in force. With a slip
// memory the weakened coefficient is approached over a slip distance, not at once.

#include <cstdint>
#include <vector>

#include "models/skin.h"
#include "sensors/labels.h"
#include "sim/simulation.h"

namespace tactip {

/// The friction law of one skin in one run. Not thread-safe; one per run.
class FrictionLaw {
 public:
  /// Draws each pin's static coefficient around `mu` (relative spread
  /// contact.pin_friction_spread, from `seed`) and sets the geoms of `model`: the pins'
  /// (`pin_geom`, -1 = no geom) and the stimulus's (`stimulus_geom`).
  FrictionLaw(const ContactConfig& contact, const LabelConfig& labels, double mu, const std::vector<int>& pin_geom,
              int stimulus_geom, std::uint64_t seed, CompiledModel& model);

  /// True when a pin's coefficient changes as it slides (kinetic_ratio < 1): Update must then
  /// see the contacts at every step.
  bool switching() const { return contact_.kinetic_ratio < 1.0; }
  /// Switches each pin from this step's contact samples and slip labels, in `model`; called
  /// at every physics step, whose length (the model's, for contact.slip_memory_um) may change.
  void Update(const std::vector<PinContactSample>& samples, const std::vector<std::uint8_t>& pin_slip,
              CompiledModel& model);
  /// Per pin: the static coefficient.
  const std::vector<double>& static_mu() const { return mu_pin_; }

 private:
  const ContactConfig contact_;
  const double slip_speed_m_s_;
  const std::vector<int> pin_geom_;
  std::vector<double> mu_pin_;          // per pin: static coefficient
  std::vector<double> mu_cur_;          // per pin: coefficient in force
  std::vector<std::uint8_t> sliding_;   // per pin: kinetic friction in force
};

}  // namespace tactip
