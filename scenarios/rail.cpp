#include "scenarios/rail.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "sim/random.h"
#include "sim/simulation.h"
#include "tactip/version.h"

namespace tactip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kExtraRetractM = 5e-3;  // keep retracting this far past the press before giving up
constexpr double kOffDropM = 10e-3;      // an object this far below its held position has left the skin

// Quintic smooth step: 0 -> 1 with zero velocity and acceleration at both ends.
double SmoothStep(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

// Timeline of the rail protocol for one run (seconds, metres).
struct Schedule {
  double press_start, press_end, lift_start, lift_end, retract_start, give_up;
  double press_dist, lift_dist, retract_speed;

  Schedule(const RailConfig& r, double depth_m) {
    press_dist = r.approach_gap_mm * 1e-3 + depth_m;
    lift_dist = r.lift_mm * 1e-3;
    retract_speed = r.retract_speed_mm_s * 1e-3;
    press_start = r.settle_s;
    press_end = press_start + press_dist / (r.press_speed_mm_s * 1e-3);
    lift_start = press_end + r.settle_s;
    lift_end = lift_start + lift_dist / (r.lift_speed_mm_s * 1e-3);
    retract_start = lift_end + r.hold_s;
    give_up = retract_start + (press_dist + kExtraRetractM) / retract_speed;
  }
  // Servo targets (arm joint positions) at time t.
  double X(double t) const {
    const double pressed = press_dist * SmoothStep((t - press_start) / (press_end - press_start));
    return pressed - retract_speed * std::max(0.0, t - retract_start);
  }
  double Z(double t) const { return lift_dist * SmoothStep((t - lift_start) / (lift_end - lift_start)); }
};

double Dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

std::array<double, 3> ToSensorFrame(const std::array<double, 3>& p, const std::array<double, 3>& origin,
                                    const std::array<double, 9>& rot) {
  // p_sensor = R^T (p - origin), R row-major.
  const double d[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
  return {rot[0] * d[0] + rot[3] * d[1] + rot[6] * d[2], rot[1] * d[0] + rot[4] * d[1] + rot[7] * d[2],
          rot[2] * d[0] + rot[5] * d[1] + rot[8] * d[2]};
}

}  // namespace

void RailScenarioConfig::ValidateRules() const {
  // Section rules first, then rules that tie sections together.
  skin.ValidateRules();
  contact.ValidateRules();
  if (contact.timeconst_s < 2.0 * sim.timestep_s) {
    FailRule("contact.timeconst_s", contact.timeconst_s,
             fmt::format("must be >= 2 * sim.timestep_s = {} s (MuJoCo would silently soften it)",
                         2.0 * sim.timestep_s));
  }
  // A run must end: the retraction (past the press plus 5 mm) within an hour of simulation.
  constexpr double kMaxRetractS = 3600.0;
  const double retract_mm = rail.approach_gap_mm + rail.press_depth_mm + rail.press_depth_jitter_mm + 5.0;
  if (retract_mm / rail.retract_speed_mm_s > kMaxRetractS) {
    FailRule("rail.retract_speed_mm_s", rail.retract_speed_mm_s,
             fmt::format("the retraction would take {:.0f} s of simulated time (limit {:.0f} s); use >= {:.3g}",
                         retract_mm / rail.retract_speed_mm_s, kMaxRetractS, retract_mm / kMaxRetractS));
  }
  if (external.enabled && rail.stimulus != "acrylic") {
    FailRule("external.enabled", 1.0,
             "the external camera sees the skin only through a transparent stimulus: set rail.stimulus = acrylic");
  }
  const double frame_dt = 1.0 / sensor.frame_rate_hz;
  if (frame_dt < sim.timestep_s) {
    FailRule("sensor.frame_rate_hz", sensor.frame_rate_hz,
             fmt::format("one frame ({} s) is shorter than sim.timestep_s = {} s", frame_dt, sim.timestep_s));
  }
  if (sim.check_stability) {
    const StiffMode mode = RailStiffestMode(SceneSpec());
    const double dt_max = MaxStableTimestep(mode.omega, mode.zeta);
    if (sim.timestep_s > dt_max) {
      FailRule("sim.timestep_s", sim.timestep_s,
               fmt::format("unstable: exceeds the limit {:.3g} s of {} (omega = {:.0f} rad/s, damping ratio {:.2f}); "
                           "use sim.timestep_s <= {:.3g}",
                           dt_max, mode.name, mode.omega, mode.zeta, dt_max));
    }
  }
}

RailSceneSpec RailScenarioConfig::SceneSpec() const {
  RailSceneSpec spec;
  spec.sim = sim;
  spec.object = object;
  spec.contact = contact;
  spec.rail = rail;
  spec.skin = skin;
  spec.arm = arm;
  spec.max_depth_m = (rail.press_depth_mm + rail.press_depth_jitter_mm) * 1e-3;
  return spec;
}

// Compiled scene and the element ids the protocol needs.
struct RailScenario::Impl {
  BuiltScene scene;
  std::optional<CompiledModel> model;
  int servo_x = -1, servo_z = -1, sensor_body = -1, slider_body = -1, stimulus_geom = -1;
  int slide_dof = -1, arm_z_dof = -1;
  std::vector<int> pin_site, pin_outer_site, pin_geom;  // pin_geom -1: no contact geom
  std::vector<int> slot_of_geom;                         // geom id -> pin index
  double marker_rock_m_N = 0.0;  // inner marker moves by -this * tangential contact force (ridge pivot)
  double apex_x_m = 0.0;         // dome apex in the sensor frame
};

RailScenario::RailScenario(const RailScenarioConfig& cfg) : impl_(std::make_unique<Impl>()), cfg_(cfg) {
  ValidateConfig(cfg_);
  // Build and compile once; runs copy the model.
  impl_->scene = BuildRailScene(cfg_.SceneSpec());
  impl_->model.emplace(CompiledModel::FromXml(impl_->scene.xml));
  const CompiledModel& m = *impl_->model;
  impl_->servo_x = m.ActuatorId(RailNames::kServoX);
  impl_->servo_z = m.ActuatorId(RailNames::kServoZ);
  impl_->sensor_body = m.BodyId(RailNames::kSensor);
  impl_->slider_body = m.BodyId(RailNames::kSlider);
  impl_->stimulus_geom = m.GeomId(RailNames::kStimulus);
  impl_->slide_dof = m.JointDofAdr(m.JointId(RailNames::kSlide));
  impl_->arm_z_dof = m.JointDofAdr(m.JointId(RailNames::kArmZ));
  impl_->slot_of_geom.assign(m.ngeom(), -1);
  const SkinMechanics mech = SkinMechanics::From(cfg_.skin, PinLattice::Build(cfg_.skin));
  if (cfg_.skin.coupling == "membrane" && mech.k_rock_N_m > 0.0) {
    impl_->marker_rock_m_N = mech.marker_rock_factor / mech.k_rock_N_m;
  }
  impl_->apex_x_m = cfg_.skin.OuterRadiusMm() * 1e-3;
  for (int i = 0; i < impl_->scene.n_pins; ++i) {
    impl_->pin_site.push_back(m.SiteId(SkinNames::PinSite(i)));
    impl_->pin_outer_site.push_back(m.SiteId(SkinNames::PinOuterSite(i)));
    int g = -1;
    try {
      g = m.GeomId(SkinNames::PinGeom(i));
    } catch (const ModelError&) {
      g = -1;  // culled: this pin cannot touch the stimulus
    }
    impl_->pin_geom.push_back(g);
    if (g >= 0) impl_->slot_of_geom[g] = i;
  }
}

RailScenario::~RailScenario() = default;

const std::string& RailScenario::xml() const { return impl_->scene.xml; }
int RailScenario::n_pins() const { return impl_->scene.n_pins; }
int RailScenario::n_collidable() const { return impl_->scene.n_collidable; }

RailRunSummary RailScenario::Run(int index, std::uint64_t seed, RunRecord& rec,
                                 const std::atomic<bool>* stop) const {
  const auto wall0 = std::chrono::steady_clock::now();
  const RailScenarioConfig& c = cfg_;
  const Impl& im = *impl_;
  const int N = im.scene.n_pins;

  // Per-run variation: always draw both numbers so each stays on its own stream.
  const std::uint64_t run_seed = DeriveSeed(seed, static_cast<std::uint64_t>(index));
  Rng vary(DeriveSeed(run_seed, 0));
  const double depth_m = (c.rail.press_depth_mm + vary.Uniform(-1.0, 1.0) * c.rail.press_depth_jitter_mm) * 1e-3;
  const double mu = c.contact.friction * (1.0 + vary.Uniform(-1.0, 1.0) * c.contact.friction_jitter);
  DetectionNoise noise(c.sensor, DeriveSeed(run_seed, 1));
  CameraConfig ext_noise_cfg;
  ext_noise_cfg.pixel_noise_px = c.external.pixel_noise_px;
  ext_noise_cfg.dropout_prob = 0.0;
  DetectionNoise ext_noise(ext_noise_cfg, DeriveSeed(run_seed, 2));

  // This run's model: the shared one with this run's friction.
  CompiledModel model = im.model->Copy();
  // MuJoCo takes the larger of the two geoms' coefficients: the stimulus gets the
  // lowest kinetic value of any pin, and each pin's own coefficient moves between
  // its static and kinetic values as it sticks and slides (switched at the slip
  // tolerance, or continuously by velocity weakening).
  const double mu_k = mu * c.contact.kinetic_ratio;
  std::vector<double> mu_pin(N, mu);  // per pin: static coefficient
  Rng pin_rng(DeriveSeed(run_seed, 3));
  for (double& m : mu_pin) m *= 1.0 + c.contact.pin_friction_spread * pin_rng.Uniform(-1.0, 1.0);
  model.SetGeomFriction(im.stimulus_geom, mu_k * (1.0 - c.contact.pin_friction_spread));
  for (int i = 0; i < N; ++i) {
    if (im.pin_geom[i] >= 0) model.SetGeomFriction(im.pin_geom[i], mu_pin[i]);
  }
  std::vector<std::uint8_t> sliding(N, 0);  // per pin: kinetic friction in force
  std::vector<double> mu_cur = mu_pin;       // per pin: coefficient in force
  const bool weakening = c.contact.weakening_speed_mm_s > 0.0;
  Simulation sim(model);
  sim.Forward();

  const Schedule sched(c.rail, depth_m);
  const double dt = c.sim.timestep_s;
  const double weight_N = c.object.mass_kg * model.gravity();
  PinholeCamera camera(c.sensor);
  const ExternalCamera ext_camera(c.external, im.apex_x_m);

  // Output arrays, grown frame by frame.
  rec = RunRecord{};
  rec.index = index;
  rec.n_pins = N;
  const size_t expect = static_cast<size_t>((sched.give_up + 1.0) * c.sensor.frame_rate_hz);
  rec.time.reserve(std::min<size_t>(expect, 200000));

  std::vector<GeomContact> contacts(N);
  std::vector<std::array<double, 3>> tangential(N);
  std::vector<PinContactSample> samples(N);
  std::vector<float> px(2 * N), prev_px, ext_px(2 * N), prev_ext_px;
  std::vector<std::uint8_t> ext_valid(N);
  std::vector<std::uint8_t> slid_before_gross(N, 0), contact_at_retract;
  std::vector<std::uint8_t> valid(N), pin_contact(N), pin_slip(N);

  RailRunSummary sum;
  sum.press_depth_mm = depth_m * 1e3;
  sum.friction = mu;
  sum.retract_start_s = sched.retract_start;
  sum.gross_slip_onset_s = kNaN;
  sum.object_fall_s = kNaN;
  sum.predicted_onset_s = kNaN;
  sum.coulomb_early_s = kNaN;
  sum.incipient_onset_s = kNaN;
  sum.incipient_lead_s = kNaN;
  sum.pre_slip_fraction = kNaN;
  double end_time = sched.give_up;
  double prev_margin = kNaN, prev_skin = kNaN, prev_t = 0.0;
  double rel_ref = kNaN, creep_ref = kNaN, creep_max = 0.0;
  bool ending = false;

  long long frame = 0;
  long long next_frame_step = FrameStep(0, c.sensor.frame_rate_hz, dt);
  for (long long n = 0;; ++n) {
    const double t = static_cast<double>(n) * dt;
    if (t > end_time) break;
    if (stop && stop->load(std::memory_order_relaxed)) throw Interrupted();
    // Drive the arm servos along the protocol and advance one step.
    sim.SetControl(im.servo_x, sched.X(t));
    sim.SetControl(im.servo_z, sched.Z(t));
    sim.Step();
    ++sum.steps;

    // Between frames the contacts are read only while the onset (exact, at step
    // resolution) and its Coulomb prediction are still being searched for.
    const bool frame_now = n == next_frame_step;
    const bool seek_onset = t >= sched.lift_start && std::isnan(sum.gross_slip_onset_s);
    const bool seek_prediction = t >= sched.retract_start && std::isnan(sum.predicted_onset_s);
    const bool two_coefficients = c.contact.kinetic_ratio < 1.0;
    if (!frame_now && !seek_onset && !seek_prediction && !two_coefficients) continue;
    sim.ReadContacts(im.slot_of_geom, contacts);
    double holding_N = 0.0;  // sum of mu_s,i * N_i
    for (int i = 0; i < N; ++i) {
      const GeomContact& gc = contacts[i];
      holding_N += mu_pin[i] * gc.normal_N;
      const double fn = Dot(gc.force_world, gc.normal_world);
      for (int k = 0; k < 3; ++k) tangential[i][k] = gc.force_world[k] - fn * gc.normal_world[k];
      const double ft = std::sqrt(Dot(tangential[i], tangential[i]));
      const double mu_now = mu_cur[i];
      samples[i] = {gc.in_contact, gc.slip_speed_m_s, gc.in_contact ? ft / (mu_now * gc.normal_N) : 0.0};
    }
    const FrameLabels fl = LabelFrame(samples, c.labels, pin_contact.data(), pin_slip.data());
    if (two_coefficients) {
      for (int i = 0; i < N; ++i) {
        if (im.pin_geom[i] < 0) continue;
        if (weakening) {
          // Velocity weakening from this step's slip speed.
          mu_cur[i] = c.contact.WeakenedFriction(mu_pin[i], samples[i].in_contact ? samples[i].slip_speed_m_s : 0.0);
        } else {
          // Static -> kinetic when a pin slides, back when it sticks (or leaves contact).
          const bool now = pin_slip[i] || (sliding[i] && samples[i].in_contact &&
                                           samples[i].slip_speed_m_s > c.labels.slip_speed_m_s);
          if (now == static_cast<bool>(sliding[i])) continue;
          sliding[i] = now ? 1 : 0;
          mu_cur[i] = now ? c.contact.kinetic_ratio * mu_pin[i] : mu_pin[i];
        }
        model.SetGeomFriction(im.pin_geom[i], mu_cur[i]);
      }
    }
    // Gross slip: every contacting pin slides and the object moves along the rail
    // relative to the sensor (with rail friction the skin alone may creep under a
    // still object for a few frames first).
    const double obj_speed = std::abs(sim.Qvel(im.slide_dof) - sim.Qvel(im.arm_z_dof));
    const std::uint8_t gross = fl.gross_slip && obj_speed > c.labels.slip_speed_m_s ? 1 : 0;
    // Gross onset: first such step once the object is held.
    if (seek_onset && gross) sum.gross_slip_onset_s = t;
    if (seek_prediction) {
      // Coulomb prediction from the simulated normal forces: the holding margin
      // sum(mu_i N_i) + rail friction - m g crosses zero between two steps.
      // The rail's static friction (either sign, up to F_rail) shares the load in a
      // statically undetermined way, so the skin may start sliding anywhere between
      // sum(mu_i N_i) = m g + F_rail and sum(mu_i N_i) = m g - F_rail.
      const double margin = holding_N + c.rail.friction_N - weight_N;
      const double skin_margin = margin - 2.0 * c.rail.friction_N;
      if (!std::isnan(prev_margin) && prev_margin >= 0.0 && margin < 0.0) {
        sum.predicted_onset_s = prev_t + (t - prev_t) * prev_margin / (prev_margin - margin);
      }
      if (std::isnan(sum.coulomb_early_s) && !std::isnan(prev_skin) && prev_skin >= 0.0 && skin_margin < 0.0) {
        sum.coulomb_early_s = prev_t + (t - prev_t) * prev_skin / (prev_skin - skin_margin);
      }
      prev_margin = margin;
      prev_skin = skin_margin;
      prev_t = t;
    }
    if (!frame_now) continue;

    // ---- One camera frame: the state at step n (time t). ----
    const double tf = static_cast<double>(frame) / c.sensor.frame_rate_hz;
    ++frame;
    next_frame_step = FrameStep(frame, c.sensor.frame_rate_hz, dt);
    rec.time.push_back(tf);

    // Pin inner ends in the sensor frame, and their image positions. A fingerprint
    // ridge rocks under its tangential contact force (quasi-statically, deflection
    // f_t / k_rock at the contact point), which moves the inner marker the other way.
    const auto origin = sim.BodyPos(im.sensor_body);
    const auto rot = sim.BodyRot(im.sensor_body);
    for (int i = 0; i < N; ++i) {
      auto p = ToSensorFrame(sim.SitePos(im.pin_site[i]), origin, rot);
      if (im.marker_rock_m_N > 0.0) {
        const auto& f = tangential[i];
        const auto fs = ToSensorFrame({origin[0] + f[0], origin[1] + f[1], origin[2] + f[2]}, origin, rot);
        for (int k = 0; k < 3; ++k) p[k] -= im.marker_rock_m_N * fs[k];
      }
      for (int k = 0; k < 3; ++k) rec.pos_m.push_back(static_cast<float>(p[k]));
      const auto uv = camera.Project(p);
      px[2 * i] = static_cast<float>(uv[0]);
      px[2 * i + 1] = static_cast<float>(uv[1]);
    }
    noise.Apply(px, valid, prev_px);
    prev_px = px;
    rec.pos_px.insert(rec.pos_px.end(), px.begin(), px.end());
    rec.valid.insert(rec.valid.end(), valid.begin(), valid.end());
    if (c.external.enabled) {
      // External markers: the outer contact points, seen through the plate.
      for (int i = 0; i < N; ++i) {
        const auto q = ToSensorFrame(sim.SitePos(im.pin_outer_site[i]), origin, rot);
        for (int k = 0; k < 3; ++k) rec.external_m.push_back(static_cast<float>(q[k]));
        const auto uv = ext_camera.Project(q);
        ext_px[2 * i] = static_cast<float>(uv[0]);
        ext_px[2 * i + 1] = static_cast<float>(uv[1]);
      }
      ext_noise.Apply(ext_px, ext_valid, prev_ext_px);
      prev_ext_px = ext_px;
      rec.external_px.insert(rec.external_px.end(), ext_px.begin(), ext_px.end());
    }

    // Contact forces (tangential in sensor y, z) and stick/slip labels.
    for (int i = 0; i < N; ++i) {
      rec.normal_N.push_back(static_cast<float>(contacts[i].normal_N));
      const auto& ft = tangential[i];
      const auto fts = ToSensorFrame({origin[0] + ft[0], origin[1] + ft[1], origin[2] + ft[2]}, origin, rot);
      rec.tangential_N.push_back(static_cast<float>(fts[1]));
      rec.tangential_N.push_back(static_cast<float>(fts[2]));
    }
    rec.pin_contact.insert(rec.pin_contact.end(), pin_contact.begin(), pin_contact.end());
    rec.pin_slip.insert(rec.pin_slip.end(), pin_slip.begin(), pin_slip.end());
    rec.gross_slip.push_back(gross);
    const std::uint8_t partial = fl.n_slip > 0 && fl.n_slip < fl.n_contact ? 1 : 0;
    rec.incipient.push_back(partial);
    // Incipient slip: partial slip from the retraction on, before gross slip.
    if (t >= sched.retract_start && std::isnan(sum.gross_slip_onset_s)) {
      if (contact_at_retract.empty()) contact_at_retract = pin_contact;
      for (int i = 0; i < N; ++i) slid_before_gross[i] |= contact_at_retract[i] & pin_slip[i];
      if (partial && std::isnan(sum.incipient_onset_s)) sum.incipient_onset_s = t;
    }
    const double obj_z = sim.BodyPos(im.slider_body)[2];
    rec.object_height_m.push_back(obj_z - RailLayout::kAxisHeight);

    // Run-level events from frames: object drop and creep, from the retraction on (or
    // from the onset, if the object already slips during the lift).
    if (t >= sched.retract_start || !std::isnan(sum.gross_slip_onset_s)) {
      // Object drop relative to the sensor, and sliding relative to the centre pin.
      const double rel = obj_z - origin[2];
      const double creep = obj_z - sim.SitePos(im.pin_outer_site[0])[2];
      if (std::isnan(rel_ref)) {
        rel_ref = rel;
        creep_ref = creep;
      }
      if (std::isnan(sum.gross_slip_onset_s)) creep_max = std::max(creep_max, std::abs(creep - creep_ref));
      if (std::isnan(sum.object_fall_s) && rel_ref - rel > c.labels.fall_threshold_mm * 1e-3) {
        sum.object_fall_s = tf;
      }
      // The run ends post_fall_s after the fall once the object really slides off: a
      // compliant (fingerprint) skin can sag past the fall threshold while its centre
      // still sticks, so the fall alone does not end it unless the drop is large.
      const bool off = !std::isnan(sum.gross_slip_onset_s) || rel_ref - rel > kOffDropM;
      if (!std::isnan(sum.object_fall_s) && off && !ending) {
        ending = true;
        end_time = std::min(end_time, t + c.rail.post_fall_s);
      }
    }
  }

  // Run attributes.
  sum.creep_um = creep_max * 1e6;
  if (!std::isnan(sum.incipient_onset_s) && !std::isnan(sum.gross_slip_onset_s)) {
    sum.incipient_lead_s = sum.gross_slip_onset_s - sum.incipient_onset_s;
  }
  if (!contact_at_retract.empty()) {
    int n_c = 0, n_s = 0;
    for (int i = 0; i < N; ++i) {
      n_c += contact_at_retract[i];
      n_s += slid_before_gross[i];
    }
    if (n_c > 0) sum.pre_slip_fraction = static_cast<double>(n_s) / n_c;
  }
  sum.held = std::isnan(sum.gross_slip_onset_s) || sum.gross_slip_onset_s >= sched.retract_start;
  sum.mujoco_warnings = sim.WarningCount();
  sum.sim_time_s = static_cast<double>(sum.steps) * dt;
  sum.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  rec.attrs["gross_slip_onset_s"] = sum.gross_slip_onset_s;
  rec.attrs["object_fall_s"] = sum.object_fall_s;
  rec.attrs["object_mass_kg"] = c.object.mass_kg;
  rec.attrs["friction_coefficient"] = mu;
  rec.attrs["kinetic_friction_coefficient"] = mu_k;
  rec.attrs["retract_speed_mm_s"] = c.rail.retract_speed_mm_s;
  rec.attrs["press_depth_mm"] = sum.press_depth_mm;
  rec.attrs["retract_start_s"] = sum.retract_start_s;
  rec.attrs["predicted_onset_s"] = sum.predicted_onset_s;
  rec.attrs["coulomb_early_s"] = sum.coulomb_early_s;
  rec.attrs["creep_um"] = sum.creep_um;
  rec.attrs["rail_friction_N"] = c.rail.friction_N;
  rec.attrs["object_held"] = sum.held ? 1.0 : 0.0;
  rec.attrs["incipient_onset_s"] = sum.incipient_onset_s;
  rec.attrs["incipient_lead_s"] = sum.incipient_lead_s;
  rec.attrs["pre_slip_fraction"] = sum.pre_slip_fraction;
  rec.text_attrs["stimulus"] = c.rail.stimulus;
  rec.text_attrs["skin_pattern"] = c.skin.pattern;
  rec.CheckShapes();
  return sum;
}

void RunRailRuns(const RailScenario& scenario, int runs, std::uint64_t seed, int jobs_requested,
                 const std::atomic<bool>* stop, const std::function<void(RunRecord&&, const RailRunSummary&)>& take) {
  // Workers take run indices in order; this thread hands them to `take` in order.
  const int jobs = std::max(
      1, std::min(runs, jobs_requested > 0 ? jobs_requested : static_cast<int>(std::thread::hardware_concurrency())));
  std::mutex mu;
  std::condition_variable cv;
  std::map<int, RunRecord> done;
  std::map<int, RailRunSummary> summaries;
  std::exception_ptr failure;
  int next_index = 0;
  std::atomic<bool> abort{false};
  auto worker = [&] {
    for (;;) {
      int idx;
      {
        std::unique_lock lock(mu);
        // Bound memory: do not run ahead of the consumer by more than 2 * jobs runs.
        cv.wait(lock, [&] { return failure || next_index >= runs || static_cast<int>(done.size()) < 2 * jobs; });
        if (failure || next_index >= runs) return;
        idx = next_index++;
      }
      try {
        RunRecord rec;
        const RailRunSummary s = scenario.Run(idx, seed, rec, &abort);
        std::lock_guard lock(mu);
        done.emplace(idx, std::move(rec));
        summaries.emplace(idx, s);
      } catch (...) {
        std::lock_guard lock(mu);
        if (!failure) failure = std::current_exception();
        abort = true;
      }
      cv.notify_all();
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);

  int taken = 0;
  try {
    while (taken < runs) {
      RunRecord rec;
      RailRunSummary s;
      {
        std::unique_lock lock(mu);
        // Poll, because an interrupting signal cannot notify the condition variable.
        while (!(failure || done.count(taken) > 0 || (stop && stop->load()))) {
          cv.wait_for(lock, std::chrono::milliseconds(200));
        }
        if (stop && stop->load()) {
          abort = true;
          if (!failure) failure = std::make_exception_ptr(Interrupted());
        }
        if (failure) break;
        rec = std::move(done.at(taken));
        done.erase(taken);
        s = summaries.at(taken);
      }
      cv.notify_all();
      take(std::move(rec), s);
      ++taken;
    }
  } catch (...) {
    std::lock_guard lock(mu);
    if (!failure) failure = std::current_exception();
    abort = true;
  }
  cv.notify_all();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

GenerateResult GenerateRailDataset(const RailScenarioConfig& cfg, const GenerateOptions& opts) {
  if (opts.runs < 1) throw InputError(fmt::format("--runs = {}: must be >= 1", opts.runs));
  if (opts.out_path.empty()) throw InputError("no output file given (--out)");
  const RailScenario scenario(cfg);
  const auto wall0 = std::chrono::steady_clock::now();

  DatasetHeader header;
  header.tactip_version = TACTIP_VERSION;
  header.scenario = opts.scenario;
  header.seed = opts.seed;
  header.config_yaml = ConfigToYaml(scenario.config());
  DatasetWriter writer(opts.out_path, header);

  GenerateResult result;
  RunRailRuns(scenario, opts.runs, opts.seed, opts.jobs, opts.stop, [&](RunRecord&& rec, const RailRunSummary& s) {
    writer.WriteRun(rec);
    result.sim_time_s += s.sim_time_s;
    ++result.runs;
    if (opts.progress) opts.progress(result.runs, opts.runs, rec.index, s);
  });
  writer.Commit();
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return result;
}

}  // namespace tactip
