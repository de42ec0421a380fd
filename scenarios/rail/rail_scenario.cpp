#include "scenarios/rail/rail_scenario.h"

#include "scenarios/rail/rail_run.h"

namespace tactip {

RailScenario::RailScenario(const RailScenarioConfig& cfg) : RailScenario(cfg, SceneOptions{}) {}

RailScenario::RailScenario(const RailScenarioConfig& cfg, const SceneOptions& options) : cfg_(cfg) {
  ValidateConfig(cfg_);
  ids_ = std::make_unique<RailSceneIds>(cfg_, options);
}

RailScenario::~RailScenario() = default;

const std::string& RailScenario::xml() const { return ids_->scene.xml; }
int RailScenario::n_pins() const { return ids_->scene.n_pins; }
int RailScenario::n_collidable() const { return ids_->scene.n_collidable; }

RailRunSummary RailScenario::Run(int index, std::uint64_t seed, RunRecord& rec, const std::atomic<bool>* stop) const {
  RailRun run(cfg_, *ids_, index, seed);
  return run.Execute(rec, stop);
}

RailRunSummary RailScenario::Run(int index, std::uint64_t seed, RunRecord& rec, const std::atomic<bool>* stop,
                                 const ControllerFactory& make) const {
  RailRun run(cfg_, *ids_, index, seed);
  std::unique_ptr<RailController> controller;
  if (make) {
    controller = make(index, run.schedule());
    run.SetController(controller.get());
  }
  return run.Execute(rec, stop);
}

RailRunSummary RailScenario::RunInstrumented(int index, std::uint64_t seed, RunRecord& rec,
                                             RunInstrumentation& out) const {
  RailRun run(cfg_, *ids_, index, seed);
  run.Instrument(&out);
  return run.Execute(rec, nullptr);
}

const CompiledModel& RailScenario::model() const { return *ids_->model; }

}  // namespace tactip
