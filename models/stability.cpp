#include "models/stability.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace tactip {

namespace {
constexpr double kSafety = 0.9;  // as MaxStableTimestep
}  // namespace

double StiffMode::MaxTimestep() const { return MaxStableTimestep(omega, zeta, kSafety); }

StiffMode ContactTouchdownMode(const ContactConfig& contact) {
  // solref (timeconst, dampratio 1): stiffness 1 / (dmax timeconst)^2 per unit mass, scaled
  // by d / (1 - d) at impedance d.
  const double d0 = contact.impedance_min;
  StiffMode m;
  m.omega = std::sqrt(d0 / (1.0 - d0)) / (contact.impedance * contact.timeconst_s);
  m.zeta = 0.0;
  m.name = "the contact's touch-down mode (set by contact.impedance_min, contact.impedance, contact.timeconst_s)";
  return m;
}

double MaxStableImpedanceMin(const ContactConfig& contact, double timestep_s) {
  const double omega_max = kSafety * 2.0 / timestep_s;
  const double x = std::pow(omega_max * contact.impedance * contact.timeconst_s, 2.0);
  return x / (1.0 + x);
}

std::vector<StiffMode> RailModes(const RailSceneSpec& spec) {
  const PinLattice lattice = PinLattice::Build(spec.skin);
  const SkinMechanics mech = SkinMechanics::From(spec.skin, lattice);
  const bool membrane = spec.skin.coupling == "membrane";
  std::vector<StiffMode> modes;
  // The pin normal mode with every neighbour in antiphase. A membrane lattice raises its
  // joint damping to keep its modes stable at the configured step.
  StiffMode pin;
  pin.omega = mech.StiffestOmega();
  const double c_normal = membrane ? mech.NormalDamping(spec.sim.timestep_s) : mech.pin_damping_Ns_m;
  // Dome springs: the stiffest pin moves along its dome normal, on the mass m / g, damped
  // through its normal and shear joints in series (SkinMechanics::DomeSpringDamping).
  const double c_tip = membrane ? mech.TipDamping(spec.sim.timestep_s) : mech.tip_damping_Ns_m;
  pin.zeta = mech.DomeSpringDamping(c_normal, c_tip) * mech.dome_gain / (2.0 * mech.pin_mass_kg * pin.omega);
  pin.damping_follows_timestep = membrane;
  pin.name = "the skin's pin normal mode (set by skin.gel_modulus_kpa, skin.skin_modulus_mpa, skin.thickness_mm, "
             "skin.pin_mass_g, skin.normal_spring)";
  modes.push_back(pin);
  if (membrane) {
    StiffMode shear;
    shear.omega = mech.StiffestShearOmega();
    shear.zeta = mech.TipDamping(spec.sim.timestep_s) / (2.0 * mech.pin_mass_kg * shear.omega);
    shear.damping_follows_timestep = true;
    shear.name = "the membrane lattice's shear mode (set by skin.thickness_mm, skin.skin_modulus_mpa, skin.ridge_*, "
                 "skin.membrane_links, skin.pin_mass_g)";
    modes.push_back(shear);
  }
  if (spec.skin.coupling == "shell") {
    // The shell's in-plane translation on the gel columns and, when clamped, the rim's annulus.
    StiffMode shell;
    shell.omega = std::sqrt(mech.ShellShearStiffness(lattice.size()) / mech.shell_moving_mass_kg);
    shell.zeta = mech.shell_damping_Ns_m / (2.0 * mech.shell_moving_mass_kg * shell.omega);
    shell.name = "the smooth skin's in-plane shell mode (set by skin.gel_shear_modulus_kpa and, with skin.rim = "
                 "clamped, skin.skin_modulus_mpa and skin.thickness_mm)";
    modes.push_back(shell);
  }
  // The z servo carries less mass than the x servo, so it is the stiffer of the two.
  StiffMode arm;
  const double m_sensors = static_cast<double>(spec.sensors.size()) * SensorMassKg(mech, lattice.size());
  arm.omega = spec.arm.Omega(spec.arm.stage_mass_kg + m_sensors);
  arm.zeta = spec.arm.damping_ratio;
  arm.name = "the arm servo (set by arm.kp_N_m, arm.stage_mass_kg)";
  modes.push_back(arm);
  StiffMode touch = ContactTouchdownMode(spec.contact);
  touch.other_fix = "contact.impedance_min <= " +
                   config_detail::FormatAtMost(MaxStableImpedanceMin(spec.contact, spec.sim.timestep_s));
  modes.push_back(touch);
  return modes;
}

double ShearDofValidatedTimestep(const SkinConfig& skin, const ContactConfig& contact) {
  if (skin.coupling == "shell") return std::numeric_limits<double>::infinity();
  return kShearDofValidatedStepS / std::max(1.0, contact.friction);
}

double LightShellValidatedSlidingStep(const SkinConfig& skin) {
  if (skin.coupling != "shell" || skin.ShellDampingRatio() >= kLightShellDampingRatio) {
    return std::numeric_limits<double>::infinity();
  }
  return kLightShellValidatedStepS;
}

StiffMode RailStiffestMode(const RailSceneSpec& spec) {
  const std::vector<StiffMode> modes = RailModes(spec);
  return *std::min_element(modes.begin(), modes.end(),
                           [](const StiffMode& a, const StiffMode& b) { return a.MaxTimestep() < b.MaxTimestep(); });
}

StableTimestep LargestStableTimestep(const RailSceneSpec& spec) {
  // The modes with their physical damping (a vanishing step raises nothing).
  RailSceneSpec physical = spec;
  physical.sim.timestep_s = 1e-9;
  StableTimestep best;
  best.timestep_s = std::numeric_limits<double>::infinity();
  for (const StiffMode& m : RailModes(physical)) {
    // A membrane mode keeps its physical damping only while the step stays below its
    // limit by the margin the model's damping floor keeps.
    const double limit = m.damping_follows_timestep ? m.MaxTimestep() / SkinMechanics::kDampingRaiseMargin
                                                    : m.MaxTimestep();
    if (limit < best.timestep_s) best = {limit, m};
  }
  return best;
}

}  // namespace tactip
