#include "scenarios/studies/stability/stability_suite.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "sim/base/nan.h"
#include "sim/base/number_text.h"
#include "sim/config.h"
#include "sim/simulation.h"

namespace tactip {

namespace {

constexpr std::uint64_t kSeed = 1;  // every case simulates run 0 of this master seed

using E = ExpectHeld;

// Every stimulus on every skin: the smooth skin and both fingerprint skins on each stimulus.
std::vector<StabilityCase> StimulusSkinCases() {
  std::vector<StabilityCase> out;
  const std::pair<const char*, const char*> skins[] = {
      {"smooth", "smooth"}, {"v1", "fingerprint-v1"}, {"v2", "fingerprint-v2"}};
  for (const auto& [tag, skin] : skins) {
    for (const char* stim : {"flat", "acrylic", "curved80", "curved40", "curved20"}) {
      out.push_back({fmt::format("{}-{}", tag, stim), fmt::format("the {} skin on the {} stimulus", skin, stim), skin,
                     {fmt::format("rail.stimulus={}", stim)}, E::kAny});
    }
  }
  return out;
}

// Stiff skins and stiff couplings: modes whose limit falls below the configured step.
std::vector<StabilityCase> StiffnessCases() {
  return {
      // Stiff skins: the pin normal mode's limit falls below the 2 ms step.
      {"gel-x100", "gel 100x stiffer (10 MPa): pin normal mode omega x10", "", {"skin.gel_modulus_kpa=10000"}},
      {"gel-x100-auto-dt", "the same at the step --auto-timestep picks", "", {"skin.gel_modulus_kpa=10000"}, E::kHeld,
       true},
      {"skin-x100", "skin rubber 100x stiffer (100 MPa): bending coupling x100", "", {"skin.skin_modulus_mpa=100"}},
      {"skin-x100-auto-dt", "the same at the step --auto-timestep picks", "", {"skin.skin_modulus_mpa=100"}, E::kHeld,
       true},
      {"gel-skin-x100-auto-dt", "gel and skin 100x stiffer at the step --auto-timestep picks", "",
       {"skin.gel_modulus_kpa=10000", "skin.skin_modulus_mpa=100"}, E::kHeld, true},
      {"v1-auto-dt", "fingerprint-v1 at the step --auto-timestep picks", "fingerprint-v1", {}, E::kAny, true},
      {"v2-auto-dt", "fingerprint-v2 at the step --auto-timestep picks (its shear mode, damping not raised)",
       "fingerprint-v2", {}, E::kAny, true},
      {"v2-gel-x100", "fingerprint-v2 with the gel 100x stiffer (the membrane raises its damping)", "fingerprint-v2",
       {"skin.gel_modulus_kpa=10000"}},
      {"v1-skin-x100", "fingerprint-v1 with the skin 100x stiffer (membrane links x100)", "fingerprint-v1",
       {"skin.skin_modulus_mpa=100"}},
      // Dome springs: each pin's gel spring along its dome normal is k_n / cos^2(theta), damped
      // through its normal and shear joints in series (SkinMechanics::DomeSpringDamping).
      {"v2-dome", "fingerprint-v2 with dome springs", "fingerprint-v2", {"skin.normal_spring=dome"}},
      {"v2-dome-central-0.25ms", "the same with central links at 0.25 ms, its best E/W and S/N figures",
       "fingerprint-v2", {"skin.normal_spring=dome", "skin.membrane_links=central", "sim.timestep_s=0.00025"}},
      {"v1-dome", "fingerprint-v1 with dome springs (refused: its edge pins flicker while held)", "fingerprint-v1",
       {"skin.normal_spring=dome"}},
      // A clamped rim on a thin, stiff skin: the annulus (E t) outgrows the bending coupling (E t^3)
      // and the smooth shell's in-plane mode limits the step.
      {"rim-thin-x100", "clamped rim, 0.1 mm skin 100x stiffer: the shell's in-plane mode omega x11", "",
       {"skin.rim=clamped", "skin.thickness_mm=0.1", "skin.skin_modulus_mpa=100"}},
      {"rim-thin-x100-auto-dt", "the same at the step --auto-timestep picks", "",
       {"skin.rim=clamped", "skin.thickness_mm=0.1", "skin.skin_modulus_mpa=100"}, E::kHeld, true},
  };
}

// Loads beyond the rig's: object mass, friction, fast retraction.
std::vector<StabilityCase> LoadCases() {
  return {
      // Object mass from 5 g to 5 kg (the skin holds ~3 N at mu = 1).
      {"mass-5g", "a 5 g object (held to the end of the contact)", "", {"object.mass_kg=0.005"}, E::kHeld},
      {"mass-1kg", "a 1 kg object (9.8 N against ~3.3 N of friction: not held)", "", {"object.mass_kg=1"},
       E::kNotHeld},
      {"mass-5kg", "a 5 kg object (49 N: left behind during the lift)", "", {"object.mass_kg=5"}, E::kNotHeld},
      // Friction from 0.05 to 3.
      {"mu-0.05", "mu = 0.05 (0.17 N of friction against 0.98 N: not held)", "", {"contact.friction=0.05"},
       E::kNotHeld},
      {"mu-3", "mu = 3 (kinetic 1.8)", "", {"contact.friction=3"}, E::kHeld},
      {"mu-0.05-mass-5g", "mu = 0.05 holding a 5 g object", "", {"contact.friction=0.05", "object.mass_kg=0.005"},
       E::kHeld},
      {"mu-3-mass-5kg", "mu = 3 under a 5 kg object (10 N against 49 N)", "", {"contact.friction=3", "object.mass_kg=5"},
       E::kNotHeld},
      {"v2-mu-3", "fingerprint-v2, mu = 3", "fingerprint-v2", {"contact.friction=3"}, E::kHeld},
      {"v2-mu-3-auto-dt", "fingerprint-v2, mu = 3, at the step --auto-timestep picks", "fingerprint-v2",
       {"contact.friction=3"}, E::kHeld, true},
      {"v2-mu-0.05", "fingerprint-v2, mu = 0.05", "fingerprint-v2", {"contact.friction=0.05"}, E::kNotHeld},
      // Fast retraction.
      {"retract-10mm-s", "retraction at 10 mm/s", "", {"rail.retract_speed_mm_s=10"}, E::kHeld},
      {"retract-50mm-s", "retraction at 50 mm/s", "", {"rail.retract_speed_mm_s=50"}, E::kHeld},
      {"v2-retract-50mm-s", "fingerprint-v2, retraction at 50 mm/s", "fingerprint-v2", {"rail.retract_speed_mm_s=50"},
       E::kHeld},
  };
}

// Steps, ridge geometry, indentation depth, an empty contact and the incipient rig.
std::vector<StabilityCase> StepGeometryAndRigCases() {
  return {
      // Large steps (contact.timeconst_s >= 2 dt).
      {"dt-2.5ms", "2.5 ms step", "", {"sim.timestep_s=0.0025", "contact.timeconst_s=0.005"}, E::kHeld},
      {"dt-5ms", "5 ms step", "", {"sim.timestep_s=0.005", "contact.timeconst_s=0.01"}},
      {"dt-5ms-heavy-pins", "5 ms step with 1 g pins (pin mode omega / sqrt 5)", "",
       {"sim.timestep_s=0.005", "contact.timeconst_s=0.01", "skin.pin_mass_g=1"}, E::kHeld},
      {"dt-5ms-auto-dt", "5 ms asked for as the cap of --auto-timestep", "",
       {"sim.timestep_s=0.005", "contact.timeconst_s=0.01"}, E::kHeld, true},
      {"v2-dt-5ms", "fingerprint-v2 at a 5 ms step", "fingerprint-v2",
       {"sim.timestep_s=0.005", "contact.timeconst_s=0.01"}},
      // Ridges taller than their pitch.
      {"v1-ridge-8mm", "fingerprint-v1, 8 mm ridges on a 4 mm pitch", "fingerprint-v1", {"skin.ridge_height_mm=8"}},
      {"v2-ridge-6mm", "fingerprint-v2, 6 mm ridges on a 3 mm pitch", "fingerprint-v2", {"skin.ridge_height_mm=6"}},
      {"v2-ridge-10mm-pitch-2", "fingerprint-v2, 10 mm ridges on a 2 mm pitch", "fingerprint-v2",
       {"skin.ridge_height_mm=10", "skin.ridge_spacing_mm=2"}},
      // Indentation: at the 7 mm a TacTip tolerates, and beyond.
      {"depth-7mm", "7 mm indentation (the bound)", "", {"rail.press_depth_mm=7"}, E::kHeld},
      {"depth-7mm-curved20", "7 mm into the 20 mm sphere", "", {"rail.press_depth_mm=7", "rail.stimulus=curved20"},
       E::kHeld},
      {"v2-depth-7mm", "fingerprint-v2 pressed 7 mm", "fingerprint-v2", {"rail.press_depth_mm=7"}, E::kHeld},
      {"depth-7.5mm", "7.5 mm indentation (beyond the bound)", "", {"rail.press_depth_mm=7.5"}},
      {"depth-7mm-jitter", "7 mm with +-0.5 mm jitter (deepest 7.5 mm)", "",
       {"rail.press_depth_mm=7", "rail.press_depth_jitter_mm=0.5"}},
      // The sensor pressing nothing.
      {"empty-contact", "the press stops 1 mm short of the stimulus", "", {"rail.press_depth_mm=-1"}, E::kNotHeld},
      {"v2-empty-contact", "fingerprint-v2 stopping 1 mm short", "fingerprint-v2", {"rail.press_depth_mm=-1"},
       E::kNotHeld},
      // The incipient rig: v2 on acrylic, external camera, velocity weakening, per-pin spread.
      // At its own retraction speed: at the short protocol's 1 mm/s an edge pin sliding out of the
      // contact bounces off the object once during a precursor slip in some runs (flicker 3, at
      // 0.5 and 0.25 ms alike; docs/limitations.md 'Numerics').
      {"incipient-rig", "the incipient scenario's defaults on the short protocol, retracting at 0.3 mm/s", "",
       {"rail.retract_speed_mm_s=0.3"}, E::kHeld, false, "incipient"},
  };
}

std::vector<StabilityCase> BuildCases() {
  std::vector<StabilityCase> cases = StimulusSkinCases();
  for (const auto& group : {StiffnessCases(), LoadCases(), StepGeometryAndRigCases()}) {
    cases.insert(cases.end(), group.begin(), group.end());
  }
  return cases;
}

// Non-finite values in any recorded array.
bool AllFinite(const RunRecord& r) {
  const auto finite = [](const auto& v) {
    return std::all_of(v.begin(), v.end(), [](auto x) { return std::isfinite(static_cast<double>(x)); });
  };
  const auto sensor_finite = [&](const SensorRecord& s) {
    return finite(s.pos_px) && finite(s.pos_m) && finite(s.external_px) && finite(s.external_m) &&
           finite(s.normal_N) && finite(s.tangential_N);
  };
  return finite(r.time) && std::all_of(r.sensors.begin(), r.sensors.end(), sensor_finite) &&
         finite(r.object_height_m) && finite(r.actions.controls);
}

std::string Csv(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

const char* ExpectName(ExpectHeld e) {
  switch (e) {
    case ExpectHeld::kHeld: return "held";
    case ExpectHeld::kNotHeld: return "not held";
    default: return "any";
  }
}

}  // namespace

const std::vector<std::string>& StabilityProtocol() {
  static const std::vector<std::string> sets = {
      "sensor.noise_model=independent", "sensor.pixel_noise_px=0", "sensor.dropout_prob=0", "rail.press_depth_jitter_mm=0",
      "contact.friction_jitter=0", "rail.settle_s=0.1",            "rail.press_speed_mm_s=5",
      "rail.lift_mm=15",           "rail.lift_speed_mm_s=30",      "rail.hold_s=0.2",
      "rail.retract_speed_mm_s=1", "rail.post_fall_s=0.1",
  };
  return sets;
}

const std::vector<StabilityCase>& StabilityCases() {
  static const std::vector<StabilityCase> cases = BuildCases();
  return cases;
}

const StabilityCase& FindStabilityCase(const std::string& name) {
  for (const auto& c : StabilityCases()) {
    if (c.name == name) return c;
  }
  throw InputError("--case '" + name + "': unknown case ('tactip stability --list' lists them)");
}

std::vector<const StabilityCase*> ChooseStabilityCases(const std::vector<std::string>& names) {
  std::vector<const StabilityCase*> chosen;
  if (names.empty()) {
    for (const auto& c : StabilityCases()) chosen.push_back(&c);
  }
  for (const auto& n : names) chosen.push_back(&FindStabilityCase(n));
  return chosen;
}

ConfigSource StabilityCaseSource(const StabilityCase& c, const std::vector<std::string>& sets) {
  ConfigSource src;
  src.overrides = StabilityProtocol();
  if (!c.skin.empty()) {
    const auto preset = SkinPresetOverrides(c.skin);
    src.overrides.insert(src.overrides.end(), preset.begin(), preset.end());
  }
  src.overrides.insert(src.overrides.end(), sets.begin(), sets.end());
  src.overrides.insert(src.overrides.end(), c.sets.begin(), c.sets.end());
  src.auto_timestep = c.auto_timestep;
  return src;
}

const char* OutcomeName(CaseOutcome o) {
  switch (o) {
    case CaseOutcome::kHealthy: return "healthy";
    case CaseOutcome::kRefused: return "refused";
    default: return "FAILED";
  }
}

std::string CaseSettings(const StabilityCase& c) {
  std::string s;
  if (c.scenario != "rail") s += "scenario " + c.scenario;
  if (!c.skin.empty()) s += (s.empty() ? "" : " ") + std::string("--skin ") + c.skin;
  for (const auto& k : c.sets) s += (s.empty() ? "" : " ") + k;
  if (c.auto_timestep) s += (s.empty() ? "" : " ") + std::string("--auto-timestep");
  return s.empty() ? "-" : s;
}

bool RefusalIsClear(const std::string& message, const std::vector<std::string>& keys) {
  if (message.empty() || message.find('\n') != std::string::npos) return false;
  const bool names_key = std::any_of(keys.begin(), keys.end(), [&](const std::string& k) {
    return message.rfind(k + " = ", 0) == 0;
  });
  const bool safe_value = message.find("use ") != std::string::npos || message.find("must be ") != std::string::npos;
  return names_key && safe_value;
}

void CheckSuiteSets(const std::vector<std::string>& sets, const std::vector<const StabilityCase*>& cases) {
  if (sets.empty()) return;
  for (const std::string& kv : sets) ParseAssignment(kv);  // malformed: the config's own refusal, no scenario's
  std::vector<std::string> scenarios;
  for (const StabilityCase* c : cases) {
    if (std::find(scenarios.begin(), scenarios.end(), c->scenario) == scenarios.end()) scenarios.push_back(c->scenario);
  }
  for (const std::string& name : scenarios) {
    ConfigSource src;
    src.overrides = StabilityProtocol();
    src.overrides.insert(src.overrides.end(), sets.begin(), sets.end());
    try {
      FindScenario(name).Check(src);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--set: {} (on the {} scenario's defaults)", e.what(), name));
    }
  }
}

StabilityResult RunStabilityCase(const StabilityCase& c, const std::atomic<bool>* stop,
                                 const std::vector<std::string>& sets) {
  const auto wall0 = std::chrono::steady_clock::now();
  StabilityResult r;
  r.c = &c;
  r.timestep_s = kNaN;
  r.suite_sets = sets;
  const auto finish = [&](CaseOutcome o, std::string message) {
    r.outcome = o;
    r.message = std::move(message);
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return r;
  };
  // Before it runs: the config's bounds and rules, incl. the stability check.
  const RailFamilyScenario& registered = RailFamily(FindScenario(c.scenario));
  RailScenarioConfig cfg;
  try {
    cfg = registered.Load(StabilityCaseSource(c, sets));
  } catch (const InputError& e) {
    std::vector<std::string> keys;
    for (const auto& f : registered.Describe(ConfigSource{})) keys.push_back(f.key);
    if (RefusalIsClear(e.what(), keys)) return finish(CaseOutcome::kRefused, e.what());
    return finish(CaseOutcome::kFailed, std::string("refused without naming a parameter and a safe value: ") + e.what());
  }
  r.timestep_s = cfg.sim.timestep_s;
  // The run: any MuJoCo warning or non-finite value, unhealthy figures, or an object that
  // Coulomb says must (not) be held.
  try {
    const RailScenario scenario(cfg);
    RunRecord rec;
    const RailRunSummary s = scenario.Run(0, kSeed, rec, stop);
    r.run = s;
    if (s.mujoco_warnings > 0) {
      return finish(CaseOutcome::kFailed, fmt::format("{} MuJoCo warning(s)", s.mujoco_warnings));
    }
    if (!AllFinite(rec)) return finish(CaseOutcome::kFailed, "non-finite values in the recorded run");
    if (!s.health.ok) return finish(CaseOutcome::kFailed, "unhealthy: " + s.health.reason);
    if ((c.held == ExpectHeld::kHeld && !s.held) || (c.held == ExpectHeld::kNotHeld && s.held)) {
      return finish(CaseOutcome::kFailed, fmt::format("the object was {}held; Coulomb friction says {}",
                                                      s.held ? "" : "not ", ExpectName(c.held)));
    }
    return finish(CaseOutcome::kHealthy, "");
  } catch (const SimulationError& e) {
    return finish(CaseOutcome::kFailed, std::string("crashed: ") + e.what());
  } catch (const ModelError& e) {
    return finish(CaseOutcome::kFailed, std::string("the model does not build: ") + e.what());
  }
}

std::vector<StabilityResult> RunStabilitySuite(const StabilityOptions& opts) {
  const std::vector<const StabilityCase*> todo = ChooseStabilityCases(opts.cases);
  CheckSuiteSets(opts.sets, todo);
  const int total = static_cast<int>(todo.size());
  const int jobs = std::max(
      1, std::min(total, opts.jobs > 0 ? opts.jobs : static_cast<int>(std::thread::hardware_concurrency())));
  // Workers take cases in order; after the first exception (an interruption) no case starts.
  std::vector<StabilityResult> results(todo.size());
  std::mutex mu;
  int next = 0, done = 0;
  std::exception_ptr failure;
  auto worker = [&] {
    for (;;) {
      int i;
      {
        std::lock_guard lock(mu);
        if (failure || next >= total) return;
        i = next++;
      }
      try {
        if (opts.stop && opts.stop->load()) throw Interrupted();
        StabilityResult res = RunStabilityCase(*todo[i], opts.stop, opts.sets);
        std::lock_guard lock(mu);
        results[i] = std::move(res);
        ++done;
        if (opts.progress) opts.progress(done, total, results[i]);
      } catch (...) {
        std::lock_guard lock(mu);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  return results;
}

std::string FormatStabilityCases(const std::vector<StabilityCase>& cases) {
  std::string out = fmt::format("{:<24} {:<9} {}\n", "case", "expects", "what it tests / what it sets");
  for (const auto& c : cases) {
    out += fmt::format("{:<24} {:<9} {}\n{:<34} {}\n", c.name, ExpectName(c.held), c.what, "", CaseSettings(c));
  }
  return out;
}

std::string FormatStabilityTable(const std::vector<StabilityResult>& results) {
  std::string out;
  if (!results.empty() && !results.front().suite_sets.empty()) {
    out += fmt::format("every case with --set {} (after its skin preset, before its own keys)\n",
                       fmt::join(results.front().suite_sets, " "));
  }
  out += fmt::format("{:<24} {:<8} {:>6} {:>8} {:>8} {:>6} {:>8} {:>8} {:>8} {:>7} {:>6} {:>6}  {}\n",
                                "case", "outcome", "dt_ms", "held", "onset_s", "flick", "speed_px", "creep_um",
                                "e_gain", "sim_s", "wall_s", "exp", "sets");
  for (const auto& r : results) {
    const StabilityCase& c = *r.c;
    const std::string dt = NumberCell(r.timestep_s * 1e3, "{:.3g}");
    if (r.run) {
      const RailRunSummary& s = *r.run;
      out += fmt::format("{:<24} {:<8} {:>6} {:>8} {:>8} {:>6} {:>8} {:>8} {:>8} {:>7.2f} {:>6.2f} {:>6}  {}\n", c.name,
                         OutcomeName(r.outcome), dt, s.held ? "yes" : "no", NumberCell(s.gross_slip_onset_s, "{:.3f}"),
                         s.health.flicker_max, NumberCell(s.health.pin_speed_px, "{:.3f}"),
                         NumberCell(s.health.stick_creep_um, "{:.2f}"), NumberCell(s.health.energy_gain, "{:.1e}"), s.sim_time_s,
                         r.wall_time_s, c.held == ExpectHeld::kAny ? "-" : (c.held == ExpectHeld::kHeld ? "yes" : "no"),
                         CaseSettings(c));
    } else {
      out += fmt::format("{:<24} {:<8} {:>6} {:>8} {:>8} {:>6} {:>8} {:>8} {:>8} {:>7} {:>6.2f} {:>6}  {}\n", c.name,
                         OutcomeName(r.outcome), dt, "-", "-", "-", "-", "-", "-", "-", r.wall_time_s,
                         c.held == ExpectHeld::kAny ? "-" : (c.held == ExpectHeld::kHeld ? "yes" : "no"),
                         CaseSettings(c));
    }
    if (!r.message.empty()) out += fmt::format("    {}\n", r.message);
  }
  int healthy = 0, refused = 0, failed = 0;
  for (const auto& r : results) {
    healthy += r.outcome == CaseOutcome::kHealthy;
    refused += r.outcome == CaseOutcome::kRefused;
    failed += r.outcome == CaseOutcome::kFailed;
  }
  out += fmt::format("{} case(s): {} healthy, {} refused, {} FAILED\n", results.size(), healthy, refused, failed);
  return out;
}

std::string StabilityCsv(const std::vector<StabilityResult>& results) {
  std::string out =
      "case,scenario,sets,expect,outcome,timestep_s,held,gross_slip_onset_s,object_fall_s,predicted_onset_s,"
      "flicker_max,pin_speed_px,stick_creep_um,energy_gain,mujoco_warnings,sim_time_s,wall_time_s,message,"
      "suite_sets\n";
  for (const auto& r : results) {
    const StabilityCase& c = *r.c;
    out += fmt::format("{},{},{},{},{},{},", Csv(c.name), Csv(c.scenario), Csv(CaseSettings(c)), ExpectName(c.held),
                       OutcomeName(r.outcome), NumberCell(r.timestep_s, "{}"));
    if (r.run) {
      const RailRunSummary& s = *r.run;
      out += fmt::format("{},{},{},{},{},{},{},{},{},{},", s.held ? 1 : 0, NumberCell(s.gross_slip_onset_s, "{}"),
                         NumberCell(s.object_fall_s, "{}"), NumberCell(s.predicted_onset_s, "{}"), s.health.flicker_max,
                         NumberCell(s.health.pin_speed_px, "{}"), NumberCell(s.health.stick_creep_um, "{}"),
                         NumberCell(s.health.energy_gain, "{}"), s.mujoco_warnings, NumberCell(s.sim_time_s, "{}"));
    } else {
      out += ",,,,,,,,,,";
    }
    out += fmt::format("{},{},{}\n", NumberCell(r.wall_time_s, "{:.3f}"), Csv(r.message),
                       Csv(fmt::format("{}", fmt::join(r.suite_sets, " "))));
  }
  return out;
}

}  // namespace tactip
