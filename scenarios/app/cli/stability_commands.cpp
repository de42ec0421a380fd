#include "scenarios/app/cli/stability_commands.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "scenarios/app/cli/option_checks.h"
#include "scenarios/app/cli/output_checks.h"
#include "scenarios/studies/stability/stability_suite.h"
#include "sim/base/progress.h"
#include "sim/config.h"
#include "sim/base/files.h"

namespace tactip::cli {

namespace {

// Options of `tactip stability` (owned by the returned closure).
struct StabilityArgs {
  std::vector<std::string> cases;  // --case NAME (repeatable)
  std::vector<std::string> sets;   // --set KEY=VALUE (repeatable): every case
  std::string out;                 // --out DIR
  int jobs = 0;
  bool list = false, quiet = false;
};

// tactip stability: run the cases, print the table, optionally write it as CSV.
int RunStability(const StabilityArgs& a, const std::atomic<bool>* stop) {
  if (a.list) {
    std::printf("%s", FormatStabilityCases(StabilityCases()).c_str());
    return 0;
  }
  StabilityOptions o;
  o.cases = a.cases;
  o.sets = a.sets;
  const std::vector<const StabilityCase*> chosen = ChooseStabilityCases(o.cases);  // before anything runs
  CheckSuiteSets(o.sets, chosen);
  o.jobs = a.jobs;
  o.stop = stop;
  std::string csv_path;
  NewFolderGuard folder(a.out);
  if (!a.out.empty()) {
    CreateOutputFolder(a.out);
    csv_path = (std::filesystem::path(a.out) / "stability.csv").string();
    CheckWritableLocation(csv_path);
  }
  const size_t total = chosen.size();
  if (!a.quiet) {
    std::string with;
    for (const auto& kv : a.sets) with += " " + kv;
    ProgressF("stability: %zu case(s) on the short protocol (noise off, 15 mm lift, 1 mm/s retraction)%s%s\n",
                 total, with.empty() ? "" : ", every case with --set", with.c_str());
    o.progress = [](int done, int n, const StabilityResult& r) {
      ProgressF("[%d/%d] %s: %s (%.1f s)\n", done, n, r.c->name.c_str(), OutcomeName(r.outcome),
                   r.wall_time_s);
    };
  }
  const auto wall0 = std::chrono::steady_clock::now();
  const std::vector<StabilityResult> results = RunStabilitySuite(o);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::printf("%s", FormatStabilityTable(results).c_str());
  if (!csv_path.empty()) WriteFileAtomic(csv_path, StabilityCsv(results));
  folder.Keep();
  bool failed = false;
  for (const auto& r : results) {
    if (r.outcome != CaseOutcome::kFailed) continue;
    failed = true;
    ProgressF("tactip: stability case %s FAILED: %s\n", r.c->name.c_str(), r.message.c_str());
  }
  ProgressF("done: %zu case(s) in %.1f s wall%s%s\n", results.size(), wall,
               csv_path.empty() ? "" : "; wrote ", csv_path.c_str());
  return failed ? 1 : 0;
}

}  // namespace

std::function<int()> AddStabilityCommands(CLI::App& app, const std::atomic<bool>* stop) {
  auto a = std::make_shared<StabilityArgs>();
  auto* c = app.add_subcommand(
      "stability",
      "Run the stability suite: stiff and extreme cases of the rail scene (stiff skins, 5 g to 5 kg, mu 0.05 to 3, "
      "fast retraction, large steps, tall ridges, deep and empty presses, every stimulus and skin). Each must run "
      "healthy or be refused before it runs with a message naming the parameter and a safe value; exit 1 if any "
      "case fails.");
  CLI::Option* only = c->add_option("--case", a->cases, "Run only this case (repeatable); --list shows the names.")
      ->type_name("NAME")
      ->check(NonEmpty("a case name (see --list)"));
  CLI::Option* set = c->add_option("--set", a->sets,
                "Override one config key in every case (repeatable): after the case's skin preset, before the case's "
                "own keys; each must be accepted on the scenario's defaults.")
      ->type_name("KEY=VALUE")
      ->check(NonEmpty("e.g. skin.membrane_links=central"));
  CLI::Option* out = c->add_option("--out", a->out, "Also write the table as DIR/stability.csv (the folder is created).")
      ->type_name("DIR")
      ->check(NonEmpty("a folder"));
  CLI::Option* jobs = c->add_option("--jobs", a->jobs, "Cases run at once (default: all cores).")->check(CLI::Range(0, 256));
  c->add_flag("--list", a->list, "List the cases (name, the outcome Coulomb expects, what each sets) and exit.")
      ->excludes(only)
      ->excludes(set)
      ->excludes(out)
      ->excludes(jobs);
  c->add_flag("--quiet", a->quiet, "No per-case progress lines.");
  return [a, c, stop]() -> int { return *c ? RunStability(*a, stop) : -1; };
}

}  // namespace tactip::cli
