#include "scenarios/rail/rail_scenario.h"

#include "scenarios/rail/rail_run.h"

namespace tactip {

RailScenario::RailScenario(const RailScenarioConfig& cfg) : RailScenario(cfg, SceneOptions{}) {}

RailScenario::RailScenario(const RailScenarioConfig& cfg, const SceneOptions& options) : cfg_(cfg) {
  ValidateConfig(cfg_);
  scene_ = std::make_unique<RailScene>(cfg_, options);
}

RailScenario::~RailScenario() = default;

const std::string& RailScenario::xml() const { return scene_->scene.built.xml; }
int RailScenario::n_pins() const { return scene_->scene.built.n_pins; }
int RailScenario::n_collidable() const { return scene_->scene.built.n_collidable; }

RailRunSummary RailScenario::Run(int index, std::uint64_t seed, RunRecord& rec, const std::atomic<bool>* stop) const {
  RailRun run(cfg_, *scene_, index, seed);
  return run.Execute(rec, stop);
}

RailRunSummary RailScenario::Run(int index, std::uint64_t seed, RunRecord& rec, const std::atomic<bool>* stop,
                                 const ControllerFactory& make) const {
  RailRun run(cfg_, *scene_, index, seed, make);
  return run.Execute(rec, stop);
}

RailRunSummary RailScenario::RunInstrumented(int index, std::uint64_t seed, RunRecord& rec,
                                             RunInstrumentation& out) const {
  RailRun run(cfg_, *scene_, index, seed);
  run.Instrument(&out);
  return run.Execute(rec, nullptr);
}

const CompiledModel& RailScenario::model() const { return *scene_->scene.model; }

}  // namespace tactip
