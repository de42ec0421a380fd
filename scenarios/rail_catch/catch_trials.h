#pragma once
// Trials of the online rail catch: each trial is one rail run (its own depth, friction and
// noise draws) with the detector in the loop, scored as the hardware's trials were.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scenarios/rail/rail.h"
#include "scenarios/rail_catch/catch_controller.h"

namespace tactip {

/// How one trial ended.
enum class CatchOutcome {
  kCaught,         ///< slip declared after the onset and the object held again
  kFalsePositive,  ///< the arm acted before the object slipped
  kDropped,        ///< the object fell: no declaration, or too late to catch it
};
/// "caught", "false_positive", "dropped".
std::string ToString(CatchOutcome o);

/// One trial's result.
struct CatchTrial {
  int trial = 0;
  std::string stimulus;
  double speed_mm_s = 0.0;
  CatchOutcome outcome = CatchOutcome::kDropped;
  double slip_distance_mm = 0.0;  ///< object's slide relative to the sensor from the onset to the end (0: no onset)
  double onset_s = 0.0;           ///< gross-slip onset (NaN: none)
  double declared_s = 0.0;        ///< slip declared (NaN: never)
  double delay_ms = 0.0;          ///< declared - onset (NaN: either missing)
  double classify_us = 0.0;       ///< measured classification time per frame (mean)
};

/// What RunCatchTrials runs.
struct CatchTrialOptions {
  std::string model_path;   ///< trained detector (Detector::Save)
  CatchOptions loop;        ///< the closed loop
  int trials = 20;          ///< trials per (stimulus, speed)
  std::uint64_t seed = 1;   ///< trial i is run i of this seed
  int jobs = 0;             ///< threads (0: all cores)
  std::function<void(const CatchTrial&)> progress;  ///< after each trial
  const std::atomic<bool>* stop = nullptr;          ///< cooperative interruption
};

/// Runs opts.trials trials of the rail scenario `cfg` (its stimulus and retraction speed)
/// with the detector of opts.model_path in the loop. Throws InputError for an unreadable
/// model, SimulationError, or Interrupted.
std::vector<CatchTrial> RunCatchTrials(const RailScenarioConfig& cfg, const CatchTrialOptions& opts);

/// Scores one finished trial from its summary and record (object heights per frame).
CatchTrial ScoreCatchTrial(const RailRunSummary& s, const RunRecord& rec, double classify_us);

}  // namespace tactip
