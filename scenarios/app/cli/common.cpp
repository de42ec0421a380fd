#include "scenarios/app/cli/common.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "models/skin.h"
#include "scenarios/app/cli/option_checks.h"
#include "sensors/camera_presets.h"
#include "sim/base/number_text.h"
#include "sim/base/progress.h"

namespace tactip::cli {

std::string Fmt(double v, const char* spec) {
  return NumberCell(v, spec);
}

double Attr(const RunRecord& r, const std::string& key) {
  auto it = r.attrs.find(key);
  return it == r.attrs.end() ? std::nan("") : it->second;
}

void ConfigArgs::Add(CLI::App* c, bool with_scenario) {
  if (with_scenario) {
    c->add_option("scenario", scenario, "Scenario name (see 'tactip scenarios').")
        ->required()
        ->check(NonEmpty("a scenario name (see 'tactip scenarios')"));
  }
  AddFileAndSets(c, "YAML config file; its keys override the built-in defaults (see assets/scenes/).",
                 "Override one config key, e.g. --set sensor.pixel_noise_px=0.3 (repeatable; applied after "
                 "--config and the shortcut options). 'tactip config SCENARIO' lists every key.");
  c->add_option("--speed-mm-s", speed_mm_s, "Shortcut for --set rail.retract_speed_mm_s=V.")->check(FiniteNumber());
  c->add_option("--stimulus", stimulus, "Shortcut for --set rail.stimulus=S (flat, acrylic, curved80, curved40, curved20).")
      ->check(NonEmpty("one of flat, acrylic, curved80, curved40, curved20"));
  AddSkin(c, fmt::format("Skin preset: smooth, fingerprint-v1 or fingerprint-v2 (sets skin.pattern, skin.coupling, "
                         "the variant's ridge/thickness/pin keys and the skin's materials (lumped for smooth, "
                         "resolved for the fingerprint skins: skin.gel_shear_modulus_kpa, skin.skin_modulus_mpa, "
                         "skin.rim), and for a fingerprint skin its step "
                         "sim.timestep_s: {} for v1, {} for v2; applied before --set).",
                         *SkinPresetTimestep("fingerprint-v1"), *SkinPresetTimestep("fingerprint-v2")));
  AddCamera(c);
}

void ConfigArgs::AddFileAndSets(CLI::App* c, const std::string& config_help, const std::string& set_help) {
  c->add_option("--config", config_path, config_help)->check(NonEmpty("a YAML file"))->check(CLI::ExistingFile);
  c->add_option("--set", sets, set_help)->type_name("KEY=VALUE")->check(NonEmpty("KEY=VALUE"));
}

void ConfigArgs::AddSkin(CLI::App* c, const std::string& help) {
  c->add_option("--skin", skin, help)->check(NonEmpty("one of smooth, fingerprint-v1, fingerprint-v2"));
}

void ConfigArgs::AddCamera(CLI::App* c) {
  c->add_option("--camera", camera,
                "Camera preset: tactip-640x480 (the default camera: the real 127-pin TacTip's, outer ring 131 px), "
                "pose-dataset-256 (the 256x256 crops of the public TacTip pose datasets, outer ring 84 px) or legacy "
                "(f = 580 px and independent 0.28 px noise, as before the real-camera calibration); sets sensor.* "
                "keys after --skin, before --set.")
      ->check(CLI::IsMember(CameraPresetNames()));
}

void ConfigArgs::AddImages(CLI::App* c) {
  c->add_flag("--images", images,
              "Shortcut for --set images.enabled=true: render every sensor's camera frames, run the blob pipeline on "
              "them and store images, pins/detected_px and pins/detected_valid (see 'tactip config rail', images.*).");
}

void ConfigArgs::AddAutoTimestep(CLI::App* c) {
  c->add_flag("--auto-timestep", auto_timestep,
              "Choose sim.timestep_s: the largest step that is stable for every timestep-limiting mode (damping "
              "as configured), at most the configured sim.timestep_s (2 ms unless set), contact.timeconst_s / 2 and "
              "one camera frame, rounded down to a whole fraction of the frame period. Prints it on stderr.");
}

namespace {

// The --auto-timestep line on stderr, when a step was chosen.
void ReportTimestep(const std::optional<TimestepChoice>& choice) {
  if (!choice) return;
  const TimestepChoice& t = *choice;
  ProgressF(
               "auto-timestep: sim.timestep_s = %.6g s (bound %.6g s by %s; largest stable step %.6g s, set by %s)\n",
               t.timestep_s, t.bound_s, t.binding.c_str(), t.stable_s, t.stable_mode.c_str());
}

}  // namespace

void CheckAndReport(const Scenario& scenario, const ConfigSource& src) { ReportTimestep(scenario.Check(src)); }

RailScenarioConfig ResolveRailAndReport(const Scenario& scenario, const ConfigSource& src) {
  Resolved<RailScenarioConfig> r = RailFamily(scenario).Resolve(src);
  ReportTimestep(r.timestep);
  return std::move(r.config);
}

ConfigSource ConfigArgs::Source() const {
  ConfigSource src;
  src.auto_timestep = auto_timestep;
  src.yaml_path = config_path;
  if (!skin.empty()) src.overrides = SkinPresetOverrides(skin);
  if (!camera.empty()) {
    const std::vector<std::string> keys = CameraPreset(camera);
    src.overrides.insert(src.overrides.end(), keys.begin(), keys.end());
  }
  if (!std::isnan(speed_mm_s)) src.overrides.push_back(fmt::format("rail.retract_speed_mm_s={}", speed_mm_s));
  if (!stimulus.empty()) src.overrides.push_back("rail.stimulus=" + stimulus);
  if (images) src.overrides.push_back("images.enabled=true");
  src.overrides.insert(src.overrides.end(), sets.begin(), sets.end());
  return src;
}

CLI::Option* AddSensorOption(CLI::App* c, std::string& sensor) {
  return c->add_option("--sensor", sensor,
                       "Sensor of the dataset whose pins to read (default: its first; 'tactip info' lists them).")
      ->check(NonEmpty("a sensor name (see 'tactip info')"));
}

namespace {

/// "tactip: 331 pins, skin_pattern smooth; left: 127 pins": the sensors of `run`.
std::string SensorsText(const RunRecord& run) {
  std::string out;
  for (const SensorRecord& s : run.sensors) {
    out += fmt::format("{}{}: {} pins", out.empty() ? "" : "; ", s.name, s.n_pins);
    for (const auto& [key, value] : s.text_attrs) out += fmt::format(", {} {}", key, value);
  }
  return out;
}

}  // namespace

bool FlaggedByHealth(const RunRecord& r) {
  const double ok = Attr(r, "health_ok");
  return !std::isnan(ok) && ok <= 0.0;
}

void PrintDatasetSummary(const std::string& path, bool with_config) {
  DatasetReader reader(path);
  const auto& h = reader.header();
  const auto& runs = reader.run_indices();
  // Every run is read (and checked) before anything is printed.
  std::vector<RunRecord> summaries;
  for (int idx : runs) summaries.push_back(reader.ReadRunSummary(idx));
  std::printf("dataset      %s\n", path.c_str());
  std::printf("scenario     %s (tactip %s, seed %llu)\n", h.scenario.c_str(), h.tactip_version.c_str(),
              static_cast<unsigned long long>(h.seed));
  if (h.shard) {
    std::printf("shard        %s: %s ('tactip merge' joins the shards)\n", h.shard->text().c_str(),
                h.shard->runs_text().c_str());
  }
  std::printf("sensors      %s%s\n", SensorsText(summaries.front()).c_str(),
              h.layout_version < kDatasetLayoutVersion ? fmt::format(" (layout {})", h.layout_version).c_str() : "");
  std::printf("runs         %zu\n", runs.size());
  std::printf("%5s %7s %9s %10s %10s %10s %8s %9s %8s %9s %7s\n", "run", "frames", "length_s", "onset_s", "fall_s",
              "coulomb_s", "mu", "depth_mm", "v_mm_s", "creep_um", "health");
  size_t frames = 0;
  int slipped = 0;
  double err_sum = 0.0;
  int err_n = 0;
  std::vector<std::string> flagged;
  for (const RunRecord& r : summaries) {
    const int idx = r.index;
    frames += r.frames();
    const double onset = Attr(r, "gross_slip_onset_s");
    const double pred = Attr(r, "predicted_onset_s");
    if (!std::isnan(onset)) ++slipped;
    if (!std::isnan(onset) && !std::isnan(pred)) {
      err_sum += std::abs(onset - pred);
      ++err_n;
    }
    // Run health: ok, flagged (with the reason listed below), or not measured (older files).
    const bool run_flagged = FlaggedByHealth(r);
    const char* health = std::isnan(Attr(r, "health_ok")) ? "-" : (run_flagged ? "FLAGGED" : "ok");
    if (run_flagged) {
      auto it = r.text_attrs.find("health_reason");
      flagged.push_back(fmt::format("run {}: {}", idx, it == r.text_attrs.end() ? "" : it->second));
    }
    std::printf("%5d %7zu %9.2f %10s %10s %10s %8.4f %9.3f %8.3f %9s %7s\n", idx, r.frames(),
                r.frames() ? r.time.back() : 0.0, Fmt(onset).c_str(), Fmt(Attr(r, "object_fall_s")).c_str(),
                Fmt(pred).c_str(), Attr(r, "friction_coefficient"), Attr(r, "press_depth_mm"),
                Attr(r, "retract_speed_mm_s"), Fmt(Attr(r, "creep_um"), "{:.2f}").c_str(), health);
  }
  std::printf("total        %zu frames; gross slip in %d of %zu runs", frames, slipped, runs.size());
  if (err_n > 0) std::printf("; mean |onset - Coulomb prediction| = %.1f ms", 1e3 * err_sum / err_n);
  std::printf("\n");
  if (!flagged.empty()) {
    std::printf("health       %zu run(s) FLAGGED (health_ok = 0); their ground truth is not to be trusted:\n",
                flagged.size());
    for (const auto& f : flagged) std::printf("  %s\n", f.c_str());
  }
  if (with_config) std::printf("config:\n%s", h.config_yaml.c_str());
}

std::vector<int> FlaggedRuns(const DatasetReader& reader, const std::vector<int>& runs) {
  const std::vector<int>& present = reader.run_indices();
  std::vector<int> flagged;
  for (int idx : runs.empty() ? present : runs) {
    if (!std::binary_search(present.begin(), present.end(), idx)) continue;
    if (FlaggedByHealth(reader.ReadRunSummary(idx))) flagged.push_back(idx);
  }
  std::sort(flagged.begin(), flagged.end());
  flagged.erase(std::unique(flagged.begin(), flagged.end()), flagged.end());
  return flagged;
}

void NoteFlaggedRuns(const DatasetReader& reader, const std::string& path, const std::vector<int>& runs) {
  const std::vector<int> flagged = FlaggedRuns(reader, runs);
  if (flagged.empty()) return;
  const size_t read = runs.empty() ? reader.run_indices().size() : runs.size();
  ProgressF(
               "tactip: note: %zu of the %zu run(s) read from '%s' are flagged by run health (health_ok = 0): "
               "run(s) %s; their ground truth is not to be trusted ('tactip info %s' gives the reasons)\n",
               flagged.size(), read, path.c_str(), fmt::format("{}", fmt::join(flagged, ", ")).c_str(), path.c_str());
}

void NoteFlaggedRuns(const std::string& path, const std::vector<int>& runs) {
  if (std::filesystem::path(path).extension() == ".csv") return;
  NoteFlaggedRuns(DatasetReader(path), path, runs);
}

}  // namespace tactip::cli
