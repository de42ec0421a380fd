#pragma once
// The contact between the skin and the stimulus (the `contact.` section): friction, its
// velocity weakening, and the MuJoCo contact's softness.

#include <algorithm>
#include <vector>

#include "sim/config.h"

namespace tactip {

/// Contact properties of the skin (the `contact.` section).
struct ContactConfig {
  double friction = 1.0;            ///< static Coulomb coefficient skin-stimulus
  double kinetic_ratio = 0.6;       ///< kinetic / static friction coefficient
  double friction_jitter = 0.05;    ///< per-run relative perturbation of the friction (uniform +-)
  double pin_friction_spread = 0.0; ///< per-pin relative perturbation of the friction (uniform +-)
  double weakening_speed_mm_s = 0.0;///< velocity-weakening scale v_c (0 = switch at the slip tolerance)
  double breakaway_ratio = 1.0;     ///< coefficient right after breakaway / static (weakening from there)
  double slip_memory_um = 0.0;      ///< slip distance over which a pin's friction follows its speed (0 = at once)
  double timeconst_s = 0.004;       ///< contact softness time constant
  double impedance = 0.99;          ///< contact impedance d (solimp dmax), closer to 1 = harder
  double impedance_min = 0.5;       ///< impedance at zero penetration (solimp dmin)
  double impedance_width_mm = 0.02; ///< penetration over which the impedance rises to `impedance` (solimp width)
  double presliding_mm = 0.01;      ///< tangential give of a sticking contact at the Coulomb limit (sim.noslip = exact)

  /// Lists every key of the section in order (sim/config.h).
  template <class V>
  void Visit(V& v) {
    v("friction", friction, "",
      "Static Coulomb friction coefficient between skin and stimulus (silicone rubber on PLA/acrylic "
      "~0.5-1.5).",
      Bounds::Closed(0.01, 5.0));
    v("kinetic_ratio", kinetic_ratio, "",
      "Kinetic over static friction (silicone rubber on smooth plastics ~0.5-0.8). A sliding pin's coefficient "
      "drops to kinetic_ratio * friction until it sticks again, so slip starts with the sudden release seen "
      "on hardware; 1 gives pure single-coefficient Coulomb friction.",
      Bounds::LeftOpen(0.0, 1.0));
    v("friction_jitter", friction_jitter, "",
      "Per-run variation: friction is drawn uniformly in friction * (1 +- jitter). 0 switches it off.",
      Bounds::RightOpen(0.0, 1.0));
    v("pin_friction_spread", pin_friction_spread, "",
      "Per-pin variation within a run (surface roughness, moulding): pin i's coefficients are scaled by "
      "(1 + spread * u_i), u_i uniform in [-1, 1), drawn per run. 0 gives every pin the same friction.",
      Bounds::RightOpen(0.0, 0.5));
    v("weakening_speed_mm_s", weakening_speed_mm_s, "mm/s",
      "Velocity weakening: a pin sliding at speed v has mu_k + (mu_s - mu_k) / (1 + v / v_c). 0 switches a pin "
      "to mu_k as soon as it slides faster than labels.slip_speed_m_s.",
      Bounds::Closed(0.0, 1000.0));
    v("breakaway_ratio", breakaway_ratio, "",
      "With velocity weakening: a pin that breaks away (starts to slide) drops at once to breakaway_ratio * "
      "friction and weakens from there, mu_k + (mu_b - mu_k) / (1 + v / v_c); a pin that is not sliding weakens "
      "from the static value. 1 = no sudden drop (the weakening is continuous from rest). Between "
      "kinetic_ratio and 1.",
      Bounds::LeftOpen(0.0, 1.0));
    v("slip_memory_um", slip_memory_um, "um",
      "With velocity weakening: a pin's coefficient follows the weakened value of its slip speed over this slip "
      "distance D_c instead of at once, mu <- mu_v + (mu - mu_v) exp(-v dt / D_c) each step (the slip law of "
      "rate-and-state friction): a contact must slide D_c to lose its friction, which removes the law's "
      "instantaneous negative damping; a breakaway drop is spread over D_c too. A pin that leaves contact starts "
      "again from the static value; one that sticks again regains its friction only as it creeps (over D_c of "
      "creep), not with time. 0 = memoryless.",
      Bounds::Closed(0.0, 1000.0));
    v("timeconst_s", timeconst_s, "s",
      "MuJoCo contact time constant (solref). Must be >= 2 timesteps; with impedance 0.99 the contact "
      "is ~30x stiffer than a pin's gel spring, so the gel, not the solver, sets the indentation.",
      Bounds::Closed(1e-4, 0.1));
    v("impedance", impedance, "",
      "MuJoCo contact impedance d in (0,1) once the contact has penetrated impedance_width_mm (solimp dmax); "
      "steady penetration scales with (1-d)/d.",
      Bounds::Closed(0.5, 0.9999));
    v("impedance_min", impedance_min, "",
      "Contact impedance at zero penetration (solimp dmin). Contacts are found at the start of a step, so a pin "
      "that loses contact for one step is launched by its preload; a soft onset keeps the contact's stiffness at "
      "touch-down within the step's reach (contact mode omega_0 dt < 2, see 'Numerical stability').",
      Bounds::Closed(0.01, 0.9999));
    v("impedance_width_mm", impedance_width_mm, "mm",
      "Penetration over which the impedance rises from impedance_min to impedance (solimp width). Small against "
      "the loaded pins' penetration (~35 um), so they sit at the full impedance.",
      Bounds::Closed(1e-4, 1.0));
    v("presliding_mm", presliding_mm, "mm",
      "Pre-sliding displacement: a sticking contact gives elastically along its surface and reaches the Coulomb "
      "limit mu N at this displacement (tangential stiffness mu N / presliding, so every contact's friction "
      "is used in proportion to its normal force). Lets a contact compress along a sloped surface without "
      "sliding. 0 = rigid stick. Used by the friction pass (sim.noslip = exact).",
      Bounds::Closed(0.0, 1.0));
  }
  /// impedance_min must not exceed impedance.
  void ValidateRules() const;
  /// The MJCF solimp vector of a contact geom.
  std::vector<double> Solimp() const {
    return {impedance_min, impedance, impedance_width_mm * 1e-3, 0.5, 2.0};
  }
  /// Velocity-weakened coefficient of a pin with static coefficient mu_s slipping at
  /// slip_speed_m_s (needs weakening_speed_mm_s > 0): kinetic_ratio * mu_s when fast;
  /// towards rest, mu_s for a pin that is not sliding and breakaway_ratio * mu_s for one
  /// that has broken away; halfway at the weakening speed.
  double WeakenedFriction(double mu_s, double slip_speed_m_s, bool broken_away = false) const {
    const double mu_k = kinetic_ratio * mu_s;
    const double mu_0 = broken_away ? std::max(mu_k, breakaway_ratio * mu_s) : mu_s;
    return mu_k + (mu_0 - mu_k) / (1.0 + slip_speed_m_s / (weakening_speed_mm_s * 1e-3));
  }
};

}  // namespace tactip
