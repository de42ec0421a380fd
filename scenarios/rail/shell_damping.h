#pragma once
// The shell skin's in-plane damper under skin.shell_damping = gel.
#include <cmath>
#include <vector>

#include "scenarios/rail/rail_config.h"
#include "sim/simulation.h"

namespace tactip {

/// A gel with a constant loss tangent damps every mode at about the same ratio, whatever
/// mass moves in it. The shell skin's in-plane mode along the rail (its z joint) carries
/// the shell alone (M_shell: the membrane plus every pin) once the contact slides, and the
/// shell plus the held object while the contact sticks; a fixed damper set for the first
/// leaves the second barely damped (0.4 kg: a quarter of the ratio). So the z damper follows
/// the carried mass M_shell + share * m_object:
/// c = c_shell * sqrt(1 + share * m_object / M_shell), where c_shell gives the shell alone
/// skin.shear_damping_ratio and share is the object's share held by this sensor's stuck
/// contacts (its stuck fraction of contacting pins, divided by the number of sensors with
/// stuck contacts). An approximation: the share counts stuck pins, not where the object's
/// weight goes (before the lift the end stop carries it; in partial slip the object still
/// moves with the shell while the share falls). Across the rail (y) the object, on its
/// slide joint, does not move, and that damper stays c_shell. Does nothing under
/// skin.shell_damping = viscous.
class ShellDamping {
 public:
  ShellDamping() = default;  ///< inactive
  /// Finds each sensor's shell joint along the rail in `model` (this run's copy, which
  /// Update changes); `n_pins` per sensor.
  ShellDamping(const RailScenarioConfig& cfg, CompiledModel& model, int n_pins);

  bool active() const { return !dofs_.empty(); }
  /// `stuck[k]`: sensor k's stuck share of its contacting pins (0 with no contact).
  void Update(const std::vector<double>& stuck);
  /// The damper's factor over c_shell for a carried object mass of `mass_ratio` shell masses.
  static double Factor(double mass_ratio) { return std::sqrt(1.0 + mass_ratio); }

 private:
  CompiledModel* model_ = nullptr;
  std::vector<int> dofs_;           ///< each sensor's z (along the rail) shell dof, in the config's order
  double c_shell_ = 0.0;            ///< the shell alone's damper (N s/m)
  double object_over_shell_ = 0.0;  ///< m_object / M_shell
};

}  // namespace tactip
