#pragma once
// Numerical settings of the MuJoCo solver shared by every scene.

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/config.h"

namespace tactip {

/// Name of the MJCF custom numeric that switches tactip's friction pass on (sim.noslip =
/// exact); its values are the clamp-and-solve rounds and the pre-sliding displacement in
/// metres. Scenes write it with MuJoCo's own noslip off.
inline constexpr const char* kFrictionPassNumeric = "tactip_friction_pass";

/// Name of the MJCF custom numeric holding sim.free_sliding_speed_mm_s (in m/s): contacts
/// sliding faster lose their friction rows' velocity target in MuJoCo's solve (faded out,
/// none at twice it; sim/friction_reference.h). Absent: MuJoCo's target everywhere.
inline constexpr const char* kFreeSlidingNumeric = "tactip_free_sliding_speed";

/// Integrator and constraint-solver settings (the `sim.` section).
struct SimConfig {
  /// Shortest allowed physics step, s.
  static constexpr double kMinTimestepS = 1e-5;
  /// Fewest Newton iterations allowed: with fewer the solver stops unconverged while the
  /// contact changes fast and pins fly off (see the doc of `iterations`).
  static constexpr int kMinIterations = 20;
  double timestep_s = 2e-3;        ///< physics step
  int iterations = 50;             ///< Newton iterations per step
  double tolerance = 1e-10;        ///< solver early-exit tolerance
  std::string noslip = "exact";    ///< friction post-pass: exact (direct solve) or mujoco (Gauss-Seidel sweeps)
  int noslip_iterations = 10;      ///< noslip rounds (exact) or sweeps (mujoco); 0 = off: contacts creep
  double noslip_tolerance = 1e-10; ///< noslip early-exit tolerance
  double impratio = 10.0;          ///< friction-to-normal impedance ratio (elliptic cones)
  std::string cone = "elliptic";   ///< friction cone
  bool check_stability = true;     ///< refuse timesteps above the stiffest mode's limit
  double free_sliding_speed_mm_s = 30.0;  ///< faster contacts: friction velocity target faded out (none at 2x)
  double sliding_timestep_s = 1e-3;  ///< at most this step from the gross-slip onset on; 0 = timestep_s throughout

  /// The step a rail run takes from the gross-slip onset on: timestep_s when sliding_timestep_s
  /// is 0 or not smaller, else the largest whole fraction timestep_s / k that is at most
  /// sliding_timestep_s (to a relative 1e-9, which keeps an exact divisor from being pushed to
  /// the next k by rounding), so that frames on the held step's grid stay on the finer one.
  double SlidingTimestep() const {
    if (sliding_timestep_s <= 0.0 || sliding_timestep_s >= timestep_s) return timestep_s;
    return timestep_s / std::ceil(timestep_s / sliding_timestep_s - 1e-9);
  }

