#pragma once
// The closed-loop subcommands of `tactip run`: protocols with a detector in the loop
// (rail-catch: the online slip detection and catch on the rail rig; incipient-stop: the
// online incipient detection on the acrylic rig).

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>

namespace tactip::cli {

/// Registers `tactip run rail-catch` and `tactip run incipient-stop` on `app`. The returned function runs the selected one
/// (returns its exit code), or returns -1 if none was selected.
std::function<int()> AddRunCommands(CLI::App& app, const std::atomic<bool>* stop);

}  // namespace tactip::cli
