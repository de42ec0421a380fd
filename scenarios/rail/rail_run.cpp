#include "scenarios/rail/rail_run.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace tactip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kOffDropM = 10e-3;  // an object this far below its held position has left the skin

// A TacTip's cameras, noise and labelling, its ridge-rocking marker shift and its gel field.
TactileSensorSpec SensorSpec(const RailScenarioConfig& cfg, const std::string& name) {
  TactileSensorSpec spec;
  spec.name = name;
  spec.camera = cfg.sensor;
  spec.external = cfg.external;
  spec.labels = cfg.labels;
  const PinLattice lattice = PinLattice::Build(cfg.skin);
  const SkinMechanics mech = SkinMechanics::From(cfg.skin, lattice);
  spec.gel_field = GelField::Build(cfg.skin, lattice);
  if (cfg.skin.coupling == "membrane" && mech.k_rock_N_m > 0.0) {
    spec.marker_rock_m_N = mech.marker_rock_factor / mech.k_rock_N_m;
  }
  spec.apex_x_m = cfg.skin.OuterRadiusMm() * 1e-3;
  return spec;
}

}  // namespace

RailSceneIds::RailSceneIds(const RailScenarioConfig& cfg, const SceneOptions& options) {
  // Build and compile once; runs copy the model.
  RailSceneSpec spec = cfg.SceneSpec();
  spec.options = options;
  scene = BuildRailScene(spec);
  model.emplace(CompiledModel::FromXml(scene.xml));
  const CompiledModel& m = *model;
  servo_x = m.ActuatorId(RailNames::kServoX);
  servo_z = m.ActuatorId(RailNames::kServoZ);
  slider_body = m.BodyId(RailNames::kSlider);
  stimulus_geom = m.GeomId(RailNames::kStimulus);
  // The object's vertical DOF: the slide joint, or a free joint's third (z translation).
  slide_dof = m.JointDofAdr(m.JointId(RailNames::kSlide)) + (options.object_free_joint ? 2 : 0);
  arm_z_dof = m.JointDofAdr(m.JointId(RailNames::kArmZ));
  const std::vector<bool> outer = RailOuterSitePins(spec, static_cast<size_t>(scene.n_pins));
  for (const SensorMountConfig& mount : cfg.sensors) {
    sensors.push_back(TactileSensorIds::Find(m, RailNames::SensorMount(mount.name), scene.n_pins, outer,
                                             SkinNames{mount.Prefix()}));
    sensor_specs.push_back(SensorSpec(cfg, mount.name));
  }
}

RailRun::Draws RailRun::Draw(const RailScenarioConfig& c, std::uint64_t run_seed) {
  // Always draw both numbers so each stays on its own stream.
  Rng vary(DeriveSeed(run_seed, 0));
  Draws d;
  d.run_seed = run_seed;
  d.depth_m = (c.rail.press_depth_mm + vary.Uniform(-1.0, 1.0) * c.rail.press_depth_jitter_mm) * 1e-3;
  d.mu = c.contact.friction * (1.0 + vary.Uniform(-1.0, 1.0) * c.contact.friction_jitter);
  return d;
}

RailRun::RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, std::uint64_t seed,
                 RailController* controller)
    : RailRun(cfg, ids, index, Draw(cfg, DeriveSeed(seed, static_cast<std::uint64_t>(index))), controller) {}

