#include "sensors/run_checks.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/config.h"

namespace tactip {
namespace {

/// Throws "<source>: run_NNNN/<array> <problem>".
[[noreturn]] void Refuse(const RunRecord& run, const std::string& source, const char* array,
                         const std::string& problem) {
  throw InputError(fmt::format("{}: {}/{} {}", source, RunGroupName(run.index), array, problem));
}

/// "frame 3" or "frame 3, pin 7" for value `i` of a (T) or (T, N, width) array.
std::string Position(size_t i, size_t n_pins, size_t width) {
  if (width == 0) return fmt::format("frame {}", i);
  return fmt::format("frame {}, pin {}", i / (n_pins * width), (i / width) % n_pins);
}

/// Refuses the first non-finite value of a (T) array (width 0) or a (T, N, width) array.
template <class T>
void CheckFinite(const RunRecord& run, const std::string& source, const char* array, const std::vector<T>& values,
                 size_t width) {
  const size_t n = static_cast<size_t>(run.n_pins);
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      Refuse(run, source, array, fmt::format("is {} at {} (must be a finite number)", values[i], Position(i, n, width)));
    }
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

void CheckRunValues(const RunRecord& run, const std::string& source) {
  CheckFinite(run, source, "pins/pos_px", run.pos_px, 2);
  CheckFinite(run, source, "pins/pos_m", run.pos_m, 3);
  CheckFinite(run, source, "contact/normal_N", run.normal_N, 1);
  CheckFinite(run, source, "contact/tangential_N", run.tangential_N, 2);
  CheckFinite(run, source, "object/height_m", run.object_height_m, 0);
  CheckFinite(run, source, "external/pos_px", run.external_px, 2);
  CheckFinite(run, source, "external/pos_m", run.external_m, 3);
  const size_t n = static_cast<size_t>(run.n_pins);
  for (size_t i = 0; i < run.valid.size(); ++i) {
    if (run.valid[i] > 1) {
      Refuse(run, source, "pins/valid", fmt::format("is {} at {} (must be 0 or 1)", run.valid[i], Position(i, n, 1)));
    }
  }
}

}  // namespace tactip