  template <class V>
  void Visit(V& v) {
    v("timestep_s", timestep_s, "s",
      "Physics step. 2 ms is stable for the default skin (stiffest pin mode omega*dt = 1.93 against a limit "
      "of 2.74) and keeps the slip-onset error within one camera frame of the 0.5 ms reference.",
      Bounds::Closed(kMinTimestepS, 0.01));
    v("iterations", iterations, "",
      "Maximum Newton iterations per step (on the rail scene the solver exits after 1 on average: tactip bench "
      "--speed). At least 20: with fewer the solver stops unconverged when the contact changes fast (gross slip, "
      "the object leaving) and pins are thrown far off with forces far beyond the press (measured on every "
      "stimulus and skin: 12 or fewer give unhealthy or absurd runs, 15 and more the same runs as 50).",
      Bounds::Closed(kMinIterations, 1000));
    v("tolerance", tolerance, "", "Newton early-exit tolerance on the cost improvement.",
      Bounds::LeftOpen(0.0, 1e-2));
    v("noslip", noslip, "",
      "Friction post-pass that stops sticking contacts from creeping. exact: the friction forces of all contacts "
      "solved at once (Cholesky of the friction rows' Delassus matrix), contacts outside their cone clamped onto "
      "it and the rest solved again. mujoco: MuJoCo's own noslip (Gauss-Seidel sweeps), which converges slowly "
      "when many contacts share a few heavy bodies and each moves a light pin of its own (sloped contacts).",
      Choices{"exact", "mujoco"});
    v("noslip_iterations", noslip_iterations, "",
      "Noslip pass: clamp-and-solve rounds (exact) or Gauss-Seidel sweeps (mujoco). MuJoCo friction rows have "
      "no position term, so without this pass a stuck contact creeps (~1 mm/s measured); 0 switches it off.",
      Bounds::Closed(0, 1000));
    v("noslip_tolerance", noslip_tolerance, "", "Noslip early-exit tolerance.", Bounds::LeftOpen(0.0, 1e-2));
    v("impratio", impratio, "",
      "Ratio of frictional to normal constraint impedance; high values make friction stiff (less "
      "creep) with elliptic cones.",
      Bounds::Closed(0.01, 1000.0));
    v("cone", cone, "", "Friction cone type: elliptic is the exact Coulomb cone.", Choices{"elliptic", "pyramidal"});
    v("check_stability", check_stability, "",
      "Refuse a timestep above 0.9 x the stability limit of the stiffest explicit spring mode "
      "(see MaxStableTimestep). Turn off only to study the instability itself.");
    v("free_sliding_speed_mm_s", free_sliding_speed_mm_s, "mm/s",
      "With a friction post-pass (noslip_iterations > 0): contacts sliding faster than this lose their friction "
      "velocity target in MuJoCo's solve (faded out linearly, none at twice this speed), whose elliptic cone "
      "otherwise turns it into a normal force that grows "
      "with the sliding speed and makes a sliding object's contacts chatter (rail, gross slip: total normal force "
      "0.02-1.2 N, 1-31 pins in contact, against a steady 0.8-0.97 N and 19 pins without it). 30 mm/s: above "
      "the quasi-static partial slip of fingerprint skins (mm/s), below gross slip. 0 keeps MuJoCo's target "
      "everywhere (the behaviour of datasets written before this key).",
      Bounds::Closed(0.0, 1000.0));
    v("sliding_timestep_s", sliding_timestep_s, "s",
      "Rail scenarios: at most this step from the gross-slip onset on (the first step in which every contacting pin "
      "slides), when it is smaller than timestep_s; the step taken is the largest whole fraction of timestep_s at "
      "most this (timestep_s / k), so the camera's frames stay on the steps' grid. The release kicks the pins' "
      "normal modes as friction drops to kinetic; at 2 ms some sliding contacts then let go for a step (0.1 mm/s: 9 of 20 runs, down to 1 of 19 pins), "
      "at 1 ms none does. Everything before the onset is unchanged, and the sliding phase is short, so the cost is "
      "small. 0 keeps timestep_s throughout (the behaviour of datasets written before this key).",
      Bounds::Closed(0.0, 0.01));
  }
  /// The exact noslip pass needs elliptic cones.
  void ValidateRules() const {
    if (noslip == "exact" && cone != "elliptic") {
      FailRule("sim.cone", cone, "pyramidal cones need sim.noslip = mujoco (the exact noslip pass solves elliptic cones)");
    }
    if (sliding_timestep_s > 0.0 && sliding_timestep_s < kMinTimestepS) {
      FailRule("sim.sliding_timestep_s", sliding_timestep_s,
               "must be 0 (off) or at least 0.00001 s, the smallest sim.timestep_s");
    }
    if (sliding_timestep_s > 0.0 && SlidingTimestep() < kMinTimestepS) {
      FailRule("sim.sliding_timestep_s", sliding_timestep_s,
               "gives a sliding step (the largest sim.timestep_s / k within it) below 0.00001 s, the smallest "
               "sim.timestep_s; use 0 (off) or a value that divides sim.timestep_s");
    }
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