RailRun::RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, const Draws& d,
                 RailController* controller)
    : c_(cfg),
      im_(ids),
      index_(index),
      n_(ids.scene.n_pins),
      depth_m_(d.depth_m),
      mu_(d.mu),
      model_(ids.model->Copy()),
      sched_(cfg.rail, d.depth_m),
      schedule_controller_(sched_),
      controller_(controller ? controller : &schedule_controller_),
      dt_(cfg.sim.timestep_s),
      weight_N_(cfg.object.mass_kg * ids.model->gravity()),
      next_frame_step_(FrameStep(0, cfg.sensor.frame_rate_hz, cfg.sim.timestep_s)),
      limits_(StateLimits::For(cfg, ids.scene.n_collidable, controller_->ExtraPressM())),
      health_(n_ * static_cast<int>(ids.sensors.size()), cfg.health),
      end_time_(sched_.give_up),
      prev_margin_(kNaN),
      prev_skin_(kNaN),
      rel_ref_(kNaN),
      lift_rel_ref_(kNaN),
      creep_ref_(kNaN) {
  AddChannels(cfg, d);
  shell_damping_ = ShellDamping(cfg, model_, n_);
  model_.EnableEnergy();
  sim_.emplace(model_);
  sim_->Forward();
  for (Channel& ch : channels_) ch.sensor.Rest(*sim_);
  sum_.press_depth_mm = depth_m_ * 1e3;
  sum_.friction = mu_;
  sum_.retract_start_s = sched_.retract_start;
  for (double* v : {&sum_.gross_slip_onset_s, &sum_.object_fall_s, &sum_.predicted_onset_s, &sum_.coulomb_early_s,
                    &sum_.incipient_onset_s, &sum_.incipient_lead_s, &sum_.pre_slip_fraction}) {
    *v = kNaN;
  }
}

void RailRun::AddChannels(const RailScenarioConfig& cfg, const Draws& d) {
  // Sensor k's noise streams and pin friction spread: the run's streams 1-3 for the first,
  // streams of its own below stream 100 + k for the others.
  channels_.reserve(im_.sensors.size());
  for (size_t k = 0; k < im_.sensors.size(); ++k) {
    const std::uint64_t base = k == 0 ? d.run_seed : DeriveSeed(d.run_seed, 100 + k);
    const TactileSensorIds& ids = im_.sensors[k];
    channels_.push_back(Channel{
        TactileSensor(im_.sensor_specs[k], ids, DeriveSeed(base, 1), DeriveSeed(base, 2)),
        FrictionLaw(cfg.contact, cfg.labels, d.mu, ids.pin_geom, im_.stimulus_geom, DeriveSeed(base, 3), model_),
        std::vector<double>(n_, kNaN), {}, std::vector<double>(n_, kNaN), std::nullopt});
    // Rendered images only when asked for (their pixel noise on stream 4).
    if (cfg.images.enabled) channels_.back().imaging.emplace(cfg.images, cfg.sensor, DeriveSeed(base, 4));
    friction_switching_ = friction_switching_ || channels_.back().friction.switching();
  }
  health_px_.resize(2 * static_cast<size_t>(n_) * channels_.size());
  health_contact_.resize(static_cast<size_t>(n_) * channels_.size());
}

void RailRun::InitRecord(RunRecord& rec) {
  // The scene's tactile sensors, and the arm's two servos as the controls.
  const size_t expect = static_cast<size_t>((sched_.give_up + 1.0) * c_.sensor.frame_rate_hz);
  std::vector<SensorGroup> groups;
  for (const Channel& ch : channels_) groups.push_back({ch.sensor.name(), n_});
  recorder_.emplace(rec, index_, groups, std::vector<std::string>{RailNames::kServoX, RailNames::kServoZ},
                    std::min<size_t>(expect, 200000));
}

void RailRun::RecordControls() {
  // The step's length, and the controls in actuator order (servo_x, servo_z are the scene's only actuators).
  std::vector<double>& c = instrument_->ctrl;
  const size_t base = c.size();
  c.resize(base + 2);
  c[base + static_cast<size_t>(im_.servo_x)] = arm_.x_m;
  c[base + static_cast<size_t>(im_.servo_z)] = arm_.z_m;
  instrument_->timestep_s.push_back(dt_);
}

void RailRun::Instrument(RunInstrumentation* out) {
  instrument_ = out;
  sim_->EnableProfile();
}

