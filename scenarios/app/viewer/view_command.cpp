#include "scenarios/app/viewer/view_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "scenarios/app/viewer/rail_view_source.h"
#include "scenarios/cli/common.h"
#include "scenarios/cli/option_checks.h"
#include "sim/config.h"
#include "sim/files.h"
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
  if (!a.config.config_path.empty() && SameFile(a.screenshot, a.config.config_path)) {
    throw InputError(fmt::format("--screenshot {}: is the --config file; choose another name", a.screenshot));
  }
  CheckWritableLocation(a.screenshot);
}

// Everything that can be checked before the scene is built.
void CheckViewArgs(const ViewArgs& a) {
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
  std::fprintf(stderr, "wrote %s (%d x %d px, t = %.3f s)\n", a.screenshot.c_str(), a.width, a.height, source.time());
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
  const ScenarioEntry& entry = FindScenario(a.config.scenario);
  RailViewSource source(ResolveAndReport(entry, a.config.Source()).config, a.run, a.seed);
  if (a.time_s > source.give_up_s()) {
    throw InputError(fmt::format("--time = {}: run {} (seed {}) ends by t = {:.3f} s; choose a time in [0, {:.3f}] s",
                                 a.time_s, a.run, a.seed, source.give_up_s(), source.give_up_s()));
  }
  return Show(source, a, "tactip view " + entry.name);
}

int RunView(const ViewArgs& a) {
  CheckViewArgs(a);
  return ViewScenario(a);
}

}  // namespace

std::function<int()> AddViewCommand(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  auto* view = app.add_subcommand(
      "view",
      "Show a run of a scenario as it is simulated in a window (mouse: orbit, "
      "zoom; keys: space pause, right arrow or '.' step, '-'/'+' slower/faster, 'f' contact forces, Esc quit), "
      "or save one frame with --screenshot. Pins: stick green, slip red, no contact grey.");
  a->config.Add(view);
  a->config.AddAutoTimestep(view);
  view->add_option("--run", a->run, fmt::format("Run number, 0 to {} (default 0): the run of 'tactip generate' with "
                                                "that index.", kMaxRunIndex))
      ->check(CLI::Range(0, kMaxRunIndex));
  AddSeedOption(view, a->seed, "Master seed, as for 'tactip generate' (default 1).");
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
