#pragma once
// The modes that limit a rail scene's timestep, each with the largest stable step and what
// to change: the skin's pin normal mode, a membrane lattice's shear mode, the arm servos,
// and the contact's touch-down mode.
//
// MuJoCo's Euler step integrates joint damping implicitly and stiffness explicitly; a mode
// of frequency omega and damping ratio zeta is stable for omega dt < 2 (zeta + sqrt(zeta^2
// + 1)). A contact is found at the start of a step and holds no force while apart, so its
// touch-down is explicit and undamped: MuJoCo's soft contact at zero penetration acts on a
// body as a spring of omega_0 = sqrt(d0 / (1 - d0)) / (dmax timeconst) per unit mass (d0 =
// contact.impedance_min, dmax = contact.impedance), stable for omega_0 dt < 2. Above it a
// pin that loses contact for one step is launched by its preload and chatters in and out.

#include <string>
#include <vector>

#include "models/rail_rig.h"

namespace tactip {

/// One timestep-limiting mode.
struct StiffMode {
  double omega = 0.0;     ///< natural frequency, rad/s
  double zeta = 0.0;      ///< damping ratio (0 for the explicit contact touch-down)
  std::string name;       ///< which part it belongs to and the keys that set it
  std::string other_fix;  ///< besides a smaller timestep, what makes it stable ("" if nothing)
  /// True for a membrane lattice's modes, whose joint damping the model raises where the
  /// timestep would otherwise make them unstable (SkinMechanics::NormalDamping, TipDamping).
  bool damping_follows_timestep = false;
  /// Largest stable timestep with the 0.9 safety factor, s.
  double MaxTimestep() const;
};

/// Every timestep-limiting mode of a rail scene.
std::vector<StiffMode> RailModes(const RailSceneSpec& spec);

/// The mode with the smallest stable timestep.
StiffMode RailStiffestMode(const RailSceneSpec& spec);

/// The largest timestep of a rail scene that the stability estimate accepts with the damping
/// the config asks for, and the mode that sets it.
struct StableTimestep {
  double timestep_s = 0.0;  ///< largest step, s
  StiffMode mode;           ///< the binding mode
};

/// The largest step at which every mode of RailModes is stable (0.9 safety factor) with its
/// configured damping: a membrane lattice's modes count only up to the step at which the
/// model would start raising their damping (SkinMechanics::kDampingRaiseMargin), so the step
/// found never changes the physics. `spec.sim.timestep_s` is ignored.
StableTimestep LargestStableTimestep(const RailSceneSpec& spec);

/// Largest step at which a skin with per-pin shear DOFs (skin.coupling = membrane or none:
/// the fingerprint skins) is validated, s; infinity for the shell. Not a mode of the
/// estimate but a measured limit: its light shear DOFs stick and slip against the friction
/// pass one step at a time, and at 2 ms those events create energy (0.05-0.43 x the stored
/// elastic energy while held, pins flickering and jumping) that no linear mode predicts; at
/// 1 ms they stay within run health at mu = 1. A slip event releases a shear load of order
/// mu N, so above mu = 1 the step shrinks as 1 / mu (contact.friction; at mu = 3, 1 ms
/// makes a pin bounce, 0.5 ms is healthy) (docs/numerics.md, "Numerical stability").
double ShearDofValidatedTimestep(const SkinConfig& skin, const ContactConfig& contact);

/// Largest validated sliding step (the step a rail run takes from the gross-slip onset on,
/// SimConfig::SlidingTimestep) of a shell skin damped below kLightShellDampingRatio (coupling
/// shell; skin.shear_damping_ratio, or skin.gel_loss_tangent / 2 under skin.shell_damping = gel):
/// kLightShellValidatedStepS; infinity for any other skin. The held phase takes any stable step.
double LightShellValidatedSlidingStep(const SkinConfig& skin);

/// The contact's touch-down mode.
StiffMode ContactTouchdownMode(const ContactConfig& contact);

/// Largest contact.impedance_min whose touch-down mode is stable at `timestep_s`.
double MaxStableImpedanceMin(const ContactConfig& contact, double timestep_s);

}  // namespace tactip