RailRunSummary RailRun::Execute(RunRecord& rec, const std::atomic<bool>* stop) {
  for (;;) {
    if (stop && stop->load(std::memory_order_relaxed)) throw Interrupted();
    if (!Step(rec)) break;
  }
  return Finish(rec);
}

bool RailRun::Step(RunRecord& rec) {
  if (!started_) {
    wall0_ = std::chrono::steady_clock::now();
    InitRecord(rec);
    started_ = true;
  }
  const long long n = step_;
  const double t = StepTime(n);
  if (t > end_time_ || controller_->Done(t)) return false;
  // Drive the arm servos with the controller's targets and advance one step.
  arm_ = controller_->Targets(t);
  sim_->SetControl(im_.servo_x, arm_.x_m);
  sim_->SetControl(im_.servo_z, arm_.z_m);
  if (instrument_) RecordControls();
  sim_->Step();
  ++step_;
  ++sum_.steps;
  const bool held = t >= sched_.lift_end && std::isnan(sum_.gross_slip_onset_s);
  if (held) health_.Step(sim_->energy_created_J(), sim_->elastic_energy_J());

  // Between frames the contacts are read only while the onset (exact, at step
  // resolution) and its Coulomb prediction are still being searched for, or while
  // friction switches.
  const bool frame_now = n == next_frame_step_;
  const bool seek_onset = t >= sched_.lift_start && std::isnan(sum_.gross_slip_onset_s);
  const bool seek_prediction = t >= sched_.retract_start && std::isnan(sum_.predicted_onset_s);
  if (!frame_now && !seek_onset && !seek_prediction && !friction_switching_) return true;
  ReadContacts();
  if (shell_damping_.active()) UpdateShellDamping();
  if (n_slip_ > 0) slipped_since_frame_ = true;
  for (Channel& ch : channels_) {
    if (ch.friction.switching()) ch.friction.Update(ch.sensor.samples(), ch.sensor.pin_slip(), model_);
  }
  TrackFirstSlips(t);
  TrackOnset(t, seek_onset);
  if (seek_prediction) TrackPrediction(t);
  if (!frame_now) return true;

  // One camera frame: the state at step n (time t).
  const double tf = static_cast<double>(frame_) / c_.sensor.frame_rate_hz;
  ++frame_;
  next_frame_step_ = NextFrameStep();
  RecordFrame(t, tf);
  TrackEvents(t, tf);
  TrackHealth(t);
  FrameInput frames{tf, {}};
  for (const Channel& ch : channels_) frames.frames.push_back(&ch.sensor.frame());
  controller_->OnFrame(frames);
  return true;
}

void RailRun::ReadContacts() {
  // Friction holds up to mu_s N in the rail's direction (it acts across the pressing
  // axis, which the rail is); a sloped contact's normal force also pushes along the rail.
  holding_N_ = 0.0;
  for (Channel& ch : channels_) {
    ch.sensor.ReadContacts(*sim_);
    const std::vector<double>& mu_pin = ch.friction.static_mu();
    for (int i = 0; i < n_; ++i) {
      const GeomContact& gc = ch.sensor.contacts()[i];
      holding_N_ += mu_pin[i] * gc.normal_N - gc.normal_N * gc.normal_world[2];
    }
  }
  ReadLabels();
}

void RailRun::UpdateShellDamping() {
  std::vector<double> stuck;
  for (const Channel& ch : channels_) {
    const FrameLabels& labels = ch.sensor.labels();
    stuck.push_back(labels.n_contact > 0 ? static_cast<double>(labels.n_contact - labels.n_slip) / labels.n_contact
                                         : 0.0);
  }
  shell_damping_.Update(stuck);
}

