#pragma once
// The detector subcommands of `tactip`: train, evaluate, detect, bench.

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>

namespace tactip::cli {

/// Registers train/evaluate/detect/bench on `app`. The returned function runs the one
/// that was selected (returns its exit code), or returns -1 if none was.
/// `config_overrides` gives the rail config source used by `bench`.
std::function<int()> AddDetectorCommands(CLI::App& app, const std::atomic<bool>* stop);

}  // namespace tactip::cli
