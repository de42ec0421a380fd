#pragma once
// The stability suite (`tactip stability`): stiff and extreme cases of the rail scene. Each
// case either runs healthy — no MuJoCo warning, no NaN, run health ok — or is refused before
// it runs with a one-line message naming the parameter and a safe value. A case that runs
// unhealthy, crashes, or is refused without saying what to change is a failure of the suite.

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/rail/rail.h"
#include "scenarios/registry.h"

namespace tactip {

/// What Coulomb friction says about the object: held through the lift or not. Set only
/// where the verdict is clear-cut (the margin is a factor of 3 or more); a run that
/// contradicts it fails the suite (stable but wrong).
enum class ExpectHeld { kAny, kHeld, kNotHeld };

/// One case of the suite: overrides of a scenario on the suite's short protocol.
struct StabilityCase {
  std::string name;                      ///< --case NAME
  std::string what;                      ///< what it tests, one line
  std::string skin;                      ///< --skin preset applied first ("" = the scenario's)
  std::vector<std::string> sets;         ///< key=value overrides after the short protocol
  ExpectHeld held = ExpectHeld::kAny;    ///< Coulomb's verdict where clear-cut
  bool auto_timestep = false;            ///< run at the step ChooseTimestep picks
  std::string scenario = "rail";         ///< registered scenario the case starts from
};

/// Every case of the suite, in table order: the one place where the cases are listed.
const std::vector<StabilityCase>& StabilityCases();

/// The short protocol every case starts from (noise and jitter off, 15 mm lift, retraction
/// at 1 mm/s), as key=value overrides. The lift is longer than the 10 mm drop by which a
/// run recognises an object left behind.
const std::vector<std::string>& StabilityProtocol();

/// The case named `name`; throws InputError listing the known names.
const StabilityCase& FindStabilityCase(const std::string& name);

/// The cases named in `names`, in that order, or every case in table order when `names` is
/// empty; throws InputError for an unknown name (FindStabilityCase).
std::vector<const StabilityCase*> ChooseStabilityCases(const std::vector<std::string>& names);

/// The case's config source: the short protocol, the skin preset, the suite's `sets`
/// (`tactip stability --set`, applied to every case), then the case's own keys.
ConfigSource StabilityCaseSource(const StabilityCase& c, const std::vector<std::string>& sets = {});

/// Checks the suite's `sets` before any case runs: each must be accepted by the short
/// protocol on the defaults of every scenario in `cases`; throws InputError
/// ("--set: <the scenario's reason> (on the <name> scenario's defaults)") otherwise, or the
/// config's own "--set '<text>': expected key=value" for a malformed one.
void CheckSuiteSets(const std::vector<std::string>& sets, const std::vector<const StabilityCase*>& cases);

/// How a case ended.
enum class CaseOutcome { kHealthy, kRefused, kFailed };

/// "healthy", "refused" or "FAILED".
const char* OutcomeName(CaseOutcome o);

/// The result of one case.
struct StabilityResult {
  const StabilityCase* c = nullptr;    ///< the case (points into StabilityCases())
  CaseOutcome outcome = CaseOutcome::kFailed;
  std::string message;                 ///< the refusal message or why it failed ("" when healthy)
  std::optional<RailRunSummary> run;   ///< the run's figures, when it ran to the end
  double timestep_s = 0.0;             ///< the step it ran at (NaN when refused)
  double wall_time_s = 0.0;            ///< the case's wall time, loading and building included
  std::vector<std::string> suite_sets; ///< the suite's --set keys it ran with, beneath its own
};

/// True when `message` is a clear refusal: one line that starts with a config key of the
/// scenario ("key = value: ...") and names a safe value ("use ...", "must be ...").
bool RefusalIsClear(const std::string& message, const std::vector<std::string>& keys);

/// Runs one case (run 0 of seed 1) with the suite's `sets` (StabilityCaseSource) and judges
/// it. Throws Interrupted when `*stop` becomes true.
StabilityResult RunStabilityCase(const StabilityCase& c, const std::atomic<bool>* stop = nullptr,
                                 const std::vector<std::string>& sets = {});

/// Options of a suite run.
struct StabilityOptions {
  std::vector<std::string> cases;  ///< names to run (empty: every case); unknown names throw InputError
  std::vector<std::string> sets;   ///< key=value for every case (StabilityCaseSource); checked first
  int jobs = 0;                    ///< worker threads (0 = all cores)
  const std::atomic<bool>* stop = nullptr;
  /// Called as each case finishes (from a worker thread, one call at a time).
  std::function<void(int done, int total, const StabilityResult&)> progress;
};

/// Runs the chosen cases on `jobs` threads; results in table order.
std::vector<StabilityResult> RunStabilitySuite(const StabilityOptions& opts);

/// The list of cases: name, what it sets, what it tests.
std::string FormatStabilityCases(const std::vector<StabilityCase>& cases);
/// The results as a fixed-width table, a refusal or failure message under its row; a first
/// line names the suite's --set keys when the cases ran with any.
std::string FormatStabilityTable(const std::vector<StabilityResult>& results);
/// The results as CSV, one row per case; the last column, suite_sets, holds the suite's --set
/// keys (space-separated, empty without).
std::string StabilityCsv(const std::vector<StabilityResult>& results);
/// The settings of a case as one line: "--skin NAME key=value ..." ("-" if none).
std::string CaseSettings(const StabilityCase& c);

}  // namespace tactip
