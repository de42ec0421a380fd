#include "scenarios/rail/rail_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace tactip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kOffDropM = 10e-3;  // an object this far below its held position has left the skin

double Dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// p_sensor = R^T (p - origin), R row-major.
std::array<double, 3> ToSensorFrame(const std::array<double, 3>& p, const std::array<double, 3>& origin,
                                    const std::array<double, 9>& rot) {
  const double d[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
  return {rot[0] * d[0] + rot[3] * d[1] + rot[6] * d[2], rot[1] * d[0] + rot[4] * d[1] + rot[7] * d[2],
          rot[2] * d[0] + rot[5] * d[1] + rot[8] * d[2]};
}

// A world-frame vector (not a point) in the sensor frame.
std::array<double, 3> VectorToSensorFrame(const std::array<double, 3>& v, const std::array<double, 3>& origin,
                                          const std::array<double, 9>& rot) {
  return ToSensorFrame({origin[0] + v[0], origin[1] + v[1], origin[2] + v[2]}, origin, rot);
}

// The external camera's noise: the configured pixel noise, no dropouts.
CameraConfig ExternalNoise(const ExternalCameraConfig& e) {
  CameraConfig c;
  c.pixel_noise_px = e.pixel_noise_px;
  c.dropout_prob = 0.0;
  return c;
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
  sensor_body = m.BodyId(RailNames::kSensor);
  slider_body = m.BodyId(RailNames::kSlider);
  stimulus_geom = m.GeomId(RailNames::kStimulus);
  // The object's vertical DOF: the slide joint, or a free joint's third (z translation).
  slide_dof = m.JointDofAdr(m.JointId(RailNames::kSlide)) + (options.object_free_joint ? 2 : 0);
  arm_z_dof = m.JointDofAdr(m.JointId(RailNames::kArmZ));
  slot_of_geom.assign(m.ngeom(), -1);
  const SkinMechanics mech = SkinMechanics::From(cfg.skin, PinLattice::Build(cfg.skin));
  if (cfg.skin.coupling == "membrane" && mech.k_rock_N_m > 0.0) {
    marker_rock_m_N = mech.marker_rock_factor / mech.k_rock_N_m;
  }
  apex_x_m = cfg.skin.OuterRadiusMm() * 1e-3;
  const std::vector<bool> outer = RailOuterSitePins(spec, static_cast<size_t>(scene.n_pins));
  for (int i = 0; i < scene.n_pins; ++i) {
    pin_site.push_back(m.SiteId(SkinNames::PinSite(i)));
    pin_outer_site.push_back(outer[i] ? m.SiteId(SkinNames::PinOuterSite(i)) : -1);
    int g = -1;
    try {
      g = m.GeomId(SkinNames::PinGeom(i));
    } catch (const ModelError&) {
      g = -1;  // culled: this pin cannot touch the stimulus
    }
    pin_geom.push_back(g);
    if (g >= 0) slot_of_geom[g] = i;
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

RailRun::RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, std::uint64_t seed)
    : RailRun(cfg, ids, index, Draw(cfg, DeriveSeed(seed, static_cast<std::uint64_t>(index)))) {}

RailRun::RailRun(const RailScenarioConfig& cfg, const RailSceneIds& ids, int index, const Draws& d)
    : c_(cfg),
      im_(ids),
      index_(index),
      n_(ids.scene.n_pins),
      depth_m_(d.depth_m),
      mu_(d.mu),
      noise_(cfg.sensor, DeriveSeed(d.run_seed, 1)),
      ext_noise_(ExternalNoise(cfg.external), DeriveSeed(d.run_seed, 2)),
      model_(ids.model->Copy()),
      sched_(cfg.rail, d.depth_m),
      dt_(cfg.sim.timestep_s),
      weight_N_(cfg.object.mass_kg * ids.model->gravity()),
      camera_(cfg.sensor),
      ext_camera_(cfg.external, ids.apex_x_m),
      contacts_(n_),
      tangential_(n_),
      samples_(n_),
      pin_contact_(n_),
      pin_slip_(n_),
      px_(2 * n_),
      ext_px_(2 * n_),
      clean_px_(2 * n_),
      valid_(n_),
      ext_valid_(n_),
      limits_(StateLimits::For(cfg, ids.scene.n_collidable)),
      marker_shift_m_(n_),
      normal_N_(n_),
      health_(n_, cfg.health),
      slid_before_gross_(n_, 0),
      end_time_(sched_.give_up),
      prev_margin_(kNaN),
      prev_skin_(kNaN),
      rel_ref_(kNaN),
      lift_rel_ref_(kNaN),
      creep_ref_(kNaN) {
  SetUpFriction(d.run_seed);
  model_.EnableEnergy();
  sim_.emplace(model_);
  sim_->Forward();
  const auto origin = sim_->BodyPos(im_.sensor_body);
  const auto rot = sim_->BodyRot(im_.sensor_body);
  for (int i = 0; i < n_; ++i) rest_marker_m_.push_back(ToSensorFrame(sim_->SitePos(im_.pin_site[i]), origin, rot));
  sum_.press_depth_mm = depth_m_ * 1e3;
  sum_.friction = mu_;
  sum_.retract_start_s = sched_.retract_start;
  for (double* v : {&sum_.gross_slip_onset_s, &sum_.object_fall_s, &sum_.predicted_onset_s, &sum_.coulomb_early_s,
                    &sum_.incipient_onset_s, &sum_.incipient_lead_s, &sum_.pre_slip_fraction}) {
    *v = kNaN;
  }
}

void RailRun::SetUpFriction(std::uint64_t run_seed) {
  // MuJoCo takes the larger of the two geoms' coefficients: the stimulus gets the lowest
  // kinetic value of any pin, and each pin's own coefficient moves between its static and
  // kinetic values as it sticks and slides (switched at the slip tolerance, or
  // continuously by velocity weakening).
  const double mu_k = mu_ * c_.contact.kinetic_ratio;
  mu_pin_.assign(n_, mu_);
  Rng pin_rng(DeriveSeed(run_seed, 3));
  for (double& m : mu_pin_) m *= 1.0 + c_.contact.pin_friction_spread * pin_rng.Uniform(-1.0, 1.0);
  model_.SetGeomFriction(im_.stimulus_geom, mu_k * (1.0 - c_.contact.pin_friction_spread));
  for (int i = 0; i < n_; ++i) {
    if (im_.pin_geom[i] >= 0) model_.SetGeomFriction(im_.pin_geom[i], mu_pin_[i]);
  }
  sliding_.assign(n_, 0);
  mu_cur_ = mu_pin_;
}

void RailRun::InitRecord(RunRecord& rec, int index) const {
  rec = RunRecord{};
  rec.index = index;
  rec.n_pins = n_;
  const size_t expect = static_cast<size_t>((sched_.give_up + 1.0) * c_.sensor.frame_rate_hz);
  rec.time.reserve(std::min<size_t>(expect, 200000));
}

void RailRun::RecordControls(double t) {
  // The controls in actuator order (servo_x, servo_z are the scene's only actuators).
  std::vector<double>& c = instrument_->ctrl;
  const size_t base = c.size();
  c.resize(base + 2);
  c[base + static_cast<size_t>(im_.servo_x)] = sched_.X(t);
  c[base + static_cast<size_t>(im_.servo_z)] = sched_.Z(t);
}

void RailRun::Instrument(RunInstrumentation* out) {
  instrument_ = out;
  sim_->EnableProfile();
}

RailRunSummary RailRun::Execute(RunRecord& rec, const std::atomic<bool>* stop) {
  const auto wall0 = std::chrono::steady_clock::now();
  InitRecord(rec, index_);
  long long frame = 0;
  long long next_frame_step = FrameStep(0, c_.sensor.frame_rate_hz, dt_);
  const bool two_coefficients = c_.contact.kinetic_ratio < 1.0;
  for (long long n = 0;; ++n) {
    const double t = static_cast<double>(n) * dt_;
    if (t > end_time_) break;
    if (stop && stop->load(std::memory_order_relaxed)) throw Interrupted();
    // Drive the arm servos along the protocol and advance one step.
    sim_->SetControl(im_.servo_x, sched_.X(t));
    sim_->SetControl(im_.servo_z, sched_.Z(t));
    if (instrument_) RecordControls(t);
    sim_->Step();
    ++sum_.steps;
    const bool held = t >= sched_.lift_end && std::isnan(sum_.gross_slip_onset_s);
    if (held) health_.Step(sim_->energy_created_J(), sim_->elastic_energy_J());

    // Between frames the contacts are read only while the onset (exact, at step
    // resolution) and its Coulomb prediction are still being searched for.
    const bool frame_now = n == next_frame_step;
    const bool seek_onset = t >= sched_.lift_start && std::isnan(sum_.gross_slip_onset_s);
    const bool seek_prediction = t >= sched_.retract_start && std::isnan(sum_.predicted_onset_s);
    if (!frame_now && !seek_onset && !seek_prediction && !two_coefficients) continue;
    ReadContactsAndLabel();
    if (labels_.n_slip > 0) slipped_since_frame_ = true;
    if (two_coefficients) UpdateFriction();
    TrackOnset(t, seek_onset);
    if (seek_prediction) TrackPrediction(t);
    if (!frame_now) continue;

    // One camera frame: the state at step n (time t).
    const double tf = static_cast<double>(frame) / c_.sensor.frame_rate_hz;
    ++frame;
    next_frame_step = FrameStep(frame, c_.sensor.frame_rate_hz, dt_);
    rec.time.push_back(tf);
    RecordFrame(t, rec);
    TrackEvents(t, tf);
    TrackHealth(t);
  }
  Finish(rec);
  if (instrument_) instrument_->profile = sim_->profile();
  sum_.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return sum_;
}

void RailRun::ReadContactsAndLabel() {
  sim_->ReadContacts(im_.slot_of_geom, contacts_);
  holding_N_ = 0.0;
  for (int i = 0; i < n_; ++i) {
    const GeomContact& gc = contacts_[i];
    // Friction holds up to mu_s N in the rail's direction (it acts across the pressing
    // axis, which the rail is); a sloped contact's normal force also pushes along the rail.
    holding_N_ += mu_pin_[i] * gc.normal_N - gc.normal_N * gc.normal_world[2];
    const double fn = Dot(gc.force_world, gc.normal_world);
    for (int k = 0; k < 3; ++k) tangential_[i][k] = gc.force_world[k] - fn * gc.normal_world[k];
    // On the cone as the friction rows hold it (see GeomContact::cone_use).
    samples_[i] = {gc.in_contact, gc.slip_speed_m_s, gc.in_contact ? gc.cone_use : 0.0};
  }
  labels_ = LabelFrame(samples_, c_.labels, pin_contact_.data(), pin_slip_.data());
  // Gross slip: every contacting pin slides and the object moves along the rail relative
  // to the sensor (with rail friction the skin alone may creep under a still object for a
  // few frames first).
  const double obj_speed = std::abs(sim_->Qvel(im_.slide_dof) - sim_->Qvel(im_.arm_z_dof));
  gross_ = labels_.gross_slip && obj_speed > c_.labels.slip_speed_m_s ? 1 : 0;
}

void RailRun::UpdateFriction() {
  const bool weakening = c_.contact.weakening_speed_mm_s > 0.0;
  for (int i = 0; i < n_; ++i) {
    if (im_.pin_geom[i] < 0) continue;
    if (weakening) {
      // Velocity weakening from this step's slip speed.
      mu_cur_[i] = c_.contact.WeakenedFriction(mu_pin_[i], samples_[i].in_contact ? samples_[i].slip_speed_m_s : 0.0);
    } else {
      // Static -> kinetic when a pin slides, back when it sticks (or leaves contact).
      const bool now = pin_slip_[i] || (sliding_[i] && samples_[i].in_contact &&
                                        samples_[i].slip_speed_m_s > c_.labels.slip_speed_m_s);
      if (now == static_cast<bool>(sliding_[i])) continue;
      sliding_[i] = now ? 1 : 0;
      mu_cur_[i] = now ? c_.contact.kinetic_ratio * mu_pin_[i] : mu_pin_[i];
    }
    model_.SetGeomFriction(im_.pin_geom[i], mu_cur_[i]);
  }
}

void RailRun::TrackOnset(double t, bool seek_onset) {
  // Gross onset: first gross-slip step once the object is held.
  if (seek_onset && gross_) sum_.gross_slip_onset_s = t;
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

void RailRun::RecordFrame(double t, RunRecord& rec) {
  origin_ = sim_->BodyPos(im_.sensor_body);
  rot_ = sim_->BodyRot(im_.sensor_body);
  RecordPins(rec);
  if (c_.external.enabled) RecordExternal(rec);
  RecordContacts(t, rec);
  CheckPlausible(t);
}

void RailRun::CheckPlausible(double t) const {
  const std::string why = ImplausibleState(limits_, marker_shift_m_, normal_N_);
  if (why.empty()) return;
  throw SimulationError(fmt::format("run {} stopped at t = {:.4f} s: {}: the solver diverged without a MuJoCo warning; "
                                    "use a smaller sim.timestep_s or more sim.iterations",
                                    index_, t, why));
}

namespace {

// Largest image motion per metre of motion of point `p` (sensor frame): the Frobenius norm
// of the projection's Jacobian, by central differences (it bounds every direction's gain).
double ImageGain(const PinholeCamera& camera, const std::array<double, 3>& p) {
  constexpr double h = 1e-5;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    auto a = p, b = p;
    a[k] += h;
    b[k] -= h;
    const auto ua = camera.Project(a), ub = camera.Project(b);
    sum += (ua[0] - ub[0]) * (ua[0] - ub[0]) + (ua[1] - ub[1]) * (ua[1] - ub[1]);
  }
  return std::sqrt(sum) / (2.0 * h);
}

}  // namespace

void RailRun::RecordPins(RunRecord& rec) {
  // Pin inner ends in the sensor frame, and their image positions. A fingerprint ridge
  // rocks under its tangential contact force (quasi-statically, deflection f_t / k_rock at
  // the contact point), which moves the inner marker the other way.
  image_gain_px_m_ = 0.0;
  for (int i = 0; i < n_; ++i) {
    auto p = ToSensorFrame(sim_->SitePos(im_.pin_site[i]), origin_, rot_);
    marker_shift_m_[i] = std::sqrt((p[0] - rest_marker_m_[i][0]) * (p[0] - rest_marker_m_[i][0]) +
                                   (p[1] - rest_marker_m_[i][1]) * (p[1] - rest_marker_m_[i][1]) +
                                   (p[2] - rest_marker_m_[i][2]) * (p[2] - rest_marker_m_[i][2]));
    if (im_.marker_rock_m_N > 0.0) {
      const auto fs = VectorToSensorFrame(tangential_[i], origin_, rot_);
      for (int k = 0; k < 3; ++k) p[k] -= im_.marker_rock_m_N * fs[k];
    }
    for (int k = 0; k < 3; ++k) rec.pos_m.push_back(static_cast<float>(p[k]));
    image_gain_px_m_ = std::max(image_gain_px_m_, ImageGain(camera_, p));
    const auto uv = camera_.Project(p);
    px_[2 * i] = static_cast<float>(uv[0]);
    px_[2 * i + 1] = static_cast<float>(uv[1]);
  }
  clean_px_ = px_;
  noise_.Apply(px_, valid_, prev_px_);
  prev_px_ = px_;
  rec.pos_px.insert(rec.pos_px.end(), px_.begin(), px_.end());
  rec.valid.insert(rec.valid.end(), valid_.begin(), valid_.end());
}

void RailRun::RecordExternal(RunRecord& rec) {
  // External markers: the outer contact points, seen through the plate.
  for (int i = 0; i < n_; ++i) {
    const auto q = ToSensorFrame(sim_->SitePos(im_.pin_outer_site[i]), origin_, rot_);
    for (int k = 0; k < 3; ++k) rec.external_m.push_back(static_cast<float>(q[k]));
    const auto uv = ext_camera_.Project(q);
    ext_px_[2 * i] = static_cast<float>(uv[0]);
    ext_px_[2 * i + 1] = static_cast<float>(uv[1]);
  }
  ext_noise_.Apply(ext_px_, ext_valid_, prev_ext_px_);
  prev_ext_px_ = ext_px_;
  rec.external_px.insert(rec.external_px.end(), ext_px_.begin(), ext_px_.end());
}

void RailRun::RecordContacts(double t, RunRecord& rec) {
  // Contact forces (tangential in sensor y, z) and stick/slip labels.
  for (int i = 0; i < n_; ++i) {
    normal_N_[i] = contacts_[i].normal_N;
    rec.normal_N.push_back(static_cast<float>(contacts_[i].normal_N));
    const auto fts = VectorToSensorFrame(tangential_[i], origin_, rot_);
    rec.tangential_N.push_back(static_cast<float>(fts[1]));
    rec.tangential_N.push_back(static_cast<float>(fts[2]));
  }
  rec.pin_contact.insert(rec.pin_contact.end(), pin_contact_.begin(), pin_contact_.end());
  rec.pin_slip.insert(rec.pin_slip.end(), pin_slip_.begin(), pin_slip_.end());
  rec.gross_slip.push_back(gross_);
  const std::uint8_t partial = labels_.n_slip > 0 && labels_.n_slip < labels_.n_contact ? 1 : 0;
  rec.incipient.push_back(partial);
  // Incipient slip: partial slip from the retraction on, before gross slip.
  if (t >= sched_.retract_start && std::isnan(sum_.gross_slip_onset_s)) {
    if (contact_at_retract_.empty()) contact_at_retract_ = pin_contact_;
    for (int i = 0; i < n_; ++i) slid_before_gross_[i] |= contact_at_retract_[i] & pin_slip_[i];
    if (partial && std::isnan(sum_.incipient_onset_s)) sum_.incipient_onset_s = t;
  }
  rec.object_height_m.push_back(sim_->BodyPos(im_.slider_body)[2] - RailLayout::kAxisHeight);
}

void RailRun::TrackEvents(double t, double tf) {
  // An object the skin cannot lift is left behind during the lift (its contact may be lost
  // before every pin is seen sliding): the run ends, not held.
  if (t >= sched_.lift_start && t < sched_.retract_start && std::isnan(sum_.gross_slip_onset_s)) {
    const double rel = sim_->BodyPos(im_.slider_body)[2] - origin_[2];
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
  const double rel = obj_z - origin_[2];
  const double creep = obj_z - sim_->SitePos(im_.pin_outer_site[0])[2];
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
  const double creep = retracting ? sim_->BodyPos(im_.slider_body)[2] - sim_->SitePos(im_.pin_outer_site[0])[2] : kNaN;
  // While held the sensor moves only along its normal (the retraction): a pin pushed
  // quasi-statically moves at most that far, which the image shows at most gain-fold.
  const double x = sched_.X(t);
  const double quasi_static_px = std::isnan(prev_frame_x_) ? 0.0 : image_gain_px_m_ * std::abs(x - prev_frame_x_);
  prev_frame_x_ = x;
  // Slip between frames counts too (contacts are read at every step while it matters).
  health_.Frame(held, retracting, clean_px_.data(), pin_contact_.data(), slipped_since_frame_, creep, quasi_static_px);
  slipped_since_frame_ = false;
}

void RailRun::Finish(RunRecord& rec) {
  sum_.creep_um = creep_max_ * 1e6;
  if (!std::isnan(sum_.incipient_onset_s) && !std::isnan(sum_.gross_slip_onset_s)) {
    sum_.incipient_lead_s = sum_.gross_slip_onset_s - sum_.incipient_onset_s;
  }
  if (!contact_at_retract_.empty()) {
    int n_c = 0, n_s = 0;
    for (int i = 0; i < n_; ++i) {
      n_c += contact_at_retract_[i];
      n_s += slid_before_gross_[i];
    }
    if (n_c > 0) sum_.pre_slip_fraction = static_cast<double>(n_s) / n_c;
  }
  sum_.held = !left_behind_ && (std::isnan(sum_.gross_slip_onset_s) || sum_.gross_slip_onset_s >= sched_.retract_start);
  sum_.mujoco_warnings = sim_->WarningCount();
  sum_.sim_time_s = static_cast<double>(sum_.steps) * dt_;
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
  rec.text_attrs["skin_pattern"] = c_.skin.pattern;
  rec.CheckShapes();
}

}  // namespace tactip
