#pragma once
// The lean-scene study (`tactip bench --lean`): what each part the rail scene leaves out
// would cost. For each scene, the lean scene every scenario simulates and the same scene
// with one omission put back (SceneOptions), each run through the same protocol on one
// core with every step timed (the speed study's measurement): physics time per step,
// bare mj_step time per step, constraint rows, contacts and memory, against the lean scene.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "models/rail_rig.h"
#include "scenarios/studies/speed/speed.h"
#include "sim/model_counts.h"

namespace tactip {

/// A scene variant: the lean scene or one with parts put back.
struct LeanVariant {
  std::string name;      ///< e.g. "+ visual geoms"
  SceneOptions options;  ///< what it puts back (all false: the lean scene)
  bool protocol = true;  ///< false: its run is not the rail protocol (compare its step cost only)
};

/// The lean scene, each omission put back alone, and all of them at once.
std::vector<LeanVariant> LeanVariants();

/// The scenes the study measures by default: the rail scene on the flat plate and the
/// 40 mm sphere, smooth skin. `names` (the speed study's scene names) chooses others;
/// throws InputError for an unknown name.
std::vector<SpeedScene> ChooseLeanScenes(const std::vector<std::string>& names);

/// One variant of one scene, measured.
struct LeanRow {
  LeanVariant variant;
  SpeedRow speed;      ///< the run's measurement (speed.scene names the scene)
  ModelCounts counts;  ///< what the compiled variant contains
  /// Wall time per physics step (the whole Simulation::Step) and per bare mj_step, us.
  double physics_us() const;
  double bare_us() const;
};

/// What MeasureLean does besides measuring.
struct LeanOptions {
  std::vector<std::string> overrides;  ///< "key=value" on top of each scene's
  std::uint64_t seed = 2026;
  int repeats = 1;                     ///< rounds over the variants; each keeps its fastest run and replay
  std::function<void(const std::string&)> progress;  ///< one line per finished run (may be empty)
  const std::atomic<bool>* stop = nullptr;           ///< checked between runs (throws Interrupted)
};

/// Measures every variant of every scene in `scenes`, single-threaded, in that order.
std::vector<LeanRow> MeasureLean(const std::vector<SpeedScene>& scenes, const LeanOptions& options);

/// The table printed by `tactip bench --lean`: per scene, each variant against the lean one.
std::string FormatLeanTable(const std::vector<LeanRow>& rows);
/// The same as CSV, one row per scene and variant.
std::string LeanCsv(const std::vector<LeanRow>& rows);

}  // namespace tactip
