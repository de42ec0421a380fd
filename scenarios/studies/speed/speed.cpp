#include "scenarios/studies/speed/speed.h"

#include <fmt/format.h>

#include "scenarios/registry.h"

namespace tactip {

std::vector<SpeedScene> SpeedScenes() {
  return {
      {"rail flat", "rail", {"rail.stimulus=flat"}},
      {"rail curved80", "rail", {"rail.stimulus=curved80"}},
      {"rail curved40", "rail", {"rail.stimulus=curved40"}},
      {"rail curved20", "rail", {"rail.stimulus=curved20"}},
      {"incipient v2", "incipient", {}},
      {"rail flat, mujoco noslip", "rail", {"rail.stimulus=flat", "sim.noslip=mujoco"}},
  };
}

double SpeedRow::nefc_mean() const {
  return profile.steps > 0 ? static_cast<double>(profile.nefc_sum) / static_cast<double>(profile.steps) : 0.0;
}
double SpeedRow::ncon_mean() const {
  return profile.steps > 0 ? static_cast<double>(profile.ncon_sum) / static_cast<double>(profile.steps) : 0.0;
}

namespace {

SpeedRow MeasureScene(const SpeedScene& scene, const std::vector<std::string>& overrides, std::uint64_t seed) {
  const RailScenario scenario(LoadSpeedScene(scene, overrides));
  return MeasureRailRun(scene, scenario, seed);
}

}  // namespace

RailScenarioConfig LoadSpeedScene(const SpeedScene& scene, const std::vector<std::string>& overrides) {
  ConfigSource src;
  src.overrides = scene.overrides;
  src.overrides.insert(src.overrides.end(), overrides.begin(), overrides.end());
  return RailFamily(FindScenario(scene.scenario)).Load(src);
}

SpeedRow MeasureRailRun(const SpeedScene& scene, const RailScenario& scenario, std::uint64_t seed) {
  RunRecord rec;
  RunInstrumentation inst;
  const RailRunSummary s = scenario.RunInstrumented(0, seed, rec, inst);
  SpeedRow row;
  row.scene = scene;
  row.sim_s = s.sim_time_s;
  row.run_wall_s = s.wall_time_s;
  row.profile = inst.profile;
  row.bare_wall_s = ReplayBareSteps(scenario.model(), inst.ctrl, inst.timestep_s).wall_s;
  row.nv = scenario.model().nv();
  row.memory_bytes = SceneMemoryBytes(scenario.model());
  return row;
}

std::vector<SpeedScene> ChooseSpeedScenes(const std::vector<std::string>& names) {
  const std::vector<SpeedScene> all = SpeedScenes();
  if (names.empty()) return all;
  std::vector<SpeedScene> chosen;
  for (const auto& n : names) {
    auto it = std::find_if(all.begin(), all.end(), [&](const SpeedScene& s) { return s.name == n; });
    if (it == all.end()) {
      std::string known;
      for (const auto& s : all) known += (known.empty() ? "" : ", ") + s.name;
      throw InputError("unknown speed scene '" + n + "' (known: " + known + ")");
    }
    chosen.push_back(*it);
  }
  return chosen;
}

std::vector<SpeedRow> MeasureSpeed(const std::vector<std::string>& names, const std::vector<std::string>& overrides,
                                   std::uint64_t seed) {
  const std::vector<SpeedScene> chosen = ChooseSpeedScenes(names);
  EnableMujocoTimers();
  std::vector<SpeedRow> rows;
  for (const auto& scene : chosen) rows.push_back(MeasureScene(scene, overrides, seed));
  return rows;
}

double SpeedRow::solver_iter_mean() const {
  return profile.steps > 0 ? static_cast<double>(profile.solver_iter_sum) / static_cast<double>(profile.steps) : 0.0;
}

std::string FormatSpeedTable(const std::vector<SpeedRow>& rows) {
  std::string out = fmt::format("{:<26} {:>7} {:>7} {:>7} {:>9} {:>5} {:>6} {:>5} {:>6} {:>8}\n", "scene", "RTF run",
                                "physics", "bare", "overhead", "nv", "nefc", "ncon", "iters", "memory");
  for (const auto& r : rows) {
    out += fmt::format("{:<26} {:>6.1f}x {:>6.1f}x {:>6.1f}x {:>8.1f}% {:>5} {:>6.0f} {:>5.0f} {:>6.1f} {:>6.1f}MB\n",
                       r.scene.name, r.rtf_run(), r.rtf_physics(), r.rtf_bare(), 100.0 * r.overhead(), r.nv,
                       r.nefc_mean(), r.ncon_mean(), r.solver_iter_mean(), r.memory_bytes / 1e6);
  }
  out += "\ncost split, us per step (one core):\n";
  out += fmt::format("{:<26} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}\n", "scene", "kinemat",
                     "collide", "make", "project", "step1", "plane", "forces", "solve", "fpass", "integr", "ours");
  for (const auto& r : rows) {
    const double n = static_cast<double>(std::max<long long>(r.profile.steps, 1));
    const StepProfile& p = r.profile;
    const double ours = (r.run_wall_s - p.total_s()) / n;
    out += fmt::format("{:<26} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f} {:>7.1f}\n",
                       r.scene.name, 1e6 * p.kinematics_s / n, 1e6 * p.collision_s / n, 1e6 * p.make_s / n,
                       1e6 * p.project_s / n, 1e6 * p.step1_s / n, 1e6 * p.plane_s / n, 1e6 * p.forces_s / n,
                       1e6 * p.solve_s / n, 1e6 * p.friction_pass_s / n, 1e6 * p.integrate_s / n, 1e6 * ours);
  }
  out += "(RTF: simulated seconds per wall second. run: the whole scenario; physics: its steps alone; bare: the same "
         "controls and steps (the sliding step from the onset) with plain mj_step on the exported model, which has no "
         "friction plane or pass. overhead: the "
         "scenario's own per-step work (contact read-out, labels, friction switching, camera, health, recording) "
         "over its physics steps. step1 includes kinematics, collision, making and projecting the constraints.)\n";
  return out;
}

std::string SpeedCsv(const std::vector<SpeedRow>& rows) {
  std::string out =
      "scene,sim_s,run_wall_s,physics_wall_s,bare_wall_s,rtf_run,rtf_physics,rtf_bare,overhead,nv,nefc_mean,ncon_mean,"
      "solver_iter_mean,memory_bytes,steps,kinematics_s,collision_s,make_s,project_s,step1_s,plane_s,forces_s,solve_s,"
      "friction_pass_s,integrate_s\n";
  for (const auto& r : rows) {
    const StepProfile& p = r.profile;
    out += fmt::format("\"{}\",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{:.6g},{:.6g},{:.4g},{},{},{:.6g},{:.6g},"
                       "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n",
                       r.scene.name, r.sim_s, r.run_wall_s, p.total_s(), r.bare_wall_s, r.rtf_run(), r.rtf_physics(),
                       r.rtf_bare(), r.overhead(), r.nv, r.nefc_mean(), r.ncon_mean(), r.solver_iter_mean(), r.memory_bytes, p.steps,
                       p.kinematics_s, p.collision_s, p.make_s, p.project_s, p.step1_s, p.plane_s, p.forces_s,
                       p.solve_s, p.friction_pass_s, p.integrate_s);
  }
  return out;
}

}  // namespace tactip