void RailRun::ReadLabels() {
  // Gross slip: every contacting pin of every sensor slides and the object moves along the
  // rail relative to the sensors (with rail friction the skin alone may creep under a still
  // object for a few frames first).
  n_contact_ = n_slip_ = 0;
  bool every_contact_slides = true;
  for (const Channel& ch : channels_) {
    const FrameLabels& labels = ch.sensor.labels();
    n_contact_ += labels.n_contact;
    n_slip_ += labels.n_slip;
    if (labels.n_contact > 0 && !labels.gross_slip) every_contact_slides = false;
  }
  all_slide_ = n_contact_ > 0 && every_contact_slides;
  const double obj_speed = std::abs(sim_->Qvel(im_.slide_dof) - sim_->Qvel(im_.arm_z_dof));
  gross_ = all_slide_ && obj_speed > c_.labels.slip_speed_m_s ? 1 : 0;
}

void RailRun::TrackOnset(double t, bool seek_onset) {
  // Gross onset, once the object is held: the first step of the uninterrupted run of steps in
  // which every contacting pin slides that brings the object into motion. The skin often lets
  // go a step before the object follows (its released shear springs back under the still
  // object); those steps and their frames are gross slip too.
  if (!seek_onset) return;
  if (!all_slide_) {
    all_slide_since_ = std::nan("");
    return;
  }
  if (std::isnan(all_slide_since_)) {
    all_slide_since_ = t;
    all_slide_frame_ = frame_;
    SwitchToSlidingStep();
  }
  if (!gross_) return;
  sum_.gross_slip_onset_s = all_slide_since_;
  recorder_->LabelGrossFrom(static_cast<size_t>(all_slide_frame_));
}

void RailRun::SwitchToSlidingStep() {
  // The release kicks the pins' normal modes as friction drops to kinetic: at a coarse step
  // some sliding contacts let go for a step (README 'Sliding contacts'). The steps before the
  // first all-slide step keep the configured step; the sliding phase is short.
  const double fine = c_.sim.SlidingTimestep();
  if (sliding_step_ || fine >= dt_) return;
  sliding_step_ = true;
  // The step just taken ran at the configured step: the next one starts where it ended.
  switch_time_ = StepTime(step_);
  switch_step_ = step_;
  dt_ = fine;
  model_.SetTimestep(fine);
  next_frame_step_ = NextFrameStep();
}

double RailRun::StepTime(long long n) const {
  return switch_time_ + static_cast<double>(n - switch_step_) * dt_;
}

long long RailRun::NextFrameStep() const {
  if (!sliding_step_) return FrameStep(frame_, c_.sensor.frame_rate_hz, dt_);
  const double tf = static_cast<double>(frame_) / c_.sensor.frame_rate_hz;
  return std::max(step_, switch_step_ + std::llround((tf - switch_time_) / dt_));
}

void RailRun::TrackPrediction(double t) {
  // Coulomb prediction from the simulated normal forces: the holding margin
  // sum(mu_i N_i) + normal push along the rail + rail friction - m g crosses zero between
  // two steps. The rail's static
  // friction (either sign, up to F_rail) shares the load in a statically undetermined way,
  // so the skin may start sliding anywhere between sum(mu_i N_i) = m g + F_rail and
  // sum(mu_i N_i) = m g - F_rail.
  const double margin = holding_N_ + c_.rail.friction_N - weight_N_;
  const double skin_margin = margin - 2.0 * c_.rail.friction_N;
  if (!std::isnan(prev_margin_) && prev_margin_ >= 0.0 && margin < 0.0) {
    sum_.predicted_onset_s = prev_t_ + (t - prev_t_) * prev_margin_ / (prev_margin_ - margin);
  }
  if (std::isnan(sum_.coulomb_early_s) && !std::isnan(prev_skin_) && prev_skin_ >= 0.0 && skin_margin < 0.0) {
    sum_.coulomb_early_s = prev_t_ + (t - prev_t_) * prev_skin_ / (prev_skin_ - skin_margin);
  }
  prev_margin_ = margin;
  prev_skin_ = skin_margin;
  prev_t_ = t;
}

