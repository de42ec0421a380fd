#pragma once
// The shell skin's in-plane damper under skin.shell_damping = gel.
#include <cmath>
#include <string>
#include <vector>

#include "models/skin.h"
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
  /// Finds the shell joint along the rail of each sensor (`sensor_prefixes`: their MJCF
  /// prefixes, "NAME/") in `model` (this run's copy, which Update changes); every sensor has
  /// `skin` with `n_pins` pins and holds the object of `object_mass_kg` with the others.
  ShellDamping(const SkinConfig& skin, double object_mass_kg, const std::vector<std::string>& sensor_prefixes,
               CompiledModel& model, int n_pins);

  bool active() const { return !dofs_.empty(); }
  /// `stuck[k]`: sensor k's stuck share of its contacting pins (0 with no contact).
  void Update(const std::vector<double>& stuck);
  /// The damper's factor over c_shell for a carried object mass of `mass_ratio` shell masses.
  static double Factor(double mass_ratio) { return std::sqrt(1.0 + mass_ratio); }

 private:
  CompiledModel* model_ = nullptr;
  std::vector<int> dofs_;           ///< each sensor's z (along the rail) shell dof, in sensor order
  double c_shell_ = 0.0;            ///< the shell alone's damper (N s/m)
  double object_over_shell_ = 0.0;  ///< m_object / M_shell
};

}  // namespace tactip
