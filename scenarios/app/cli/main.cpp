// tactip: the command-line program of tactip-sim. Each group of subcommands lives in its
// own file; this one parses, dispatches and turns errors into exit codes.

#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scenarios/app/cli/accuracy_command.h"
#include "scenarios/app/cli/detect_commands.h"
#include "scenarios/app/cli/plot_command.h"
#include "scenarios/app/cli/run_commands.h"
#include "scenarios/app/cli/scenario_commands.h"
#include "scenarios/app/cli/stability_commands.h"
#include "scenarios/app/cli/study_commands.h"
#include "scenarios/app/cli/track_command.h"
#include "scenarios/app/viewer/view_command.h"
#include "scenarios/rail/rail.h"
#include "sim/base/errors.h"
#include "sim/base/progress.h"
#include "tactip/version.h"

namespace {

// Set by SIGINT/SIGTERM; long runs poll it and stop cleanly (no partial output). A
// signal handler can only reach a global.
std::atomic<bool> g_stop{false};

void OnSignal(int) { g_stop = true; }

// Runs the selected subcommand and maps each kind of failure to its exit code: 2 bad
// input, 3 numerical failure, 130 interrupted, 1 anything else.
int Dispatch(const std::vector<std::function<int()>>& runners) {
  try {
    for (const auto& run : runners) {
      if (const int code = run(); code >= 0) return code;
    }
    return 0;
  } catch (const tactip::InputError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 2;
  } catch (const tactip::ModelError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 2;
  } catch (const tactip::SimulationError& e) {
    std::fprintf(stderr, "tactip: %s\n", e.what());
    return 3;
  } catch (const tactip::Interrupted&) {
    std::fprintf(stderr, "tactip: interrupted; no output written\n");
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tactip: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tactip-sim: a MuJoCo simulator of the TacTip optical tactile sensor, with exact slip ground truth.\n"
               "Scenarios build a scene, drive a protocol and write labelled HDF5 datasets."};
  app.set_version_flag("--version", std::string("tactip ") + TACTIP_VERSION);
  app.require_subcommand(1);
  const std::vector<std::function<int()>> runners = {
      tactip::cli::AddScenarioCommands(app, &g_stop),
      tactip::cli::AddStudyCommands(app, &g_stop),
      tactip::cli::AddAccuracyCommand(app, &g_stop),
      tactip::cli::AddStabilityCommands(app, &g_stop),
      tactip::cli::AddDetectorCommands(app, &g_stop),
      tactip::cli::AddRunCommands(app, &g_stop),
      tactip::cli::AddPlotCommand(app),
      tactip::cli::AddTrackCommand(app),
      tactip::cli::AddViewCommand(app),
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "tactip: %s (see --help)\n", e.what());
    return 2;
  }
  // Long simulations stop cleanly on Ctrl-C; other commands keep the default handling
  // (their outputs are written atomically at the end).
  for (const char* name : {"generate", "merge", "sweep", "bench", "stability", "run"}) {
    if (app.got_subcommand(name)) {
      std::signal(SIGINT, OnSignal);
      std::signal(SIGTERM, OnSignal);
    }
  }
  // A long step never leaves the terminal silent: after 10 s without a progress line the
  // heartbeat says what is still running (not with --quiet, nor in the viewer's window).
  bool quiet = app.got_subcommand("view");
  for (int i = 1; i < argc; ++i) quiet = quiet || std::string(argv[i]) == "--quiet";
  std::unique_ptr<tactip::Heartbeat> heartbeat;
  if (!quiet) heartbeat = std::make_unique<tactip::Heartbeat>("tactip");
  return Dispatch(runners);
}
