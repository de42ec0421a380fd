#include "scenarios/rail_catch/catch_trials.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "sim/base/nan.h"
#include "sim/config.h"

namespace tactip {

namespace {

// The object counts as held again when, over the trial's last kSettleS, it slid less than
// kSettleMm relative to the sensor (whose height is fixed during the retraction) and it is
// clear of the rail's end stop.
constexpr double kSettleS = 0.1;
constexpr double kSettleMm = 0.2;
constexpr double kStopClearMm = 2.0;

// The action `what` of a run (NaN: the controller never took it).
double ActionTime(const RailRunSummary& s, const std::string& what) {
  for (const ControllerAction& a : s.actions) {
    if (a.what == what) return a.time_s;
  }
  return kNaN;
}

// Frame index of the first frame at or after `t`.
size_t FirstFrameFrom(const RunRecord& rec, double t) {
  return static_cast<size_t>(std::lower_bound(rec.time.begin(), rec.time.end(), t) - rec.time.begin());
}

}  // namespace

std::string ToString(CatchOutcome o) {
  switch (o) {
    case CatchOutcome::kCaught: return "caught";
    case CatchOutcome::kFalsePositive: return "false_positive";
    case CatchOutcome::kDropped: return "dropped";
  }
  return "?";
}

CatchTrial ScoreCatchTrial(const RailRunSummary& s, const RunRecord& rec, double classify_us) {
  CatchTrial t;
  t.trial = rec.index;
  t.onset_s = s.gross_slip_onset_s;
  t.declared_s = ActionTime(s, "slip_declared");
  t.delay_ms = (t.declared_s - t.onset_s) * 1e3;
  t.classify_us = classify_us;
  // Slide from the onset to the end, relative to the sensor (the object's height; the
  // sensor's stays at the lift height through the retraction).
  const std::vector<double>& h = rec.object_height_m;
  if (!std::isnan(t.onset_s) && !h.empty()) {
    const size_t k = std::min(FirstFrameFrom(rec, t.onset_s), h.size() - 1);
    t.slip_distance_mm = std::max(0.0, (h[k] - h.back()) * 1e3);
  }
  // Acted before any slip: a false positive, whatever happened after.
  if (!std::isnan(t.declared_s) && (std::isnan(t.onset_s) || t.declared_s < t.onset_s)) {
    t.outcome = CatchOutcome::kFalsePositive;
    return t;
  }
  // Declared after the onset: caught if the object has come to rest clear of the stop.
  const size_t settle = FirstFrameFrom(rec, rec.time.back() - kSettleS);
  const bool at_rest = !h.empty() && std::abs(h[std::min(settle, h.size() - 1)] - h.back()) * 1e3 < kSettleMm;
  const bool clear = !h.empty() && h.back() * 1e3 > kStopClearMm;
  t.outcome = !std::isnan(t.declared_s) && at_rest && clear ? CatchOutcome::kCaught : CatchOutcome::kDropped;
  return t;
}

std::vector<CatchTrial> RunCatchTrials(const RailScenarioConfig& cfg, const CatchTrialOptions& opts) {
  opts.loop.Validate();
  opts.loop.ValidateFor(cfg.rail);
  LoadDetector(opts.model_path);  // a bad model fails here, before any trial runs
  // Long enough after a fall for the arm to come back in and the object to be watched.
  RailScenarioConfig c = cfg;
  c.rail.post_fall_s = std::max(c.rail.post_fall_s, 2.0);
  // Every pin carries a contact geom: the lean scene leaves out those that cannot reach the
  // stimulus where it is held, but a caught object has slid along the rail (on a curved
  // stimulus, onto pins lower on the dome) and the arm may press deeper to catch it.
  SceneOptions every_pin;
  every_pin.all_pins_collide = true;
  const RailScenario scenario(c, every_pin);
  // One controller per trial, each with its own copy of the detector.
  const ControllerFactory make = [&](int, const RailSchedule& schedule) -> std::unique_ptr<RailController> {
    return std::make_unique<CatchController>(schedule, LoadDetector(opts.model_path), opts.loop);
  };
  std::vector<CatchTrial> trials;
  RunRailRuns(scenario, 0, opts.trials, opts.seed, opts.jobs, opts.stop,
              [&](RunRecord&& rec, const RailRunSummary& s) {
                const auto us = s.controller_figures.find("classify_us");
                CatchTrial t = ScoreCatchTrial(s, rec, us == s.controller_figures.end() ? 0.0 : us->second);
                t.stimulus = c.rail.stimulus;
                t.speed_mm_s = rec.attrs.at("retract_speed_mm_s");  // this trial's (drawn when a range is set)
                if (opts.progress) opts.progress(t);
                trials.push_back(t);
              },
              make);
  return trials;
}

}  // namespace tactip
