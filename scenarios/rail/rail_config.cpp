#include "scenarios/rail/rail_config.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "models/scene_size.h"
#include "models/stability.h"

namespace tactip {

namespace {

using config_detail::FormatAtLeast;
using config_detail::FormatAtMost;

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;

// The press: no deeper than a TacTip tolerates, and towards the stimulus (a negative depth
// stops short of it: an empty contact); the retraction must end within an hour.
void CheckPress(const RailConfig& rail) {
  const double deepest_mm = rail.press_depth_mm + rail.press_depth_jitter_mm;
  if (deepest_mm > RailConfig::kMaxPressDepthMm) {
    FailRule("rail.press_depth_jitter_mm", rail.press_depth_jitter_mm,
             fmt::format("the deepest press, rail.press_depth_mm + rail.press_depth_jitter_mm = {} + {} = {:.3g} mm, "
                         "is beyond the {:.3g} mm a TacTip tolerates; use rail.press_depth_jitter_mm <= {}",
                         rail.press_depth_mm, rail.press_depth_jitter_mm, deepest_mm, RailConfig::kMaxPressDepthMm,
                         FormatAtMost(RailConfig::kMaxPressDepthMm - rail.press_depth_mm)));
  }
  const double travel_mm = rail.approach_gap_mm + rail.press_depth_mm - rail.press_depth_jitter_mm;
  if (travel_mm <= 0.0) {
    FailRule("rail.press_depth_mm", rail.press_depth_mm,
             fmt::format("the press would not move the sensor towards the stimulus (rail.approach_gap_mm + "
                         "press_depth_mm - press_depth_jitter_mm = {:.3g} mm); use rail.press_depth_mm > {}",
                         travel_mm, FormatAtLeast(rail.press_depth_jitter_mm - rail.approach_gap_mm)));
  }
  constexpr double kMaxRetractS = 3600.0;
  const double retract_mm = rail.approach_gap_mm + rail.press_depth_mm + rail.press_depth_jitter_mm + 5.0;
  if (retract_mm / rail.retract_speed_mm_s > kMaxRetractS) {
    FailRule("rail.retract_speed_mm_s", rail.retract_speed_mm_s,
             fmt::format("the retraction would take {:g} s of simulated time (limit {:g} s); use >= {}",
                         retract_mm / rail.retract_speed_mm_s, kMaxRetractS, FormatAtLeast(retract_mm / kMaxRetractS)));
  }
}

// The sensors: valid, distinct names; housings that do not overlap.
void CheckSensors(const RailScenarioConfig& c) {
  const double housing_mm = 2.0 * (c.skin.OuterRadiusMm() + 3.0);
  for (size_t k = 0; k < c.sensors.size(); ++k) {
    const SensorMountConfig& s = c.sensors[k];
    s.ValidateRules(k);
    for (size_t j = 0; j < k; ++j) {
      if (c.sensors[j].name == s.name) {
        FailRule(fmt::format("sensors.{}.name", k), s.name, fmt::format("sensors.{}.name is the same; each sensor "
                                                                        "needs its own name", j));
      }
      const double apart_mm = std::abs(s.offset_y_mm - c.sensors[j].offset_y_mm);
      if (apart_mm < housing_mm) {
        FailRule(fmt::format("sensors.{}.offset_y_mm", k), s.offset_y_mm,
                 fmt::format("{:.3g} mm from sensors.{} ('{}'): their housings ({:.3g} mm across) overlap; place the "
                             "sensors at least {:.3g} mm apart",
                             apart_mm, j, c.sensors[j].name, housing_mm, housing_mm));
      }
    }
  }
}

// The scene must fit in the solver memory MuJoCo reserves per run; names the skin's pin
// count key and the largest value that fits (or the ring spacing that does).
void CheckSceneSize(const RailScenarioConfig& c) {
  const SceneSize size = EstimateRailScene(c.SceneSpec());
  if (size.Fits()) return;
  const bool fingerprint = c.skin.Fingerprint();
  const std::string key = fingerprint ? "skin.pins_per_ring" : "skin.rings";
  const int current = fingerprint ? c.skin.pins_per_ring : c.skin.rings;
  const std::string skins = c.sensors.size() == 1 ? "the skin has" : fmt::format("the {} skins have", c.sensors.size());
  const std::string what = fmt::format(
      "{} {} pins ({} can touch the stimulus), for which MuJoCo would reserve {:.3g} GiB of solver stack per run "
      "(limit {:.3g} GiB)",
      skins, size.n_pins, size.n_collidable, size.stack_bytes / kGiB, kMaxSolverStackBytes / kGiB);
  RailScenarioConfig trial = c;
  for (int v = current - 1; v >= 1; --v) {
    (fingerprint ? trial.skin.pins_per_ring : trial.skin.rings) = v;
    if (EstimateRailScene(trial.SceneSpec()).Fits()) {
      FailRule(key, current, fmt::format("{}; use {} <= {}", what, key, v));
    }
  }
  // A fingerprint skin too large even at one pin per ring: wider rings.
  trial = c;
  const double first_spacing = std::ceil(2.0 * c.skin.ridge_spacing_mm) / 2.0;
  for (double s = first_spacing; fingerprint && s <= c.skin.pattern_radius_mm; s += 0.5) {
    trial.skin.ridge_spacing_mm = s;
    if (EstimateRailScene(trial.SceneSpec()).Fits()) {
      FailRule(key, current, fmt::format("{}; use skin.ridge_spacing_mm >= {}", what, s));
    }
  }
  FailRule(key, current, what + "; use a skin with fewer pins");
}

// A lightly damped shell sliding (SimConfig::SlidingTimestep) above its validated sliding step;
// the relative 1e-9 lets the step that was printed as the limit pass.
bool SlidesAboveLightShellStep(const SkinConfig& skin, const SimConfig& sim) {
  return sim.SlidingTimestep() > LightShellValidatedSlidingStep(skin) * (1.0 + 1e-9);
}

// The timestep: below the stability limit of every mode and, for a skin with per-pin shear
// DOFs, no larger than its validated step. Either refusal suggests the largest step that
// passes both, rounded down so that it passes as printed. A lightly damped shell must slide
// (SimConfig::SlidingTimestep) at no more than its validated sliding step.
void CheckTimestep(const RailScenarioConfig& c) {
  if (!c.sim.check_stability) return;
  const StiffMode mode = RailStiffestMode(c.SceneSpec());
  const double dt_max = mode.MaxTimestep();
  const double validated = ShearDofValidatedTimestep(c.skin, c.contact);
  const double safe = std::min(dt_max, validated);
  const std::string other = mode.other_fix.empty() ? "" : " or " + mode.other_fix;
  const std::string advice =
      safe >= SimConfig::kMinTimestepS
          ? fmt::format("use sim.timestep_s <= {}", FormatAtMost(safe))
          : fmt::format("no sim.timestep_s >= {} is stable: use other values of the keys that set it",
                        SimConfig::kMinTimestepS);
  if (c.sim.timestep_s > dt_max) {
    FailRule("sim.timestep_s", c.sim.timestep_s,
             fmt::format("unstable: exceeds the limit {} s of {} (omega = {:.0f} rad/s, damping ratio {:.2f}); {}{}",
                         FormatAtMost(dt_max), mode.name, mode.omega, mode.zeta, advice, other));
  }
  if (c.sim.timestep_s > validated * (1.0 + 1e-9)) {
    FailRule("sim.timestep_s", c.sim.timestep_s,
             fmt::format("skin.coupling = {} (per-pin shear DOFs) at contact.friction = {} is validated up to "
                         "{} s: at larger steps its slip events create energy; {}",
                         c.skin.coupling, c.contact.friction, FormatAtMost(validated), advice));
  }
  if (SlidesAboveLightShellStep(c.skin, c.sim)) {
    const double light = LightShellValidatedSlidingStep(c.skin);
    const std::string ratio = c.skin.shell_damping == "gel" ? "skin.gel_loss_tangent / 2" : "skin.shear_damping_ratio";
    FailRule("sim.sliding_timestep_s", c.sim.sliding_timestep_s,
             fmt::format("the shell skin damped at a ratio of {:.3g} ({}; below {}) is validated with a step up to {} "
                         "s from the gross-slip onset on (here {} s): at larger steps the released shell's ringing "
                         "makes the sliding contacts chatter; use sim.sliding_timestep_s <= {} (not 0) or "
                         "sim.timestep_s <= {}",
                         c.skin.ShellDampingRatio(), ratio, kLightShellDampingRatio, FormatAtMost(light),
                         config_detail::FormatReal(c.sim.SlidingTimestep()), FormatAtMost(light), FormatAtMost(light)));
  }
}

}  // namespace

void RailScenarioConfig::ValidateRules() const {
  // Section rules first, then rules that tie sections together.
  sim.ValidateRules();
  skin.ValidateRules();
  contact.ValidateRules();
  sensor.ValidateRules();
  external.ValidateIntrinsics(sensor);
  images.ValidateRules();
  rail.ValidateRules();
  if (contact.timeconst_s < 2.0 * sim.timestep_s) {
    FailRule("contact.timeconst_s", contact.timeconst_s,
             fmt::format("must be >= 2 * sim.timestep_s = {} s (MuJoCo would silently soften it)",
                         2.0 * sim.timestep_s));
  }
  CheckPress(rail);
  if (external.enabled && rail.stimulus != "acrylic") {
    FailRule("external.enabled", 1.0,
             "the external camera sees the skin only through a transparent stimulus: set rail.stimulus = acrylic");
  }
  const double frame_dt = 1.0 / sensor.frame_rate_hz;
  if (frame_dt < sim.timestep_s) {
    FailRule("sensor.frame_rate_hz", sensor.frame_rate_hz,
             fmt::format("one frame ({} s) is shorter than sim.timestep_s = {} s", frame_dt, sim.timestep_s));
  }
  CheckSensors(*this);
  CheckSceneSize(*this);
  CheckTimestep(*this);
}

namespace {
// The largest step up to `bound_s` that makes a camera frame a whole number of steps. A
// relative 1e-9 keeps an exact divisor (2 ms of 10 ms) from being pushed to the next one by
// rounding; the last ulp is clipped so the step never exceeds the bound.
double FrameFraction(double bound_s, double frame_s) {
  const long long steps = std::max(1LL, static_cast<long long>(std::ceil(frame_s / bound_s * (1.0 - 1e-9))));
  return std::min(frame_s / static_cast<double>(steps), bound_s);
}
}  // namespace

TimestepChoice ChooseTimestep(const RailScenarioConfig& cfg) {
  TimestepChoice c;
  const StableTimestep stable = LargestStableTimestep(cfg.SceneSpec());
  c.stable_s = stable.timestep_s;
  c.stable_mode = stable.mode.name;
  // The smallest bound wins (the first listed on a tie).
  const double frame_s = 1.0 / cfg.sensor.frame_rate_hz;
  const std::pair<double, std::string> bounds[] = {
      {stable.timestep_s, "stability"},
      {ShearDofValidatedTimestep(cfg.skin, cfg.contact), "the skin's per-pin shear DOFs (validated step)"},
      {cfg.sim.timestep_s, "accuracy (the configured sim.timestep_s)"},
      {0.5 * cfg.contact.timeconst_s, "the contact (contact.timeconst_s / 2)"},
      {frame_s, "one camera frame (sensor.frame_rate_hz)"},
  };
  c.bound_s = bounds[0].first;
  c.binding = bounds[0].second;
  for (const auto& [value, what] : bounds) {
    if (value < c.bound_s) {
      c.bound_s = value;
      c.binding = what;
    }
  }
  c.timestep_s = FrameFraction(c.bound_s, frame_s);
  // A lightly damped shell must slide within its validated step (CheckTimestep): when the
  // chosen step would not, the whole run takes it.
  SimConfig sim = cfg.sim;
  sim.timestep_s = c.timestep_s;
  if (SlidesAboveLightShellStep(cfg.skin, sim)) {
    c.bound_s = LightShellValidatedSlidingStep(cfg.skin);
    c.binding = "the lightly damped shell skin (its validated sliding step, with no sliding step within it)";
    c.timestep_s = FrameFraction(c.bound_s, frame_s);
  }
  return c;
}

RailSceneSpec RailScenarioConfig::SceneSpec() const {
  RailSceneSpec spec;
  spec.sim = sim;
  spec.object = object;
  spec.contact = contact;
  spec.rail = rail;
  spec.skin = skin;
  spec.arm = arm;
  spec.sensors = sensors;
  spec.max_depth_m = (rail.press_depth_mm + rail.press_depth_jitter_mm) * 1e-3;
  spec.external_markers = external.enabled;
  return spec;
}

}  // namespace tactip
