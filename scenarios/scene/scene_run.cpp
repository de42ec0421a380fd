#include "scenarios/scene/scene_run.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "sim/base/errors.h"

namespace tactip {

namespace {

std::vector<std::string> Prefixes(const Scene& scene) {
  std::vector<std::string> out;
  for (const SceneSensor& s : scene.sensors) out.push_back(s.prefix);
  return out;
}

}  // namespace

SceneRun::SceneRun(const Scene& scene, const SceneRunSettings& settings, const ProtocolTimeline& timeline,
                   const RunDraws& draws, SceneController& controller)
    : scene_(scene),
      settings_(settings),
      timeline_(timeline),
      draws_(draws),
      controller_(controller),
      model_(scene.model->Copy()),
      clock_(settings.sim.timestep_s, scene.frame_rate_hz()),
      watch_(scene.object, timeline, settings.labels, scene.model->gravity(), scene.sensors.size()),
      controls_(scene.actuators.size(), 0.0),
      end_time_(timeline.give_up_s),
      frame_input_{0.0, std::vector<const PinFrame*>(scene.sensors.size(), nullptr)},
      readings_(scene.sensors.size(), nullptr),
      stuck_(scene.sensors.size(), 0.0),
      health_(scene.total_pins(), settings.health),
      health_px_(2 * static_cast<size_t>(scene.total_pins())),
      health_contact_(static_cast<size_t>(scene.total_pins())) {
  // The sensors (their pins' friction set in this run's model), the shell's damper, the
  // initial state and the markers' rest positions.
  AddChannels();
  const SceneSensor& first = scene.sensors.front();
  shell_damping_ = ShellDamping(first.skin, scene.object.mass_kg, Prefixes(scene), model_, first.n_pins);
  model_.EnableEnergy();
  sim_.emplace(model_);
  sim_->Forward();
  for (SensorChannel& ch : channels_) ch.sensor.Rest(*sim_);
}

void SceneRun::AddChannels() {
  channels_.reserve(scene_.sensors.size());
  for (size_t k = 0; k < scene_.sensors.size(); ++k) {
    channels_.push_back(SensorChannel::Make(scene_.sensors[k], k, draws_.run_seed, draws_.mu,
                                            scene_.object.contact_geom, settings_.contact, settings_.labels,
                                            settings_.images, model_));
    friction_switching_ = friction_switching_ || channels_.back().friction.switching();
  }
}

void SceneRun::InitRecord(RunRecord& rec) {
  // A group per tactile sensor, and the scene's actuators as the controls.
  const size_t expect = static_cast<size_t>((timeline_.give_up_s + 1.0) * scene_.frame_rate_hz());
  std::vector<SensorGroup> groups;
  for (const SensorChannel& ch : channels_) groups.push_back({ch.sensor.name(), ch.sensor.n_pins()});
  recorder_.emplace(rec, draws_.index, groups, scene_.built.actuators, std::min<size_t>(expect, 200000));
}

void SceneRun::Instrument(RunInstrumentation* out) {
  instrument_ = out;
  sim_->EnableProfile();
}

SceneRunSummary SceneRun::Execute(RunRecord& rec, const std::atomic<bool>* stop) {
  for (;;) {
    if (stop && stop->load(std::memory_order_relaxed)) throw Interrupted();
    if (!Step(rec)) break;
  }
  return Finish(rec);
}

bool SceneRun::Step(RunRecord& rec) {
  if (!started_) {
    wall0_ = std::chrono::steady_clock::now();
    InitRecord(rec);
    started_ = true;
  }
  const long long n = clock_.step();
  const double t = clock_.StepTime(n);
  if (t > end_time_ || controller_.Done(t)) return false;
  // The controller's controls, one physics step.
  ApplyControls(t);
  sim_->Step();
  clock_.Advance();
  ++steps_;
  const bool held = t >= timeline_.held_s && std::isnan(watch_.onset_s());
  if (held) health_.Step(sim_->energy_created_J(), sim_->elastic_energy_J());

  // Between frames the contacts are read only while the onset (exact, at step resolution)
  // and its Coulomb prediction are still being searched for, or while friction switches.
  const bool frame_now = clock_.FrameDue(n);
  const bool seek_onset = t >= timeline_.load_s && std::isnan(watch_.onset_s());
  const bool seek_prediction = t >= timeline_.release_s && std::isnan(watch_.predicted_onset_s());
  if (!frame_now && !seek_onset && !seek_prediction && !friction_switching_) return true;
  ReadContacts(t);
  if (shell_damping_.active()) UpdateShellDamping();
  if (watch_.n_slip() > 0) slipped_since_frame_ = true;
  for (SensorChannel& ch : channels_) {
    if (ch.friction.switching()) ch.friction.Update(ch.sensor.samples(), ch.sensor.pin_slip(), model_);
  }
  watch_.TrackFirstSlips(t, channels_);
  const OnsetStep onset = watch_.TrackOnset(t, seek_onset, clock_.frame());
  if (onset.all_slide_began) SwitchToSlidingStep();
  if (onset.gross_from_frame >= 0) recorder_->LabelGrossFrom(static_cast<size_t>(onset.gross_from_frame));
  if (seek_prediction) watch_.TrackPrediction(t);
  if (!frame_now) return true;

  // One camera frame: the state at step n (time t).
  const double tf = clock_.TakeFrame();
  RecordFrame(t, tf);
  const SensorChannel& first = channels_.front();
  const double obj_z = sim_->BodyPos(scene_.object.body)[2];
  const double rel_z = obj_z - first.sensor.pose().origin[2];
  const double creep_z = obj_z - sim_->SitePos(first.sensor.ids().pin_outer_site[0])[2];
  end_time_ = std::min(end_time_, watch_.TrackEvents(t, tf, rel_z, creep_z));
  TrackHealth(t);
  frame_input_.time_s = tf;
  controller_.OnFrame(frame_input_);
  return true;
}

void SceneRun::ApplyControls(double t) {
  controller_.Controls(t, controls_);
  for (size_t k = 0; k < controls_.size(); ++k) sim_->SetControl(scene_.actuators[k].id, controls_[k]);
  if (instrument_) RecordControls();
}

void SceneRun::RecordControls() {
  // The step's length, and the controls in actuator id order.
  std::vector<double>& c = instrument_->ctrl;
  const size_t base = c.size();
  c.resize(base + controls_.size());
  for (size_t k = 0; k < controls_.size(); ++k) c[base + static_cast<size_t>(scene_.actuators[k].id)] = controls_[k];
  instrument_->timestep_s.push_back(clock_.timestep_s());
}

void SceneRun::ReadContacts(double t) {
  for (SensorChannel& ch : channels_) ch.sensor.ReadContacts(*sim_);
  watch_.ReadContacts(t, channels_, *sim_, scene_.sensors.front().carrier_up_dof);
}

void SceneRun::UpdateShellDamping() {
  // Each sensor's stuck share of its contacting pins.
  for (size_t k = 0; k < channels_.size(); ++k) {
    const FrameLabels& labels = channels_[k].sensor.labels();
    stuck_[k] = labels.n_contact > 0 ? static_cast<double>(labels.n_contact - labels.n_slip) / labels.n_contact : 0.0;
  }
  shell_damping_.Update(stuck_);
}

void SceneRun::SwitchToSlidingStep() {
  // The release kicks the pins' normal modes as friction drops to kinetic: at a coarse step
  // some sliding contacts let go for a step (docs: 'Sliding contacts'). The steps before the
  // first all-slide step keep the configured step; the sliding phase is short.
  if (clock_.Refine(settings_.sim.SlidingTimestep())) model_.SetTimestep(clock_.timestep_s());
}

void SceneRun::RecordFrame(double t, double tf) {
  // Each sensor's frame, recorded with the gross-slip label, the object's height and the
  // controls at this frame; then its rendered image, the incipient slip and plausibility.
  for (size_t k = 0; k < channels_.size(); ++k) {
    frame_input_.frames[k] = &channels_[k].sensor.Capture(*sim_, tf);
    readings_[k] = &channels_[k].sensor.reading();
  }
  const double height = sim_->BodyPos(scene_.object.body)[2] - scene_.object.rest_height_m;
  recorder_->Frame(tf, readings_, watch_.gross(), height, controls_);
  for (size_t k = 0; k < channels_.size(); ++k) {
    SensorChannel& ch = channels_[k];
    if (!ch.imaging) continue;
    const CameraConfig& camera = scene_.sensors[k].spec.camera;
    const ImageReading& image = ch.imaging->Capture(ch.sensor.clean_px(), ch.sensor.reading().pos_m);
    recorder_->Images(k, image, camera.width_px, camera.height_px);
  }
  watch_.TrackIncipient(t, channels_);
  CheckPlausible(t);
}

void SceneRun::CheckPlausible(double t) const {
  std::string why;
  for (size_t k = 0; k < channels_.size() && why.empty(); ++k) {
    const TactileSensor& sensor = channels_[k].sensor;
    why = ImplausibleState(settings_.limits, sensor.marker_shift_m(), sensor.normal_N());
    if (!why.empty() && channels_.size() > 1) why = "sensor '" + sensor.name() + "': " + why;
  }
  if (why.empty()) return;
  throw SimulationError(fmt::format("run {} stopped at t = {:.4f} s: {}: the solver diverged without a MuJoCo warning; "
                                    "use a smaller sim.timestep_s or more sim.iterations",
                                    draws_.index, t, why));
}

void SceneRun::TrackHealth(double t) {
  // Held: from the hold's start until gross slip (a run whose object slipped during the load
  // is never held). Creep: the object relative to the first sensor's centre pin's contact
  // point, from the release on.
  const SensorChannel& first = channels_.front();
  const bool held = t >= timeline_.held_s && std::isnan(watch_.onset_s());
  const bool releasing = t >= timeline_.release_s;
  const double obj_z = sim_->BodyPos(scene_.object.body)[2];
  const double creep = releasing ? obj_z - sim_->SitePos(first.sensor.ids().pin_outer_site[0])[2]
                                 : std::numeric_limits<double>::quiet_NaN();
  // While held the sensor moves only along its pressing axis and the object only along the
  // vertical: a pin pushed quasi-statically, or carried by the object it sticks to, moves at
  // most as far as the sensor moves against the object, which the image shows at most
  // gain-fold. The pressing axis's motion is its actuator's commanded position.
  const int press = scene_.sensors.front().press_actuator;
  const double x = press >= 0 ? controls_[static_cast<size_t>(press)] : 0.0;
  const double rel_z = obj_z - first.sensor.pose().origin[2];
  const double quasi_static_px = have_prev_frame_ ? first.sensor.image_gain_px_m() *
                                                        std::hypot(x - prev_frame_press_, rel_z - prev_frame_rel_z_)
                                                  : 0.0;
  prev_frame_press_ = x;
  prev_frame_rel_z_ = rel_z;
  have_prev_frame_ = true;
  // The pins of all sensors, in sensor order.
  size_t at = 0;
  for (const SensorChannel& ch : channels_) {
    std::copy(ch.sensor.clean_px().begin(), ch.sensor.clean_px().end(), health_px_.begin() + 2 * static_cast<long>(at));
    std::copy(ch.sensor.pin_contact().begin(), ch.sensor.pin_contact().end(),
              health_contact_.begin() + static_cast<long>(at));
    at += static_cast<size_t>(ch.sensor.n_pins());
  }
  // Slip between frames counts too (contacts are read at every step while it matters).
  health_.Frame(held, releasing, health_px_.data(), health_contact_.data(), slipped_since_frame_, creep,
                quasi_static_px);
  slipped_since_frame_ = false;
}

SceneRunSummary SceneRun::Finish(RunRecord& rec) {
  if (!started_) InitRecord(rec);
  SceneRunSummary s;
  watch_.Fill(s, channels_);
  s.health = health_.Result();
  s.mujoco_warnings = sim_->WarningCount();
  s.steps = steps_;
  s.sim_time_s = clock_.StepTime(clock_.step());
  s.actions = controller_.Actions();
  s.controller_figures = controller_.Figures();
  WriteAttributes(s, rec);
  for (size_t k = 0; k < channels_.size(); ++k) recorder_->FirstSlips(k, watch_.FirstSlips(channels_[k]));
  rec.actions.list = s.actions;
  rec.CheckShapes();
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  if (instrument_) instrument_->profile = sim_->profile();
  return s;
}

void SceneRun::WriteAttributes(const SceneRunSummary& s, RunRecord& rec) const {
  // The object's events and the run's friction; run health; each sensor's skin.
  rec.attrs["gross_slip_onset_s"] = s.gross_slip_onset_s;
  rec.attrs["object_fall_s"] = s.object_fall_s;
  rec.attrs["object_mass_kg"] = scene_.object.mass_kg;
  rec.attrs["friction_coefficient"] = draws_.mu;
  rec.attrs["kinetic_friction_coefficient"] = draws_.mu * settings_.contact.kinetic_ratio;
  rec.attrs["predicted_onset_s"] = s.predicted_onset_s;
  rec.attrs["coulomb_early_s"] = s.coulomb_early_s;
  rec.attrs["creep_um"] = s.creep_um;
  rec.attrs["object_held"] = s.held ? 1.0 : 0.0;
  rec.attrs["incipient_onset_s"] = s.incipient_onset_s;
  rec.attrs["incipient_lead_s"] = s.incipient_lead_s;
  rec.attrs["pre_slip_fraction"] = s.pre_slip_fraction;
  rec.attrs["health_ok"] = s.health.ok ? 1.0 : 0.0;
  rec.attrs["flicker_max"] = s.health.flicker_max;
  rec.attrs["held_pin_speed_px"] = s.health.pin_speed_px;
  rec.attrs["stick_creep_um"] = s.health.stick_creep_um;
  rec.attrs["energy_gain"] = s.health.energy_gain;
  rec.text_attrs["health_reason"] = s.health.reason;
  for (size_t k = 0; k < rec.sensors.size(); ++k) rec.sensors[k].text_attrs["skin_pattern"] = scene_.sensors[k].skin.pattern;
}

}  // namespace tactip
