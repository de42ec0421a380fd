#include "sensors/run_checks.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/config.h"

namespace tactip {
namespace {

/// Throws "<source>: run_NNNN/<array> <problem>".
[[noreturn]] void Refuse(const RunRecord& run, const std::string& source, const std::string& array,
                         const std::string& problem) {
  throw InputError(fmt::format("{}: {}/{} {}", source, RunGroupName(run.index), array, problem));
}

/// "frame 3" or "frame 3, pin 7" for value `i` of a (T) or (T, N, width) array.
std::string Position(size_t i, size_t n_pins, size_t width) {
  if (width == 0) return fmt::format("frame {}", i);
  return fmt::format("frame {}, pin {}", i / (n_pins * width), (i / width) % n_pins);
}

/// Refuses the first non-finite value of a (T) array (width 0) or a (T, N, width) array
/// of an N-pin sensor (n 1 for arrays without a pin axis).
template <class T>
void CheckFinite(const RunRecord& run, const std::string& source, const std::string& array,
                 const std::vector<T>& values, size_t width, size_t n = 1) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      Refuse(run, source, array, fmt::format("is {} at {} (must be a finite number)", values[i], Position(i, n, width)));
    }
  }
}

/// Refuses the first infinite value of a (N) per-pin time array (NaN means "never").
void CheckTimesOrNaN(const RunRecord& run, const std::string& source, const std::string& array,
                     const std::vector<double>& values) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (std::isinf(values[i])) {
      Refuse(run, source, array, fmt::format("is {} at pin {} (must be a finite time or NaN)", values[i], i));
    }
  }
}

/// Refuses the first value other than 0 or 1 of a (T, N) flag array.
void CheckFlags(const RunRecord& run, const std::string& source, const std::string& array,
                const std::vector<std::uint8_t>& flags, size_t n) {
  for (size_t i = 0; i < flags.size(); ++i) {
    if (flags[i] > 1) Refuse(run, source, array, fmt::format("is {} at {} (must be 0 or 1)", flags[i], Position(i, n, 1)));
  }
}

}  // namespace

void CheckRunTimes(const RunRecord& run, const std::string& source) {
  const std::vector<double>& t = run.time;
  if (t.empty()) Refuse(run, source, "time", "has no frames (a run needs at least one)");
  CheckFinite(run, source, "time", t, 0);
  for (size_t f = 1; f < t.size(); ++f) {
    if (!(t[f] > t[f - 1])) {
      Refuse(run, source, "time",
             fmt::format("is not increasing: frame {} at {} s is not after frame {} at {} s", f, t[f], f - 1, t[f - 1]));
    }
  }
}

void CheckRunValues(const RunRecord& run, const std::string& source, int layout_version) {
  for (const SensorRecord& s : run.sensors) {
    // Each sensor's arrays, named by their path in the file.
    const std::string at = SensorPath(layout_version, s.name);
    const size_t n = static_cast<size_t>(s.n_pins);
    CheckFinite(run, source, at + "pins/pos_px", s.pos_px, 2, n);
    CheckFinite(run, source, at + "pins/pos_m", s.pos_m, 3, n);
    CheckFinite(run, source, at + "contact/normal_N", s.normal_N, 1, n);
    CheckFinite(run, source, at + "contact/tangential_N", s.tangential_N, 2, n);
    CheckFinite(run, source, at + "external/pos_px", s.external_px, 2, n);
    CheckFinite(run, source, at + "external/pos_m", s.external_m, 3, n);
    CheckFinite(run, source, at + "pins/detected_px", s.detected_px, 2, n);
    CheckTimesOrNaN(run, source, at + "labels/pin_first_slip_s", s.pin_first_slip_s);
    CheckFlags(run, source, at + "pins/valid", s.valid, n);
    CheckFlags(run, source, at + "pins/detected_valid", s.detected_valid, n);
  }
  CheckFinite(run, source, "object/height_m", run.object_height_m, 0);
  // The controls: (T, U), named by frame.
  const size_t u = run.actions.actuators.size();
  for (size_t i = 0; i < run.actions.controls.size(); ++i) {
    if (!std::isfinite(run.actions.controls[i])) {
      Refuse(run, source, "actions/controls",
             fmt::format("is {} at frame {}, actuator {} (must be a finite number)", run.actions.controls[i], i / u,
                         run.actions.actuators[i % u]));
    }
  }
  for (size_t k = 0; k < run.actions.list.size(); ++k) {
    if (!std::isfinite(run.actions.list[k].time_s)) {
      Refuse(run, source, "actions/time", fmt::format("is {} at action {} (must be a finite number)",
                                                      run.actions.list[k].time_s, k));
    }
  }
}

}  // namespace tactip
