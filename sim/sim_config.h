#pragma once
// Numerical settings of the MuJoCo solver shared by every scene.

#include <cmath>
#include <string>

#include "sim/config.h"

namespace tactip {

/// Integrator and constraint-solver settings (the `sim.` section).
struct SimConfig {
  double timestep_s = 2e-3;        ///< physics step
  int iterations = 50;             ///< Newton iterations per step
  double tolerance = 1e-10;        ///< solver early-exit tolerance
  int noslip_iterations = 10;      ///< noslip post-pass iterations (0 = off: contacts creep)
  double noslip_tolerance = 1e-10; ///< noslip early-exit tolerance
  double impratio = 10.0;          ///< friction-to-normal impedance ratio (elliptic cones)
  std::string cone = "elliptic";   ///< friction cone
  bool check_stability = true;     ///< refuse timesteps above the stiffest mode's limit

  template <class V>
  void Visit(V& v) {
    v("timestep_s", timestep_s, "s",
      "Physics step. 2 ms is stable for the default skin (stiffest pin mode omega*dt = 1.93 against a limit "
      "of 2.74) and keeps the slip-onset error within one camera frame of the 0.5 ms reference.",
      Bounds::Closed(1e-5, 0.01));
    v("iterations", iterations, "",
      "Maximum Newton iterations per step (the solver usually exits after 2-5).", Bounds::Closed(1, 1000));
    v("tolerance", tolerance, "", "Newton early-exit tolerance on the cost improvement.",
      Bounds::LeftOpen(0.0, 1e-2));
    v("noslip_iterations", noslip_iterations, "",
      "Noslip post-pass iterations. MuJoCo friction rows have no position term, so without this pass "
      "a stuck contact creeps (~1 mm/s measured); 10 reduces creep to ~1e-5 mm/s.",
      Bounds::Closed(0, 1000));
    v("noslip_tolerance", noslip_tolerance, "", "Noslip early-exit tolerance.", Bounds::LeftOpen(0.0, 1e-2));
    v("impratio", impratio, "",
      "Ratio of frictional to normal constraint impedance; high values make friction stiff (less "
      "creep) with elliptic cones.",
      Bounds::Closed(1.0, 1000.0));
    v("cone", cone, "", "Friction cone type: elliptic is the exact Coulomb cone.", Choices{"elliptic", "pyramidal"});
    v("check_stability", check_stability, "",
      "Refuse a timestep above 0.9 x the stability limit of the stiffest explicit spring mode "
      "(see MaxStableTimestep). Turn off only to study the instability itself.");
  }
};

/// Largest stable timestep (s) of a spring mode of natural frequency `omega` (rad/s)
/// and damping ratio `zeta` under MuJoCo's Euler integrator, which integrates joint
/// damping implicitly and stiffness explicitly: the update is stable for
/// omega*dt < 2 (zeta + sqrt(zeta^2 + 1)) (2 when undamped). `safety` scales the limit.
inline double MaxStableTimestep(double omega, double zeta, double safety = 0.9) {
  return safety * 2.0 * (zeta + std::sqrt(zeta * zeta + 1.0)) / omega;
}

}  // namespace tactip
