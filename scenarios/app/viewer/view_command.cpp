#include "scenarios/app/viewer/view_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "scenarios/app/viewer/rail_view_source.h"
#include "scenarios/app/viewer/replay_view_source.h"
#include "scenarios/app/cli/common.h"
#include "scenarios/app/cli/option_checks.h"
#include "sim/base/progress.h"
#include "sim/config.h"
#include "sim/base/files.h"
#include "sim/png_file.h"
#include "sim/render.h"
#include "sim/viewer_window.h"

namespace tactip::cli {

namespace {

/// Latest simulated time a frame may be shown at (s): the run is stepped there first.
constexpr double kMaxViewTimeS = 600.0;
/// Largest run number (`generate` makes at most 100000 runs).
constexpr int kMaxRunIndex = 99999;

// Options of `tactip view`.
struct ViewArgs {
  ConfigArgs config;             // scenario, --config, --set and the shortcuts, as for generate
  int run = 0;                   // --run
  unsigned long long seed = 1;   // --seed
  std::string replay;            // --replay FILE.h5 ("" = simulate the scenario)
  std::string screenshot;        // "" = live window
  double time_s = 0.0;
  int width = 1024, height = 768;
  bool forces = false;
};

// --screenshot: a .png name that is none of the input files, in a writable folder.
void CheckScreenshotName(const ViewArgs& a) {
  if (std::filesystem::path(a.screenshot).extension() != ".png") {
    throw InputError(fmt::format("--screenshot {}: must name a .png file", a.screenshot));
  }
  for (const auto& [option, input] : {std::pair{"--config", a.config.config_path}, std::pair{"--replay", a.replay}}) {
    if (!input.empty() && SameFile(a.screenshot, input)) {
      throw InputError(fmt::format("--screenshot {}: is the {} file; choose another name", a.screenshot, option));
    }
  }
  CheckWritableLocation(a.screenshot);
}

// Everything that can be checked before the scene is built.
void CheckViewArgs(const ViewArgs& a) {
  if (a.replay.empty() && a.config.scenario.empty()) {
    throw InputError("view: give a scenario (see 'tactip scenarios') or --replay FILE.h5");
  }
  CheckImageSide("--width", a.width);
  CheckImageSide("--height", a.height);
  if (!(a.time_s >= 0.0 && a.time_s <= kMaxViewTimeS)) {
    throw InputError(fmt::format("--time = {}: must be in [0, {}] s", a.time_s, kMaxViewTimeS));
  }
  if (!a.screenshot.empty()) CheckScreenshotName(a);
}

// Steps the run to --time; refuses a time after the run's end.
void AdvanceToTime(RailViewSource& source, double time_s) {
  if (source.AdvanceTo(time_s)) return;
  throw InputError(fmt::format("--time = {}: run {} (seed {}) ended at t = {:.3f} s; choose a time in [0, {:.3f}] s",
                               time_s, source.index(), source.seed(), source.time(), source.time()));
}

// --screenshot: one frame at --time, saved as PNG.
int SaveScreenshot(RailViewSource& source, const ViewArgs& a) {
  SceneRenderer renderer(source.model(), a.width, a.height);  // fails early without a display
  AdvanceToTime(source, a.time_s);
  renderer.SetView(source.Camera());
  RenderOptions options;
  options.colours = source.Colours();
  options.contact_forces = a.forces;
  options.force_scale_m_N = source.force_scale_m_N();
  SavePng(renderer.Render(source.sim(), options), a.screenshot);
  ProgressF("wrote %s (%d x %d px, t = %.3f s)\n", a.screenshot.c_str(), a.width, a.height, source.time());
  return 0;
}

// The frame at --time saved, or the live window opened on it.
int Show(RailViewSource& source, const ViewArgs& a, const std::string& title) {
  if (!a.screenshot.empty()) return SaveScreenshot(source, a);
  ViewerWindow window(source.model(), a.width, a.height, title);
  AdvanceToTime(source, a.time_s);
  window.Run(source, a.forces);
  return 0;
}

// `view SCENARIO`: run --run of the scenario's config with master seed --seed.
int ViewScenario(const ViewArgs& a) {
  const Scenario& scenario = FindScenario(a.config.scenario);
  RailViewSource source(ResolveRailAndReport(scenario, a.config.Source()), a.run, a.seed);
  if (a.time_s > source.give_up_s()) {
    throw InputError(fmt::format("--time = {}: run {} (seed {}) ends by t = {:.3f} s; choose a time in [0, {:.3f}] s",
                                 a.time_s, a.run, a.seed, source.give_up_s(), source.give_up_s()));
  }
  return Show(source, a, "tactip view " + scenario.name());
}

// `view --replay FILE`: run --run of the file re-simulated, with the stored labels; reports
// how far the re-simulated pins are from the stored ones.
int ViewReplay(const ViewArgs& a) {
  ReplayViewSource source(a.replay, a.run);
  if (a.time_s > source.stored_end_s()) {
    throw InputError(fmt::format("--time = {}: run {} of {} ends at t = {:.3f} s; choose a time in [0, {:.3f}] s",
                                 a.time_s, a.run, a.replay, source.stored_end_s(), source.stored_end_s()));
  }
  const int code = Show(source, a, "tactip view --replay " + a.replay);
  ProgressF("replay of run %d of %s up to t = %.3f s: %s\n", a.run, a.replay.c_str(), source.time(),
               source.DifferenceReport().c_str());
  return code;
}

int RunView(const ViewArgs& a) {
  CheckViewArgs(a);
  return a.replay.empty() ? ViewScenario(a) : ViewReplay(a);
}

// --replay and the options that choose what to simulate exclude each other.
void AddReplayOption(CLI::App* view, std::string& replay) {
  CLI::Option* opt = view->add_option(
      "--replay", replay,
      "Re-simulate run --run of this dataset (written by 'tactip generate') from its stored scenario, config and "
      "seed, with the pins coloured by its stored labels, and report the largest difference between its stored "
      "and the re-simulated pin positions (pos_px; 0 px when the replay is exact).");
  opt->type_name("FILE.h5")->check(NonEmpty("an HDF5 dataset"));
  for (const char* name : {"scenario", "--config", "--set", "--speed-mm-s", "--stimulus", "--skin", "--auto-timestep",
                           "--seed"}) {
    opt->excludes(view->get_option(name));
  }
}

}  // namespace

std::function<int()> AddViewCommand(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  auto* view = app.add_subcommand(
      "view",
      "Show a run of a scenario as it is simulated, or a stored run replayed (--replay), in a window (mouse: orbit, "
      "zoom; keys: space pause, right arrow or '.' step, '-'/'+' slower/faster, 'f' contact forces, Esc quit), "
      "or save one frame with --screenshot. Pins: stick green, slip red, no contact grey.");
  view->add_option("scenario", a->config.scenario, "Scenario name (see 'tactip scenarios'); not with --replay.")
      ->check(NonEmpty("a scenario name (see 'tactip scenarios')"));
  a->config.Add(view, false);
  a->config.AddAutoTimestep(view);
  view->add_option("--run", a->run, fmt::format("Run number, 0 to {} (default 0): the run of 'tactip generate' with "
                                                "that index, or the run of the --replay file.", kMaxRunIndex))
      ->check(CLI::Range(0, kMaxRunIndex));
  AddSeedOption(view, a->seed, "Master seed, as for 'tactip generate' (default 1).");
  AddReplayOption(view, a->replay);
  view->add_option("--screenshot", a->screenshot,
                   "Render one frame into this PNG file and exit (no window; headless: xvfb-run -a tactip view ...).")
      ->check([](const std::string& path) { return path.empty() ? std::string("must name a .png file") : std::string(); });
  view->add_option("--time", a->time_s,
                   fmt::format("Simulated time of the frame shown first, in [0, {}] s and within the run (default 0: "
                               "the initial state).", kMaxViewTimeS));
  view->add_option("--width", a->width, "Image or window width in pixels (default 1024).");
  view->add_option("--height", a->height, "Image or window height in pixels (default 768).");
  view->add_flag("--forces", a->forces, "Draw the contact forces as arrows (in the window: toggle with 'f').");
  return [a, view]() -> int { return *view ? RunView(*a) : -1; };
}

}  // namespace tactip::cli
