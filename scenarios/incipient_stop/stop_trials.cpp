#include "scenarios/incipient_stop/stop_trials.h"

#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "sim/base/nan.h"
#include "sim/base/number_text.h"
#include "sim/config.h"

namespace tactip {

namespace {


// The hardware's online incipient stop (mission.md): fingerprint v2 stopped before the fall
// in 17 of 20 trials; the smooth TacTip shows no incipient slip.
std::string HardwareFigure(const std::string& pattern) {
  if (pattern == "fingerprint-v2") return "17/20 stopped before the fall";
  if (pattern == "smooth") return "no incipient slip (all markers move together)";
  return "-";
}

}  // namespace

std::string ToString(StopOutcome o) {
  switch (o) {
    case StopOutcome::kStopped: return "stopped";
    case StopOutcome::kStoppedLate: return "stopped_late";
    case StopOutcome::kMissed: return "missed";
  }
  return "?";
}

StopTrial ScoreStopTrial(const RailRunSummary& s, int trial) {
  StopTrial t;
  t.trial = trial;
  t.stop_s = kNaN;
  for (const ControllerAction& a : s.actions) {
    if (a.what == "stop") t.stop_s = a.time_s;
  }
  t.onset_s = s.gross_slip_onset_s;
  t.fall_s = s.object_fall_s;
  t.incipient_s = s.incipient_onset_s;
  t.lead_s = t.onset_s - t.stop_s;
  const bool stopped = !std::isnan(t.stop_s);
  t.before_gross = stopped && (std::isnan(t.onset_s) || t.stop_s < t.onset_s);
  // Stopped before the fall and still held at the end; stopped, yet it fell; or too late.
  if (stopped && (std::isnan(t.fall_s) || t.stop_s < t.fall_s)) {
    t.outcome = std::isnan(t.fall_s) ? StopOutcome::kStopped : StopOutcome::kStoppedLate;
  } else {
    t.outcome = StopOutcome::kMissed;
  }
  return t;
}

std::vector<StopTrial> RunStopTrials(const RailScenarioConfig& cfg, const StopTrialOptions& opts) {
  opts.loop.Validate();
  if (opts.loop.markers == "external" && !cfg.external.enabled) {
    throw InputError("--markers external: the scene has no external camera (set external.enabled=true)");
  }
  const RailScenario scenario(cfg);
  const ControllerFactory make = [&](int, const RailSchedule& schedule) -> std::unique_ptr<RailController> {
    return std::make_unique<StopController>(schedule, opts.loop);
  };
  std::vector<StopTrial> trials;
  RunRailRuns(scenario, 0, opts.trials, opts.seed, opts.jobs, opts.stop,
              [&](RunRecord&& rec, const RailRunSummary& s) {
                StopTrial t = ScoreStopTrial(s, rec.index);
                t.skin = cfg.skin.pattern;
                if (opts.progress) opts.progress(t);
                trials.push_back(t);
              },
              make);
  return trials;
}

std::string StopTrialsCsv(const std::vector<StopTrial>& trials) {
  std::string out = "trial,skin,outcome,stop_s,onset_s,fall_s,incipient_onset_s,lead_s,stopped_before_gross\n";
  for (const StopTrial& t : trials) {
    out += fmt::format("{},{},{},{},{},{},{},{},{}\n", t.trial, t.skin, ToString(t.outcome), NumberCell(t.stop_s, "{:.4f}", "nan"),
                       NumberCell(t.onset_s, "{:.4f}", "nan"), NumberCell(t.fall_s, "{:.4f}", "nan"), NumberCell(t.incipient_s, "{:.4f}", "nan"), NumberCell(t.lead_s, "{:.4f}", "nan"), t.before_gross ? 1 : 0);
  }
  return out;
}

std::string FormatStopTable(const std::vector<StopTrial>& trials) {
  // Per skin: trials, stopped (held), stopped before gross slip, and the mean lead of the
  // stops before a gross-slip onset that still came (a held object has no onset, so no lead).
  struct Row {
    int n = 0, stopped = 0, before_gross = 0, with_lead = 0;
    double lead_sum = 0.0;
  };
  std::map<std::string, Row> rows;
  for (const StopTrial& t : trials) {
    Row& r = rows[t.skin];
    ++r.n;
    r.stopped += t.outcome == StopOutcome::kStopped;
    if (t.before_gross) {
      ++r.before_gross;
      if (!std::isnan(t.lead_s)) {
        r.lead_sum += t.lead_s;
        ++r.with_lead;
      }
    }
  }
  std::string out = fmt::format("{:<16} {:>7} {:>16} {:>20} {:>10}   {}\n", "skin", "trials", "stopped, held",
                                "stopped before slip", "mean lead", "hardware");
  for (const auto& [skin, r] : rows) {
    out += fmt::format("{:<16} {:>7} {:>9} ({:>3.0f}%) {:>13} ({:>3.0f}%) {:>8} s   {}\n", skin, r.n, r.stopped,
                       100.0 * r.stopped / r.n, r.before_gross, 100.0 * r.before_gross / r.n,
                       r.with_lead ? fmt::format("{:.2f}", r.lead_sum / r.with_lead) : "-",
                       HardwareFigure(skin));
  }
  return out;
}

}  // namespace tactip
