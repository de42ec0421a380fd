#pragma once
// The scenario subcommands of `tactip`: scenarios, generate, merge, info, export-mjcf, config.

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>

namespace tactip::cli {

/// Registers the scenario subcommands on `app`. The returned function runs the one that
/// was selected (returns its exit code), or returns -1 if none was.
std::function<int()> AddScenarioCommands(CLI::App& app, const std::atomic<bool>* stop);

}  // namespace tactip::cli
