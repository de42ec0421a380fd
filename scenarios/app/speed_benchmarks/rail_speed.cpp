// Speed of the rail scene (Google Benchmark). Run: build/release/tactip_benchmarks
// Reports the real-time factor (simulated seconds per wall second) on one core.

#include <benchmark/benchmark.h>

#include "scenarios/rail/rail.h"
#include "scenarios/studies/speed/speed.h"

namespace {

// One complete default rail run (press, lift, retract at 0.1 mm/s until the fall)
// with camera sampling, labels and contact read-out, on the calling thread.
void BM_RailRunDefault(benchmark::State& state) {
  const tactip::RailScenarioConfig cfg;
  const tactip::RailScenario scenario(cfg);
  double sim_s = 0.0;
  for (auto _ : state) {
    tactip::RunRecord rec;
    const auto s = scenario.Run(0, 1, rec);
    sim_s += s.sim_time_s;
    benchmark::DoNotOptimize(rec.time.data());
  }
  state.counters["sim_s_per_run"] = sim_s / static_cast<double>(state.iterations());
  state.counters["real_time_factor"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RailRunDefault)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

// The same run with a given timestep: the cost side of the accuracy/run-time curve.
void BM_RailRunTimestep(benchmark::State& state) {
  tactip::RailScenarioConfig cfg;
  cfg.sim.timestep_s = static_cast<double>(state.range(0)) * 1e-4;
  cfg.contact.timeconst_s = std::max(cfg.contact.timeconst_s, 2.0 * cfg.sim.timestep_s);
  const tactip::RailScenario scenario(cfg);
  double sim_s = 0.0;
  tactip::RailRunSummary s;
  for (auto _ : state) {
    tactip::RunRecord rec;
    s = scenario.Run(0, 1, rec);
    sim_s += s.sim_time_s;
  }
  state.counters["real_time_factor"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
  // Accuracy side: onset and its Coulomb prediction (compare across timesteps).
  state.counters["onset_s"] = s.gross_slip_onset_s;
  state.counters["onset_minus_coulomb_ms"] = 1e3 * (s.gross_slip_onset_s - s.predicted_onset_s);
  state.counters["creep_um"] = s.creep_um;
}
BENCHMARK(BM_RailRunTimestep)->Arg(5)->Arg(10)->Arg(20)->Arg(25)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// Each scene of `tactip bench --speed`: its real-time factor, the physics steps alone, bare
// mj_step on the same model with the same controls, and the stage costs, all from one run.
void BM_SpeedScene(benchmark::State& state, const std::string& scene) {
  tactip::SpeedRow row;
  for (auto _ : state) row = tactip::MeasureSpeed({scene}, {}, 1).front();
  const tactip::StepProfile& p = row.profile;
  const double per_step = 1e6 / static_cast<double>(std::max<long long>(p.steps, 1));
  state.counters["rtf_run"] = row.rtf_run();
  state.counters["rtf_physics"] = row.rtf_physics();
  state.counters["rtf_bare_mj_step"] = row.rtf_bare();
  state.counters["overhead"] = row.overhead();
  state.counters["run_over_bare"] = row.run_wall_s / row.bare_wall_s;
  state.counters["us_collision"] = p.collision_s * per_step;
  state.counters["us_solve"] = p.solve_s * per_step;
  state.counters["us_friction_pass"] = p.friction_pass_s * per_step;
  state.counters["us_step"] = p.total_s() * per_step;
  state.counters["nefc"] = row.nefc_mean();
}

}  // namespace

int main(int argc, char** argv) {
  for (const auto& scene : tactip::SpeedScenes()) {
    benchmark::RegisterBenchmark(("BM_SpeedScene/" + scene.name).c_str(), BM_SpeedScene, scene.name)
        ->Unit(benchmark::kSecond)
        ->Iterations(1)
        ->UseRealTime();
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
