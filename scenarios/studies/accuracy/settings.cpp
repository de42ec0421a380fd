#include "scenarios/studies/accuracy/settings.h"

#include <fmt/format.h>

#include "sim/config.h"

namespace tactip {

namespace {

std::string StepLabel(double step_s) { return fmt::format("dt={:g}ms", 1e3 * step_s); }

std::string StepOverride(double step_s) { return fmt::format("sim.timestep_s={:g}", step_s); }

// A timestep setting; MuJoCo needs the contact time constant to be at least two steps, so a
// longer step lengthens it to that.
AccuracySetting StepSetting(double step_s, double timeconst_s) {
  AccuracySetting s{StepLabel(step_s), {StepOverride(step_s)}, false, false};
  if (timeconst_s < 2.0 * step_s) s.overrides.push_back(fmt::format("contact.timeconst_s={:g}", 2.0 * step_s));
  return s;
}

}  // namespace

std::vector<AccuracySetting> RailAccuracySettings(double default_step_s, double timeconst_s) {
  // The reference: a quarter of the scene's default step, converged solver and friction pass.
  const std::vector<std::string> fine = {StepOverride(default_step_s / 4.0), "sim.iterations=100",
                                         "sim.tolerance=1e-12", "sim.noslip_iterations=30"};
  return {
      {"reference", fine, true, false},
      {"default", {}, false, true},
      StepSetting(default_step_s / 2.0, timeconst_s),
      StepSetting(0.75 * default_step_s, timeconst_s),
      StepSetting(1.25 * default_step_s, timeconst_s),
      {"iterations=20", {"sim.iterations=20"}, false, false},
      {"tolerance=1e-6", {"sim.tolerance=1e-6"}, false, false},
      {"noslip rounds=1", {"sim.noslip_iterations=1"}, false, false},
      {"noslip=mujoco", {"sim.noslip=mujoco"}, false, false},
      {"noslip=mujoco x50", {"sim.noslip=mujoco", "sim.noslip_iterations=50"}, false, false},
      {"pyramidal", {"sim.cone=pyramidal", "sim.noslip=mujoco"}, false, false},
      {"impratio=1", {"sim.impratio=1"}, false, false},
      {"impratio=100", {"sim.impratio=100"}, false, false},
      {"timeconst=8ms", {"contact.timeconst_s=0.008"}, false, false},
      {"impedance=0.95", {"contact.impedance=0.95"}, false, false},
      {"impedance_min=0.8", {"contact.impedance_min=0.8"}, false, false},
      {"presliding=5um", {"contact.presliding_mm=0.005"}, false, false},
      {"presliding=20um", {"contact.presliding_mm=0.02"}, false, false},
  };
}

std::vector<AccuracySetting> DomeAccuracySettings() {
  // The dome check runs at 1 ms; its reference is a quarter of that.
  const std::vector<std::string> fine = {"sim.timestep_s=0.00025", "sim.iterations=100", "sim.tolerance=1e-12",
                                         "sim.noslip_iterations=30"};
  return {
      {"reference", fine, true, false},
      {"default (dt=1ms)", {}, false, true},
      {"dt=0.5ms", {"sim.timestep_s=0.0005"}, false, false},
      {"dt=2ms", {"sim.timestep_s=0.002"}, false, false},
      {"iterations=20", {"sim.iterations=20"}, false, false},
      {"noslip=mujoco", {"sim.noslip=mujoco"}, false, false},
      {"impratio=1", {"sim.impratio=1"}, false, false},
      {"timeconst=8ms", {"contact.timeconst_s=0.008"}, false, false},
      {"presliding=20um", {"contact.presliding_mm=0.02"}, false, false},
  };
}

const AccuracySetting& FindSetting(const std::vector<AccuracySetting>& settings, const std::string& label) {
  std::string known;
  for (const auto& s : settings) {
    if (s.label == label) return s;
    known += (known.empty() ? "" : ", ") + s.label;
  }
  throw InputError("unknown accuracy setting '" + label + "' (known: " + known + ")");
}

}  // namespace tactip
