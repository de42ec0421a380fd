#pragma once
// A scene on which MuJoCo raises an internal error (not a warning) while stepping, for the
// tests that such an error reaches the caller as an exception.

#include <string>

#include "sim/simulation.h"

namespace tactip::testing {

/// A box dropped 2 cm onto a plane, with MuJoCo's solver stack `nstack` numbers deep:
/// 150 is enough to compile and to step in free flight, too small for the constraints of
/// the landing ("Stack overflow"); 100000 is ample.
inline std::string DroppedBoxXml(int nstack) {
  return "<mujoco><size nstack='" + std::to_string(nstack) +
         "'/><option timestep='0.002'/><worldbody><body pos='0 0 0.12'><freejoint/>"
         "<geom type='box' size='0.1 0.1 0.1'/></body><geom type='plane' size='1 1 0.1'/></worldbody></mujoco>";
}

/// Steps `model` for up to 1 s of simulated time; returns the time reached (a throw ends it early).
inline double StepOneSecond(const CompiledModel& model) {
  Simulation sim(model);
  while (sim.time() < 1.0) sim.Step();
  return sim.time();
}

}  // namespace tactip::testing
