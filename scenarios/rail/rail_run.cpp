#include "scenarios/rail/rail_run.h"

#include <utility>

#include "sensors/marker_labels.h"
#include "sim/base/random.h"

namespace tactip {

namespace {

constexpr double kGravity = 9.81;  // m/s^2, the rail scene's
// The marker camera's random stream: its own, so the tactile noise does not depend on it.
constexpr std::uint64_t kMarkerStream = 0x6D61726B65724F6EULL;

// A TacTip's cameras, noise and labelling, its ridge-rocking marker shift and its gel field.
TactileSensorSpec SensorSpec(const RailScenarioConfig& cfg, const std::string& name) {
  TactileSensorSpec spec;
  spec.name = name;
  spec.camera = cfg.sensor;
  spec.external = cfg.external;
  spec.labels = cfg.labels;
  const PinLattice lattice = PinLattice::Build(cfg.skin);
  const SkinMechanics mech = SkinMechanics::From(cfg.skin, lattice);
  spec.gel_field = GelField::Build(cfg.skin, lattice);
  if (cfg.skin.coupling == "membrane" && mech.k_rock_N_m > 0.0) {
    spec.marker_rock_m_N = mech.marker_rock_factor / mech.k_rock_N_m;
  }
  spec.apex_x_m = cfg.skin.OuterRadiusMm() * 1e-3;
  return spec;
}

// The scene of `cfg`: its parts' MJCF and a spec and skin per sensor.
Scene CompileRailScene(const RailScenarioConfig& cfg, const SceneOptions& options) {
  RailSceneSpec spec = cfg.SceneSpec();
  spec.options = options;
  std::vector<TactileSensorSpec> specs;
  std::vector<SkinConfig> skins;
  for (const SensorMountConfig& mount : cfg.sensors) {
    specs.push_back(SensorSpec(cfg, mount.name));
    skins.push_back(cfg.skin);
  }
  return Scene::Compile(BuildRailScene(spec), std::move(specs), skins);
}

// The protocol's phases for the scene run: the load is the lift, the hold follows it, the
// release is the retraction.
ProtocolTimeline Timeline(const RailScenarioConfig& cfg, const RailSchedule& sched, const RailController& controller) {
  ProtocolTimeline t;
  t.load_s = sched.lift_start;
  t.held_s = sched.lift_end;
  t.release_s = sched.retract_start;
  t.give_up_s = controller.GiveUpTime(sched);
  t.after_loss_s = cfg.rail.post_fall_s;
  return t;
}

}  // namespace

StateLimits RailStateLimits(const RailScenarioConfig& cfg, int n_collidable, double extra_press_m) {
  return StateLimits::For(cfg.skin, cfg.rail.press_depth_mm + cfg.rail.press_depth_jitter_mm,
                          cfg.object.mass_kg * kGravity + cfg.rail.friction_N, n_collidable, extra_press_m);
}

RailScene::RailScene(const RailScenarioConfig& cfg, const SceneOptions& options)
    : scene(CompileRailScene(cfg, options)) {}

RailRun::Draws RailRun::Draw(const RailScenarioConfig& c, std::uint64_t run_seed) {
  // Always draw both numbers so each stays on its own stream.
  Rng vary(DeriveSeed(run_seed, 0));
  Draws d;
  d.run_seed = run_seed;
  d.depth_m = (c.rail.press_depth_mm + vary.Uniform(-1.0, 1.0) * c.rail.press_depth_jitter_mm) * 1e-3;
  d.mu = c.contact.friction * (1.0 + vary.Uniform(-1.0, 1.0) * c.contact.friction_jitter);
  // The retraction speed on a stream of its own (runs of one fixed speed draw nothing).
  d.retract_speed_mm_s = c.rail.retract_speed_mm_s;
  if (c.rail.retract_speed_max_mm_s > c.rail.retract_speed_mm_s) {
    Rng speed(DeriveSeed(run_seed, 1));
    d.retract_speed_mm_s = speed.Uniform(c.rail.retract_speed_mm_s, c.rail.retract_speed_max_mm_s);
  }
  return d;
}

RailRun::RailRun(const RailScenarioConfig& cfg, const RailScene& scene, int index, std::uint64_t seed,
                 const ControllerFactory& make)
    : RailRun(cfg, scene, index, Draw(cfg, DeriveSeed(seed, static_cast<std::uint64_t>(index))), make, nullptr) {}

RailRun::RailRun(const RailScenarioConfig& cfg, const RailScene& scene, int index, std::uint64_t seed,
                 RailController& controller)
    : RailRun(cfg, scene, index, Draw(cfg, DeriveSeed(seed, static_cast<std::uint64_t>(index))), {}, &controller) {}

RailRun::RailRun(const RailScenarioConfig& cfg, const RailScene& scene, int index, const Draws& d,
                 const ControllerFactory& make, RailController* controller)
    : c_(cfg), draws_(d), sched_(cfg.rail, d.depth_m, d.retract_speed_mm_s), schedule_controller_(sched_), controller_(controller) {
  // The controller: the caller's, the factory's for this run, or the offline schedule.
  if (controller_ == nullptr && make) {
    owned_ = make(index, sched_);
    controller_ = owned_.get();
  }
  if (controller_ == nullptr) controller_ = &schedule_controller_;
  Start(scene, index);
}

void RailRun::Start(const RailScene& scene, int index) {
  // The step loop's settings; a physically possible state allows for a controller that
  // presses deeper than the protocol.
  const RailScenarioConfig& c = c_;
  settings_.sim = c.sim;
  settings_.contact = c.contact;
  settings_.labels = c.labels;
  settings_.health = c.health;
  settings_.images = c.images;
  settings_.limits = RailStateLimits(c, scene.scene.built.n_collidable, controller_->ExtraPressM());
  run_ = std::make_unique<SceneRun>(scene.scene, settings_, Timeline(c, sched_, *controller_),
                                    RunDraws{index, draws_.run_seed, draws_.mu}, *controller_);
}

RailRunSummary RailRun::Execute(RunRecord& rec, const std::atomic<bool>* stop) {
  for (;;) {
    if (stop && stop->load(std::memory_order_relaxed)) throw Interrupted();
    if (!Step(rec)) break;
  }
  return Finish(rec);
}

RailRunSummary RailRun::Finish(RunRecord& rec) {
  // The scene run's events, and the protocol's own figures beside them.
  RailRunSummary s;
  static_cast<SceneRunSummary&>(s) = run_->Finish(rec);
  s.press_depth_mm = draws_.depth_m * 1e3;
  s.friction = draws_.mu;
  s.retract_start_s = sched_.retract_start;
  rec.attrs["retract_speed_mm_s"] = draws_.retract_speed_mm_s;
  rec.attrs["press_depth_mm"] = s.press_depth_mm;
  rec.attrs["retract_start_s"] = s.retract_start_s;
  // The hardware-style onset: a marker on the object tracked from the end of the hold.
  rec.attrs["marker_onset_s"] =
      MarkerOnset(rec.time, rec.object_height_m, HoldSpan{sched_.lift_end, sched_.retract_start}, c_.marker_camera,
                  draws_.run_seed ^ kMarkerStream);
  rec.attrs["rail_friction_N"] = c_.rail.friction_N;
  rec.text_attrs["stimulus"] = c_.rail.stimulus;
  return s;
}

}  // namespace tactip
