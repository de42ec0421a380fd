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

double ReplayBareSteps(const CompiledModel& model, const std::vector<double>& ctrl) {
  const mjModel* m = model.raw();
  std::unique_ptr<mjData, MjDataDeleter> d(mj_makeData(m));
  if (!d) throw ModelError("cannot allocate mjData");
  const int nu = m->nu;
  if (nu == 0 || ctrl.size() % static_cast<size_t>(nu) != 0) {
    throw std::invalid_argument("bare replay: the controls are not a whole number of steps of " + std::to_string(nu) +
                                " actuators");
  }
  const size_t steps = ctrl.size() / static_cast<size_t>(nu);
  mj_forward(m, d.get());
  const auto t0 = std::chrono::steady_clock::now();
  for (size_t n = 0; n < steps; ++n) {
    for (int u = 0; u < nu; ++u) d->ctrl[u] = ctrl[n * nu + u];
    mj_step(m, d.get());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace tactip
