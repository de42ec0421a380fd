#pragma once
// Trials of the online incipient stop: each trial is one run of the incipient scenario
// (its own depth, friction and noise draws) with the step-wise retraction and the
// incipient detector in the loop, scored as the hardware's trials were.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scenarios/incipient_stop/stop_controller.h"
#include "scenarios/rail/rail.h"

namespace tactip {

/// How one trial ended.
enum class StopOutcome {
  kStopped,      ///< the arm stopped and the object stayed held
  kStoppedLate,  ///< the arm stopped, but the object slipped off anyway
  kMissed,       ///< the object fell before the detector fired
};
/// "stopped", "stopped_late", "missed".
std::string ToString(StopOutcome o);

/// One trial's result.
struct StopTrial {
  int trial = 0;
  std::string skin;
  StopOutcome outcome = StopOutcome::kMissed;
  double stop_s = 0.0;      ///< the arm stopped (NaN: never)
  double onset_s = 0.0;     ///< gross-slip onset (NaN: none)
  double fall_s = 0.0;      ///< object fell (NaN: never)
  double incipient_s = 0.0; ///< first partial slip in the ground truth (NaN: none)
  double lead_s = 0.0;      ///< onset - stop (NaN: either missing)
  bool before_gross = false;  ///< stopped before gross slip (or with none after it)
};

/// What RunStopTrials runs.
struct StopTrialOptions {
  StopOptions loop;
  int trials = 20;
  std::uint64_t seed = 1;   ///< trial i is run i of this seed
  int jobs = 0;             ///< threads (0: all cores)
  std::function<void(const StopTrial&)> progress;  ///< after each trial
  const std::atomic<bool>* stop = nullptr;         ///< cooperative interruption
};

/// Runs opts.trials trials of the incipient-scenario config `cfg`. Throws InputError
/// (bad options; external markers without the external camera), SimulationError or Interrupted.
std::vector<StopTrial> RunStopTrials(const RailScenarioConfig& cfg, const StopTrialOptions& opts);

/// Scores one finished trial from its summary.
StopTrial ScoreStopTrial(const RailRunSummary& s, int trial);

/// trials.csv: `trial,skin,outcome,stop_s,onset_s,fall_s,incipient_onset_s,lead_s,stopped_before_gross`.
std::string StopTrialsCsv(const std::vector<StopTrial>& trials);
/// The summary table per skin, with the hardware's figure beside.
std::string FormatStopTable(const std::vector<StopTrial>& trials);

}  // namespace tactip
