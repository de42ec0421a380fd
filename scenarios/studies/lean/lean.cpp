#include "scenarios/studies/lean/lean.h"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "scenarios/rail/rail.h"

namespace tactip {

namespace {

bool IsLean(const SceneOptions& o) {
  return !o.all_pins_collide && !o.visual_geoms && !o.outer_sites && !o.object_free_joint;
}

double PerStepUs(double seconds, long long steps) { return steps > 0 ? 1e6 * seconds / static_cast<double>(steps) : 0.0; }

// The lean variant of `row`'s scene (the ratios' reference), or null.
const LeanRow* LeanOf(const std::vector<LeanRow>& rows, const LeanRow& row) {
  for (const auto& r : rows) {
    if (r.speed.scene.name == row.speed.scene.name && IsLean(r.variant.options)) return &r;
  }
  return nullptr;
}

double Ratio(double value, double lean) { return lean > 0.0 ? value / lean : 0.0; }

double PhysicsPerStep(const SpeedRow& r) { return r.profile.total_s() / static_cast<double>(std::max(r.profile.steps, 1LL)); }

// Every variant of one scene, `repeats` rounds over all variants (so a machine whose speed
// drifts slows them alike); each variant keeps its run with the fastest physics and its
// fastest bare replay.
std::vector<LeanRow> MeasureScene(const SpeedScene& scene, const LeanOptions& o) {
  const RailScenarioConfig cfg = LoadSpeedScene(scene, o.overrides);
  const std::vector<LeanVariant> variants = LeanVariants();
  std::vector<std::unique_ptr<RailScenario>> scenarios;
  std::vector<LeanRow> rows(variants.size());
  for (size_t v = 0; v < variants.size(); ++v) {
    scenarios.push_back(std::make_unique<RailScenario>(cfg, variants[v].options));
    rows[v].variant = variants[v];
    rows[v].counts = CountModel(scenarios[v]->model());
  }
  const int repeats = std::max(1, o.repeats);
  for (int k = 0; k < repeats; ++k) {
    for (size_t v = 0; v < variants.size(); ++v) {
      if (o.stop && o.stop->load()) throw Interrupted();
      SpeedRow run = MeasureRailRun(scene, *scenarios[v], o.seed);
      if (o.progress) {
        o.progress(fmt::format("{}, {} (round {}/{}): {:.1f} s simulated in {:.2f} s, {:.1f} us per physics step",
                               scene.name, variants[v].name, k + 1, repeats, run.sim_s, run.run_wall_s,
                               1e6 * PhysicsPerStep(run)));
      }
      const double bare_s = k == 0 ? run.bare_wall_s : std::min(run.bare_wall_s, rows[v].speed.bare_wall_s);
      if (k == 0 || PhysicsPerStep(run) < PhysicsPerStep(rows[v].speed)) rows[v].speed = std::move(run);
      rows[v].speed.bare_wall_s = bare_s;  // the fastest bare replay too (every round replays the same steps)
    }
  }
  return rows;
}

}  // namespace

double LeanRow::physics_us() const { return PerStepUs(speed.profile.total_s(), speed.profile.steps); }
double LeanRow::bare_us() const { return PerStepUs(speed.bare_wall_s, speed.profile.steps); }

std::vector<LeanVariant> LeanVariants() {
  std::vector<LeanVariant> v(6);
  v[0].name = "lean";
  v[1].name = "+ all pins collide";
  v[1].options.all_pins_collide = true;
  v[2].name = "+ visual geoms";
  v[2].options.visual_geoms = true;
  v[3].name = "+ outer sites";
  v[3].options.outer_sites = true;
  v[4].name = "+ free object *";
  v[4].options.object_free_joint = true;
  v[4].protocol = false;
  v[5].name = "+ all, rail kept";
  v[5].options = v[1].options;
  v[5].options.visual_geoms = v[5].options.outer_sites = true;
  return v;
}

std::vector<SpeedScene> ChooseLeanScenes(const std::vector<std::string>& names) {
  return ChooseSpeedScenes(names.empty() ? std::vector<std::string>{"rail flat", "rail curved40"} : names);
}

std::vector<LeanRow> MeasureLean(const std::vector<SpeedScene>& scenes, const LeanOptions& o) {
  EnableMujocoTimers();
  std::vector<LeanRow> rows;
  for (const auto& scene : scenes) {
    for (auto& row : MeasureScene(scene, o)) rows.push_back(std::move(row));
  }
  return rows;
}

std::string FormatLeanTable(const std::vector<LeanRow>& rows) {
  std::string out;
  std::string scene;
  for (const auto& r : rows) {
    if (r.speed.scene.name != scene) {
      scene = r.speed.scene.name;
      out += fmt::format("{}{}\n{:<18} {:>4} {:>5} {:>5} {:>8} {:>6} {:>6} {:>7} {:>8} {:>6} {:>6} {:>5} {:>9} {:>6}\n",
                         out.empty() ? "" : "\n", scene, "variant", "nv", "geoms", "sites", "us/step", "x lean",
                         "kinem", "collide", "bare us", "x lean", "nefc", "ncon", "memory B", "x lean");
    }
    const LeanRow* lean = LeanOf(rows, r);
    const double p0 = lean ? lean->physics_us() : 0.0, b0 = lean ? lean->bare_us() : 0.0;
    const double m0 = lean ? static_cast<double>(lean->speed.memory_bytes) : 0.0;
    const StepProfile& p = r.speed.profile;
    out += fmt::format(
        "{:<18} {:>4} {:>5} {:>5} {:>8.1f} {:>6.3f} {:>6.1f} {:>7.1f} {:>8.1f} {:>6.3f} {:>6.1f} {:>5.1f} {:>9} {:>6.3f}\n",
        r.variant.name, r.counts.nv, r.counts.ngeom, r.counts.nsite, r.physics_us(), Ratio(r.physics_us(), p0),
        PerStepUs(p.kinematics_s, p.steps), PerStepUs(p.collision_s, p.steps), r.bare_us(), Ratio(r.bare_us(), b0),
        r.speed.nefc_mean(), r.speed.ncon_mean(), r.speed.memory_bytes,
        Ratio(static_cast<double>(r.speed.memory_bytes), m0));
  }
  out += "(us/step: wall time of a whole physics step, one core, of which MuJoCo's kinematics and collision; bare: "
         "the same controls with plain mj_step on the variant's model; nefc, ncon: means per step; memory: model + "
         "one mjData. * not the rail protocol: a free "
         "object has no rail, so it is held by heavy damping and the skin slides over it in the lift, which ends the "
         "run early; compare its cost per step only.)\n";
  return out;
}

std::string LeanCsv(const std::vector<LeanRow>& rows) {
  std::string out =
      "scene,variant,rail_protocol,nv,ngeom,ngeom_collidable,nsite,nconmax,njmax,steps,sim_s,physics_us_per_step,"
      "physics_ratio,bare_us_per_step,bare_ratio,nefc_mean,ncon_mean,solver_iter_mean,memory_bytes,memory_ratio,"
      "kinematics_us,collision_us,make_us,project_us,solve_us,friction_pass_us\n";
  for (const auto& r : rows) {
    const LeanRow* lean = LeanOf(rows, r);
    const StepProfile& p = r.speed.profile;
    const long long n = p.steps;
    out += fmt::format(
        "\"{}\",\"{}\",{},{},{},{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{},{:.6g},{:.6g},"
        "{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n",
        r.speed.scene.name, r.variant.name, r.variant.protocol ? 1 : 0, r.counts.nv, r.counts.ngeom,
        r.counts.ngeom_collidable, r.counts.nsite, r.counts.nconmax, r.counts.njmax, n, r.speed.sim_s, r.physics_us(),
        Ratio(r.physics_us(), lean ? lean->physics_us() : 0.0), r.bare_us(),
        Ratio(r.bare_us(), lean ? lean->bare_us() : 0.0), r.speed.nefc_mean(), r.speed.ncon_mean(),
        r.speed.solver_iter_mean(), r.speed.memory_bytes,
        Ratio(static_cast<double>(r.speed.memory_bytes), lean ? static_cast<double>(lean->speed.memory_bytes) : 0.0),
        PerStepUs(p.kinematics_s, n), PerStepUs(p.collision_s, n), PerStepUs(p.make_s, n), PerStepUs(p.project_s, n),
        PerStepUs(p.solve_s, n), PerStepUs(p.friction_pass_s, n));
  }
  return out;
}

}  // namespace tactip