void RailRun::RecordFrame(double t, double tf) {
  // Each sensor's frame, recorded with the gross-slip label, the object's height and the
  // arm's servo targets at this frame (in actuator order: servo_x, servo_z); then plausibility.
  std::vector<const SensorReading*> readings;
  for (Channel& ch : channels_) {
    ch.sensor.Capture(*sim_, tf);
    readings.push_back(&ch.sensor.reading());
  }
  const double height = sim_->BodyPos(im_.slider_body)[2] - RailLayout::kAxisHeight;
  recorder_->Frame(tf, readings, gross_, height, {arm_.x_m, arm_.z_m});
  for (size_t k = 0; k < channels_.size(); ++k) {
    // The camera's image of the frame and the blob pipeline's pins (images.enabled).
    Channel& ch = channels_[k];
    if (!ch.imaging) continue;
    const ImageReading& image = ch.imaging->Capture(ch.sensor.clean_px(), ch.sensor.reading().pos_m);
    recorder_->Images(k, image, c_.sensor.width_px, c_.sensor.height_px);
  }
  TrackIncipient(t);
  CheckPlausible(t);
}

void RailRun::CheckPlausible(double t) const {
  std::string why;
  for (size_t k = 0; k < channels_.size() && why.empty(); ++k) {
    const TactileSensor& sensor = channels_[k].sensor;
    why = ImplausibleState(limits_, sensor.marker_shift_m(), sensor.normal_N());
    if (!why.empty() && channels_.size() > 1) why = "sensor '" + sensor.name() + "': " + why;
  }
  if (why.empty()) return;
  throw SimulationError(fmt::format("run {} stopped at t = {:.4f} s: {}: the solver diverged without a MuJoCo warning; "
                                    "use a smaller sim.timestep_s or more sim.iterations",
                                    index_, t, why));
}

void RailRun::TrackIncipient(double t) {
  // Incipient slip: partial slip from the retraction on, before gross slip.
  if (t < sched_.retract_start || !std::isnan(sum_.gross_slip_onset_s)) return;
  for (Channel& ch : channels_) {
    const std::vector<std::uint8_t>& slip = ch.sensor.pin_slip();
    if (!retract_seen_) ch.contact_at_retract = ch.sensor.pin_contact();
    for (int i = 0; i < n_; ++i) {
      if (ch.contact_at_retract[i] && slip[i] && std::isnan(ch.first_slip_frame_s[i])) ch.first_slip_frame_s[i] = t;
    }
  }
  retract_seen_ = true;
  const bool partial = n_slip_ > 0 && n_slip_ < n_contact_;
  if (partial && std::isnan(sum_.incipient_onset_s)) sum_.incipient_onset_s = t;
}

void RailRun::TrackFirstSlips(double t) {
  // At step resolution (the contacts are read at every step until the onset is found): the
  // frames alone cannot order pins that start to slip within one frame.
  if (t < sched_.retract_start || !std::isnan(sum_.gross_slip_onset_s)) return;
  for (Channel& ch : channels_) {
    const std::vector<std::uint8_t>& slip = ch.sensor.pin_slip();
    for (int i = 0; i < n_; ++i) {
      if (slip[i] && std::isnan(ch.first_slip_s[i])) ch.first_slip_s[i] = t;
    }
  }
}

double RailRun::ObjectHeightOverSensorM() const {
  return sim_->BodyPos(im_.slider_body)[2] - channels_.front().sensor.pose().origin[2];
}

