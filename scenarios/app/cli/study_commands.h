#pragma once
// The study subcommands of `tactip`: validate contact, sweep, report incipient.

#include <CLI/CLI.hpp>

#include <atomic>
#include <functional>

namespace tactip::cli {

/// Registers the study subcommands on `app`. The returned function runs the one that was
/// selected (returns its exit code), or returns -1 if none was.
std::function<int()> AddStudyCommands(CLI::App& app, const std::atomic<bool>* stop);

}  // namespace tactip::cli
