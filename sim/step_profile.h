#pragma once
// Where the time of a physics step goes, and a bare mj_step replay to compare against.

#include <vector>

namespace tactip {

class CompiledModel;

/// Wall time spent in each stage of Simulation::Step, summed over steps (seconds).
/// MuJoCo's finer stages (collision, constraint making, projection, kinematics) come from
/// its own timers, which need EnableMujocoTimers().
struct StepProfile {
  long long steps = 0;
  double step1_s = 0.0;        ///< mj_step1: positions (kinematics, collision, constraints) and velocities
  double plane_s = 0.0;        ///< friction rows turned across the pressing axes (FrictionPlane)
  double forces_s = 0.0;       ///< actuation and smooth accelerations
  double solve_s = 0.0;        ///< MuJoCo's constraint solve (incl. its noslip pass when on)
  double friction_pass_s = 0.0;///< tactip's friction pass (sim.noslip = exact)
  double integrate_s = 0.0;    ///< sensors, acceleration check and Euler integration
  long long nefc_sum = 0, ncon_sum = 0;  ///< constraint rows and contacts, summed over steps
  long long solver_iter_sum = 0;         ///< MuJoCo solver iterations, summed over steps
  // From MuJoCo's timers (0 without EnableMujocoTimers):
  double kinematics_s = 0.0, inertia_s = 0.0, collision_s = 0.0, make_s = 0.0, project_s = 0.0;
  /// The whole of Step.
  double total_s() const { return step1_s + plane_s + forces_s + solve_s + friction_pass_s + integrate_s; }
};

/// Bytes of a compiled model plus one mjData for it (its buffer and stack).
long long SceneMemoryBytes(const CompiledModel& model);

/// Makes MuJoCo time its own stages (a process-wide callback; for speed studies only).
void EnableMujocoTimers();

/// A bare replay: its wall time and the simulated time it covered (s).
struct BareReplay {
  double wall_s = 0.0;
  double sim_s = 0.0;
};

/// Steps a fresh mjData of a copy of `model` with plain mj_step, setting the actuators'
/// controls from `ctrl` (nu values per step) and the step from `timestep_s` (one value per
/// step: a run that refines its step at the gross-slip onset replays the same steps) before
/// each step. This is MuJoCo alone on the same model: no friction plane, no friction pass,
/// nothing read out. Throws std::invalid_argument when the two do not hold the same steps.
BareReplay ReplayBareSteps(const CompiledModel& model, const std::vector<double>& ctrl,
                           const std::vector<double>& timestep_s);

}  // namespace tactip