void RailRun::TrackEvents(double t, double tf) {
  // An object the skin cannot lift is left behind during the lift (its contact may be lost
  // before every pin is seen sliding): the run ends, not held.
  if (t >= sched_.lift_start && t < sched_.retract_start && std::isnan(sum_.gross_slip_onset_s)) {
    const double rel = ObjectHeightOverSensorM();
    if (std::isnan(lift_rel_ref_)) lift_rel_ref_ = rel;
    if (lift_rel_ref_ - rel > kOffDropM && !ending_) {
      left_behind_ = true;
      sum_.object_fall_s = tf;
      ending_ = true;
      end_time_ = std::min(end_time_, t + c_.rail.post_fall_s);
    }
    return;
  }
  // Run-level events from frames: object drop and creep, from the retraction on (or from
  // the onset, if the object already slips during the lift).
  if (t < sched_.retract_start && std::isnan(sum_.gross_slip_onset_s)) return;
  // Object drop relative to the sensor, and sliding relative to the centre pin.
  const double obj_z = sim_->BodyPos(im_.slider_body)[2];
  const double rel = ObjectHeightOverSensorM();
  const double creep = obj_z - sim_->SitePos(im_.sensors.front().pin_outer_site[0])[2];
  if (std::isnan(rel_ref_)) {
    rel_ref_ = rel;
    creep_ref_ = creep;
  }
  if (std::isnan(sum_.gross_slip_onset_s)) creep_max_ = std::max(creep_max_, std::abs(creep - creep_ref_));
  if (std::isnan(sum_.object_fall_s) && rel_ref_ - rel > c_.labels.fall_threshold_mm * 1e-3) {
    sum_.object_fall_s = tf;
  }
  // The run ends post_fall_s after the fall once the object really slides off: a
  // compliant (fingerprint) skin can sag past the fall threshold while its centre still
  // sticks, so the fall alone does not end it unless the drop is large.
  const bool off = !std::isnan(sum_.gross_slip_onset_s) || rel_ref_ - rel > kOffDropM;
  if (!std::isnan(sum_.object_fall_s) && off && !ending_) {
    ending_ = true;
    end_time_ = std::min(end_time_, t + c_.rail.post_fall_s);
  }
}

void RailRun::TrackHealth(double t) {
  // Held: from the lift's end until gross slip (a run whose object slipped during the lift
  // is never held). Creep: the object relative to the centre pin's contact point, from the
  // retraction on.
  const bool held = t >= sched_.lift_end && std::isnan(sum_.gross_slip_onset_s);
  const bool retracting = t >= sched_.retract_start;
  const double creep = retracting ? sim_->BodyPos(im_.slider_body)[2] - sim_->SitePos(im_.sensors.front().pin_outer_site[0])[2] : kNaN;
  // While held the sensor moves only along its normal (the retraction) and the object only
  // along the rail: a pin pushed quasi-statically, or carried by the object it sticks to,
  // moves at most as far as the sensor moves against the object, which the image shows at
  // most gain-fold.
  const double x = arm_.x_m;
  const double rel_z = ObjectHeightOverSensorM();
  const double gain_px_m = channels_.front().sensor.image_gain_px_m();
  const double quasi_static_px =
      std::isnan(prev_frame_x_) ? 0.0 : gain_px_m * std::hypot(x - prev_frame_x_, rel_z - prev_frame_rel_z_);
  prev_frame_x_ = x;
  prev_frame_rel_z_ = rel_z;
  // The pins of all sensors, in sensor order.
  for (size_t k = 0; k < channels_.size(); ++k) {
    const TactileSensor& sensor = channels_[k].sensor;
    std::copy(sensor.clean_px().begin(), sensor.clean_px().end(), health_px_.begin() + 2 * n_ * static_cast<long>(k));
    std::copy(sensor.pin_contact().begin(), sensor.pin_contact().end(), health_contact_.begin() + n_ * static_cast<long>(k));
  }
  // Slip between frames counts too (contacts are read at every step while it matters).
  health_.Frame(held, retracting, health_px_.data(), health_contact_.data(), slipped_since_frame_, creep, quasi_static_px);
  slipped_since_frame_ = false;
}

