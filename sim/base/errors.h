#pragma once
// The error types every folder throws; the command-line program maps each to an exit code.

#include <stdexcept>

namespace tactip {

/// Thrown for invalid user input (config values, files, command-line arguments, detector
/// models and frames); the message is one line a user can act on.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown when an MJCF text does not compile or a named element is missing.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown when a run becomes numerically invalid (NaN, reset state, dropped contacts);
/// the message names the warning, the simulated time and what to change. Also thrown for
/// MuJoCo's internal errors ("MuJoCo internal error: ..."), which would otherwise end the process.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by long work (a run, a merge) when its stop flag becomes true (Ctrl-C).
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace tactip
