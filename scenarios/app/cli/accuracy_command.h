#pragma once
// The `tactip accuracy` subcommand: error against run time of a scene's numerical settings.

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>

namespace tactip::cli {

/// Registers `accuracy` on `app`. The returned function runs it when it was selected
/// (returns its exit code), or returns -1.
std::function<int()> AddAccuracyCommand(CLI::App& app, const std::atomic<bool>* stop);

}  // namespace tactip::cli