RailRunSummary RailRun::Finish(RunRecord& rec) {
  if (!started_) InitRecord(rec);
  sum_.creep_um = creep_max_ * 1e6;
  // The onset is dated back to the first step of its all-slide run; frames from that step on,
  // read while the onset was being confirmed, are gross slip, not slip before it (a frame on
  // the onset's own step too: every contacting pin slides there). Those frames hold no partial
  // slip, so the incipient onset never falls among them.
  const auto before_gross = [&](double t) {
    return !std::isnan(t) && (std::isnan(sum_.gross_slip_onset_s) || t < sum_.gross_slip_onset_s);
  };
  if (!std::isnan(sum_.incipient_onset_s) && !std::isnan(sum_.gross_slip_onset_s)) {
    sum_.incipient_lead_s = sum_.gross_slip_onset_s - sum_.incipient_onset_s;
  }
  if (retract_seen_) {
    int n_c = 0, n_s = 0;
    for (const Channel& ch : channels_) {
      for (int i = 0; i < n_; ++i) {
        n_c += ch.contact_at_retract[i];
        n_s += before_gross(ch.first_slip_frame_s[i]) ? 1 : 0;
      }
    }
    if (n_c > 0) sum_.pre_slip_fraction = static_cast<double>(n_s) / n_c;
  }
  sum_.held = !left_behind_ && (std::isnan(sum_.gross_slip_onset_s) || sum_.gross_slip_onset_s >= sched_.retract_start);
  sum_.mujoco_warnings = sim_->WarningCount();
  sum_.sim_time_s = StepTime(step_);
  rec.attrs["gross_slip_onset_s"] = sum_.gross_slip_onset_s;
  rec.attrs["object_fall_s"] = sum_.object_fall_s;
  rec.attrs["object_mass_kg"] = c_.object.mass_kg;
  rec.attrs["friction_coefficient"] = mu_;
  rec.attrs["kinetic_friction_coefficient"] = mu_ * c_.contact.kinetic_ratio;
  rec.attrs["retract_speed_mm_s"] = c_.rail.retract_speed_mm_s;
  rec.attrs["press_depth_mm"] = sum_.press_depth_mm;
  rec.attrs["retract_start_s"] = sum_.retract_start_s;
  rec.attrs["predicted_onset_s"] = sum_.predicted_onset_s;
  rec.attrs["coulomb_early_s"] = sum_.coulomb_early_s;
  rec.attrs["creep_um"] = sum_.creep_um;
  rec.attrs["rail_friction_N"] = c_.rail.friction_N;
  rec.attrs["object_held"] = sum_.held ? 1.0 : 0.0;
  rec.attrs["incipient_onset_s"] = sum_.incipient_onset_s;
  rec.attrs["incipient_lead_s"] = sum_.incipient_lead_s;
  rec.attrs["pre_slip_fraction"] = sum_.pre_slip_fraction;
  sum_.health = health_.Result();
  rec.attrs["health_ok"] = sum_.health.ok ? 1.0 : 0.0;
  rec.attrs["flicker_max"] = sum_.health.flicker_max;
  rec.attrs["held_pin_speed_px"] = sum_.health.pin_speed_px;
  rec.attrs["stick_creep_um"] = sum_.health.stick_creep_um;
  rec.attrs["energy_gain"] = sum_.health.energy_gain;
  rec.text_attrs["health_reason"] = sum_.health.reason;
  rec.text_attrs["stimulus"] = c_.rail.stimulus;
  for (SensorRecord& sensor : rec.sensors) sensor.text_attrs["skin_pattern"] = c_.skin.pattern;
  for (size_t k = 0; k < channels_.size(); ++k) {
    // The onset is dated back to the first step of its all-slide run: a pin first seen
    // slipping after that step, while the onset was being confirmed, slipped in gross slip.
    std::vector<double> first = channels_[k].first_slip_s;
    for (double& t : first) {
      if (t > sum_.gross_slip_onset_s) t = kNaN;
    }
    recorder_->FirstSlips(k, first);
  }
  sum_.actions = controller_->Actions();
  rec.actions.list = sum_.actions;
  sum_.controller_figures = controller_->Figures();
  rec.CheckShapes();
  sum_.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  if (instrument_) instrument_->profile = sim_->profile();
  return sum_;
}

}  // namespace tactip
