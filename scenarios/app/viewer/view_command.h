#pragma once
// `tactip view SCENARIO`: the scene in a live window, or one frame saved as a PNG file
// (--screenshot, headless under xvfb-run).

#include <CLI/CLI.hpp>

#include <functional>

namespace tactip::cli {

/// Registers `view` on `app`. The returned function runs it when it was selected (returns
/// its exit code), or returns -1 if it was not.
std::function<int()> AddViewCommand(CLI::App& app);

}  // namespace tactip::cli
