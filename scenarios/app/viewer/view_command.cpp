#include "scenarios/app/viewer/view_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scenarios/app/viewer/rail_view_source.h"
#include "scenarios/registry.h"
#include "sim/config.h"
#include "sim/base/files.h"
#include "sim/png_file.h"
#include "sim/render.h"
#include "sim/viewer_window.h"

namespace tactip::cli {

namespace {

/// Latest simulated time a screenshot may be taken at (s): the scene is stepped there first.
constexpr double kMaxViewTimeS = 600.0;

// Options of `tactip view`.
struct ViewArgs {
  std::string scenario;
  std::string config_path;
  std::vector<std::string> sets;
  std::string screenshot;  // "" = live window
  double time_s = 0.0;
  int width = 1024, height = 768;
  bool forces = false;
};

// Everything that can be checked before the scene is built.
void CheckViewArgs(const ViewArgs& a) {
  CheckImageSide("--width", a.width);
  CheckImageSide("--height", a.height);
  if (!(a.time_s >= 0.0 && a.time_s <= kMaxViewTimeS)) {
    throw InputError(fmt::format("--time = {}: must be in [0, {}] s", a.time_s, kMaxViewTimeS));
  }
  if (a.screenshot.empty()) return;
  if (std::filesystem::path(a.screenshot).extension() != ".png") {
    throw InputError(fmt::format("--screenshot {}: must name a .png file", a.screenshot));
  }
  if (!a.config_path.empty() && SameFile(a.screenshot, a.config_path)) {
    throw InputError(fmt::format("--screenshot {}: is the --config file; choose another name", a.screenshot));
  }
  CheckWritableLocation(a.screenshot);
}

// --screenshot: one frame at --time, saved as PNG.
int SaveScreenshot(RailViewSource& source, const ViewArgs& a) {
  SceneRenderer renderer(source.model(), a.width, a.height);  // fails early without a display
  source.AdvanceTo(a.time_s);
  renderer.SetView(source.Camera());
  RenderOptions options;
  options.colours = source.Colours();
  options.contact_forces = a.forces;
  options.force_scale_m_N = source.force_scale_m_N();
  SavePng(renderer.Render(source.sim(), options), a.screenshot);
  std::fprintf(stderr, "wrote %s (%d x %d px, t = %.3f s)\n", a.screenshot.c_str(), a.width, a.height, source.time());
  return 0;
}

int RunView(const ViewArgs& a) {
  CheckViewArgs(a);
  const ScenarioEntry& entry = FindScenario(a.scenario);
  ConfigSource src;
  src.yaml_path = a.config_path;
  src.overrides = a.sets;
  RailViewSource source(entry.load(src));
  if (!a.screenshot.empty()) return SaveScreenshot(source, a);
  // Live: the window opens on the scene at --time.
  ViewerWindow window(source.model(), a.width, a.height, "tactip view " + entry.name);
  source.AdvanceTo(a.time_s);
  window.Run(source, a.forces);
  return 0;
}

}  // namespace

std::function<int()> AddViewCommand(CLI::App& app) {
  auto a = std::make_shared<ViewArgs>();
  auto* view = app.add_subcommand(
      "view",
      "Show a scenario's scene in a window (mouse: orbit, zoom; keys: space pause, right arrow or '.' step, "
      "'-'/'+' slower/faster, 'f' contact forces, Esc quit), or save one frame with --screenshot.");
  view->add_option("scenario", a->scenario, "Scenario name (see 'tactip scenarios').")->required();
  view->add_option("--config", a->config_path, "YAML config file (see assets/scenes/).")->check(CLI::ExistingFile);
  view->add_option("--set", a->sets, "Override one config key (repeatable), e.g. --set rail.stimulus=curved40.")
      ->type_name("KEY=VALUE");
  view->add_option("--screenshot", a->screenshot,
                   "Render one frame into this PNG file and exit (no window; headless: xvfb-run -a tactip view ...).")
      ->check([](const std::string& path) { return path.empty() ? std::string("must name a .png file") : std::string(); });
  view->add_option("--time", a->time_s,
                   fmt::format("Simulated time of the frame shown first, in [0, {}] s (default 0: the initial state).",
                               kMaxViewTimeS));
  view->add_option("--width", a->width, "Image or window width in pixels (default 1024).");
  view->add_option("--height", a->height, "Image or window height in pixels (default 768).");
  view->add_flag("--forces", a->forces, "Draw the contact forces as arrows (in the window: toggle with 'f').");
  return [a, view]() -> int { return *view ? RunView(*a) : -1; };
}

}  // namespace tactip::cli
