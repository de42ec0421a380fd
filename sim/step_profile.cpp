#include "sim/step_profile.h"

#include <mujoco/mujoco.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <memory>

#include "sim/simulation.h"

namespace tactip {

namespace {
// MuJoCo's timer callback: microseconds on a steady clock.
mjtNum MicrosecondsNow() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::micro>(Clock::now().time_since_epoch()).count();
}
}  // namespace

void EnableMujocoTimers() { mjcb_time = MicrosecondsNow; }

long long SceneMemoryBytes(const CompiledModel& model) {
  const mjModel* m = model.raw();
  std::unique_ptr<mjData, MjDataDeleter> d(mj_makeData(m));
  if (!d) throw ModelError("cannot allocate mjData");
  return static_cast<long long>(mj_sizeModel(m)) + d->nbuffer + static_cast<long long>(sizeof(mjtNum)) * d->nstack;
}

BareReplay ReplayBareSteps(const CompiledModel& model, const std::vector<double>& ctrl,
                           const std::vector<double>& timestep_s) {
  const int nu = model.raw()->nu;
  if (nu == 0 || ctrl.size() % static_cast<size_t>(nu) != 0) {
    throw std::invalid_argument("bare replay: the controls are not a whole number of steps of " + std::to_string(nu) +
                                " actuators");
  }
  const size_t steps = ctrl.size() / static_cast<size_t>(nu);
  if (timestep_s.size() != steps) {
    throw std::invalid_argument("bare replay: " + std::to_string(timestep_s.size()) + " timesteps for " +
                                std::to_string(steps) + " steps of controls");
  }
  // A copy, so that the step can change without touching the shared model.
  CompiledModel copy = model.Copy();
  const mjModel* m = copy.raw();
  std::unique_ptr<mjData, MjDataDeleter> d(mj_makeData(m));
  if (!d) throw ModelError("cannot allocate mjData");
  mj_forward(m, d.get());
  const double t0_sim = d->time;
  const auto t0 = std::chrono::steady_clock::now();
  for (size_t n = 0; n < steps; ++n) {
    for (int u = 0; u < nu; ++u) d->ctrl[u] = ctrl[n * nu + u];
    if (timestep_s[n] != m->opt.timestep) copy.SetTimestep(timestep_s[n]);
    mj_step(m, d.get());
  }
  BareReplay replay;
  replay.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  replay.sim_s = d->time - t0_sim;
  return replay;
}

}  // namespace tactip
