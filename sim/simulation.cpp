#include "sim/simulation.h"

#include "sim/friction_reference.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <chrono>
#include <mutex>

#include <fmt/format.h>

namespace tactip {

static_assert(mjNWARNING == 8, "warning table size");

namespace {

// Messages MuJoCo sent to its warning hook in this process (see MujocoWarningsRaised).
std::atomic<int> g_warnings_raised{0};

// MuJoCo's default warning handler prints to stdout and appends to MUJOCO_LOG.TXT; the
// counters in mjData are checked after every step instead. The hook only counts.
void SilentWarning(const char*) { g_warnings_raised.fetch_add(1, std::memory_order_relaxed); }

// MuJoCo calls this on an internal error (e.g. its solver stack overflows) and ends the
// process if it returns. It throws instead: the exception unwinds through MuJoCo's C frames
// (libmujoco is built with unwind tables; they run no cleanup), so callers above clean up
// (temporary files) and report it. The mjData MuJoCo was working on is left mid-step: the
// Simulation that threw must not be stepped again. The compiler inside mj_loadXML installs
// its own thread-local handler, so compile errors still come back as mj_loadXML's text.
void InternalError(const char* msg) { throw SimulationError(fmt::format("MuJoCo internal error: {}", msg)); }

void InstallHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = SilentWarning;
    mju_user_error = InternalError;
  });
}

std::mutex& LoaderMutex() {
  static std::mutex mu;
  return mu;
}

int NameToId(const mjModel* m, int type, const std::string& name, const char* what) {
  const int id = mj_name2id(m, type, name.c_str());
  if (id < 0) throw ModelError(fmt::format("model has no {} named '{}'", what, name));
  return id;
}

const char* WarningName(int i) {
  switch (i) {
    case mjWARN_INERTIA: return "INERTIA (near-singular inertia matrix)";
    case mjWARN_CONTACTFULL: return "CONTACTFULL (contact buffer full: contacts were dropped)";
    case mjWARN_CNSTRFULL: return "CNSTRFULL (constraint buffer full: constraints were dropped)";
    case mjWARN_VGEOMFULL: return "VGEOMFULL";
    case mjWARN_BADQPOS: return "BADQPOS (NaN or huge position; MuJoCo reset the state)";
    case mjWARN_BADQVEL: return "BADQVEL (NaN or huge velocity; MuJoCo reset the state)";
    case mjWARN_BADQACC: return "BADQACC (NaN or huge acceleration; MuJoCo reset the state)";
    case mjWARN_BADCTRL: return "BADCTRL (NaN control)";
    default: return "unknown";
  }
}

}  // namespace

int MujocoWarningsRaised() {
  InstallHandlers();
  return g_warnings_raised.load(std::memory_order_relaxed);
}

void MjModelDeleter::operator()(mjModel_* m) const { mj_deleteModel(m); }
void MjDataDeleter::operator()(mjData_* d) const { mj_deleteData(d); }

CompiledModel CompiledModel::FromXml(const std::string& xml) {
  InstallHandlers();
  // Load from an in-memory virtual file; the loader is serialised by a global lock.
  auto vfs = std::make_unique<mjVFS>();
  std::lock_guard<std::mutex> lock(LoaderMutex());
  mj_defaultVFS(vfs.get());
  const char* fname = "tactip_scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), fname, static_cast<int>(xml.size())) != 0) {
    throw ModelError("cannot allocate the in-memory MJCF file");
  }
  const int idx = mj_findFileVFS(vfs.get(), fname);
  std::memcpy(vfs->filedata[idx], xml.data(), xml.size());
  char err[1000] = {0};
  mjModel* m = mj_loadXML(fname, vfs.get(), err, sizeof(err));
  mj_deleteVFS(vfs.get());
  if (!m) throw ModelError(fmt::format("MJCF does not compile: {}", err));
  return CompiledModel(m);
}

CompiledModel CompiledModel::Copy() const { return CompiledModel(mj_copyModel(nullptr, model_.get())); }

int CompiledModel::BodyId(const std::string& n) const { return NameToId(model_.get(), mjOBJ_BODY, n, "body"); }
int CompiledModel::JointId(const std::string& n) const { return NameToId(model_.get(), mjOBJ_JOINT, n, "joint"); }
int CompiledModel::GeomId(const std::string& n) const { return NameToId(model_.get(), mjOBJ_GEOM, n, "geom"); }
int CompiledModel::SiteId(const std::string& n) const { return NameToId(model_.get(), mjOBJ_SITE, n, "site"); }
int CompiledModel::ActuatorId(const std::string& n) const {
  return NameToId(model_.get(), mjOBJ_ACTUATOR, n, "actuator");
}
int CompiledModel::FindTendon(const std::string& n) const { return mj_name2id(model_.get(), mjOBJ_TENDON, n.c_str()); }
int CompiledModel::JointQposAdr(int j) const { return model_->jnt_qposadr[j]; }
int CompiledModel::JointDofAdr(int j) const { return model_->jnt_dofadr[j]; }
void CompiledModel::EnableEnergy() { model_->opt.enableflags |= mjENBL_ENERGY; }
void CompiledModel::SetGeomFriction(int g, double mu) { model_->geom_friction[3 * g] = mu; }
void CompiledModel::SetDofDamping(int dof, double c) { model_->dof_damping[dof] = c; }
double CompiledModel::DofDamping(int dof) const { return model_->dof_damping[dof]; }
double CompiledModel::GeomFriction(int g) const { return model_->geom_friction[3 * g]; }
double CompiledModel::timestep() const { return model_->opt.timestep; }
void CompiledModel::SetTimestep(double seconds) { model_->opt.timestep = seconds; }
double CompiledModel::gravity() const { return mju_norm3(model_->opt.gravity); }
int CompiledModel::nv() const { return model_->nv; }
int CompiledModel::nu() const { return model_->nu; }
int CompiledModel::ngeom() const { return model_->ngeom; }

Simulation::Simulation(const CompiledModel& model)
    : model_(model),
      data_(mj_makeData(model.raw())),
      jac_a_(3 * static_cast<size_t>(model.nv())),
      jac_b_(3 * static_cast<size_t>(model.nv())),
      efc_vel_(static_cast<size_t>(model.raw()->njmax)),
      plane_(model.raw()) {
  if (!data_) throw ModelError("cannot allocate mjData");
  const mjModel* m = model.raw();
  // The friction pass is on when the model carries its settings (rounds, pre-sliding).
  const int id = mj_name2id(m, mjOBJ_NUMERIC, kFrictionPassNumeric);
  if (id >= 0 && m->numeric_size[id] >= 2) {
    FrictionPassSettings fs;
    fs.max_rounds = static_cast<int>(m->numeric_data[m->numeric_adr[id]]);
    fs.presliding_m = m->numeric_data[m->numeric_adr[id] + 1];
    friction_ = std::make_unique<FrictionPass>(m, fs);
  }
  const int free = mj_name2id(m, mjOBJ_NUMERIC, kFreeSlidingNumeric);
  if (free >= 0 && m->numeric_size[free] >= 1) free_sliding_speed_m_s_ = m->numeric_data[m->numeric_adr[free]];
}

Simulation::~Simulation() = default;

double Simulation::time() const { return data_->time; }

void Simulation::SetControl(int actuator, double value) { data_->ctrl[actuator] = value; }

void Simulation::Forward() {
  const double t = data_->time;
  mj_forward(model_.raw(), data_.get());
  if (plane_.active() || free_sliding_speed_m_s_ > 0.0) {
    // Solve the constraints again with the friction rows across the pressing axes and
    // fast contacts' velocity target faded out.
    PrepareConstraints();
    mj_fwdConstraint(model_.raw(), data_.get());
  }
  if (friction_) last_friction_ = friction_->Apply(model_.raw(), data_.get());
  CheckWarnings(t);
}

void Simulation::PrepareConstraints() {
  plane_.Apply(model_.raw(), data_.get());
  if (free_sliding_speed_m_s_ > 0.0) FadeFrictionReference(data_.get(), free_sliding_speed_m_s_);
}

void Simulation::Step() {
  // Split step: positions/velocities, then forces and integration (Euler), so that
  // contact Jacobians from step1 match the configuration the forces act in.
  // MuJoCo resets the state (and its time) on a bad step, so remember when it started.
  const double t = data_->time;
  const mjModel* m = model_.raw();
  mjData* d = data_.get();
  if (profiling_) {
    StepProfiled();
  } else {
    mj_step1(m, d);
    PrepareConstraints();
    if (!friction_) {
      mj_step2(m, d);
    } else {
      // mj_step2 with the friction pass between the constraint solve and integration.
      mj_fwdActuation(m, d);
      mj_fwdAcceleration(m, d);
      mj_fwdConstraint(m, d);
      last_friction_ = friction_->Apply(m, d);
      mj_sensorAcc(m, d);
      mj_checkAcc(m, d);
      mj_Euler(m, d);
    }
  }
  CheckWarnings(t);
  if (mjENABLED(mjENBL_ENERGY)) AuditEnergy();
}

void Simulation::StepProfiled() {
  // The same stages as Step, each timed (mj_step2 split up even without the pass).
  using Clock = std::chrono::steady_clock;
  const mjModel* m = model_.raw();
  mjData* d = data_.get();
  const auto lap = [](Clock::time_point& t0, double& acc) {
    const auto t1 = Clock::now();
    acc += std::chrono::duration<double>(t1 - t0).count();
    t0 = t1;
  };
  auto t0 = Clock::now();
  mj_step1(m, d);
  lap(t0, profile_.step1_s);
  profile_.nefc_sum += d->nefc;
  profile_.ncon_sum += d->ncon;
  PrepareConstraints();
  lap(t0, profile_.plane_s);
  mj_fwdActuation(m, d);
  mj_fwdAcceleration(m, d);
  lap(t0, profile_.forces_s);
  mj_fwdConstraint(m, d);
  lap(t0, profile_.solve_s);
  profile_.solver_iter_sum += d->solver_iter;
  if (friction_) last_friction_ = friction_->Apply(m, d);
  lap(t0, profile_.friction_pass_s);
  mj_sensorAcc(m, d);
  mj_checkAcc(m, d);
  mj_Euler(m, d);  // the scenes use Euler (MuJoCo 2.2.2 has no public implicit stage)
  lap(t0, profile_.integrate_s);
  ++profile_.steps;
}

StepProfile Simulation::profile() const {
  StepProfile p = profile_;
  const mjData* d = data_.get();
  p.kinematics_s = 1e-6 * d->timer[mjTIMER_POS_KINEMATICS].duration;
  p.inertia_s = 1e-6 * d->timer[mjTIMER_POS_INERTIA].duration;
  p.collision_s = 1e-6 * d->timer[mjTIMER_POS_COLLISION].duration;
  p.make_s = 1e-6 * d->timer[mjTIMER_POS_MAKE].duration;
  p.project_s = 1e-6 * d->timer[mjTIMER_POS_PROJECT].duration;
  return p;
}

void Simulation::AuditEnergy() {
  // d->energy was computed at the start of this step, with the state the last step ended
  // in: energy created by the last step = its change minus the work done over that step
  // (forces of the step times the velocity it ended with, the semi-implicit update).
  const mjModel* m = model_.raw();
  const mjData* d = data_.get();
  const double h = m->opt.timestep;
  const double energy = d->energy[0] + d->energy[1];
  if (audit_started_) energy_created_J_ = energy - energy_prev_J_ - step_prev_s_ * power_prev_W_;
  double power = 0.0;
  for (int i = 0; i < m->nv; ++i) {
    const double v = d->qvel[i];
    power += v * (d->qfrc_actuator[i] + d->qfrc_constraint[i]) - m->dof_damping[i] * v * v;
  }
  for (int t = 0; t < m->ntendon; ++t) power -= m->tendon_damping[t] * d->ten_velocity[t] * d->ten_velocity[t];
  // Elastic energy: the potential minus gravity's share (sum of m g height).
  double gravity = 0.0;
  for (int b = 1; b < m->nbody; ++b) gravity -= m->body_mass[b] * mju_dot3(m->opt.gravity, d->xipos + 3 * b);
  elastic_energy_J_ = d->energy[0] - gravity;
  energy_prev_J_ = energy;
  power_prev_W_ = power;
  step_prev_s_ = h;  // the step this power acts over (a run may change the step)
  audit_started_ = true;
}

void Simulation::CheckWarnings(double step_start_time) {
  const mjData* d = data_.get();
  for (int i = 0; i < mjNWARNING; ++i) {
    if (d->warning[i].number == warn_seen_[i]) continue;
    warn_seen_[i] = d->warning[i].number;
    if (i == mjWARN_VGEOMFULL) continue;  // rendering only
    std::string hint;
    if (i == mjWARN_CONTACTFULL || i == mjWARN_CNSTRFULL) {
      hint = "; the scene's contact budget is too small for this configuration";
    } else {
      hint = fmt::format("; reduce sim.timestep_s (now {} s) or the stiffest spring", model_.timestep());
    }
    throw SimulationError(
        fmt::format("simulation stopped at t = {:.4f} s: MuJoCo warning {}{}", step_start_time, WarningName(i), hint));
  }
}

double Simulation::Qpos(int adr) const { return data_->qpos[adr]; }
double Simulation::Qvel(int dof) const { return data_->qvel[dof]; }

double Simulation::TendonLength(int t) const { return data_->ten_length[t]; }

std::array<double, 3> Simulation::SitePos(int s) const {
  const double* p = data_->site_xpos + 3 * s;
  return {p[0], p[1], p[2]};
}

std::array<double, 3> Simulation::BodyPos(int b) const {
  const double* p = data_->xpos + 3 * b;
  return {p[0], p[1], p[2]};
}

std::array<double, 9> Simulation::BodyRot(int b) const {
  std::array<double, 9> r{};
  std::memcpy(r.data(), data_->xmat + 9 * b, sizeof(double) * 9);
  return r;
}

int Simulation::ContactCount() const { return data_->ncon; }

int Simulation::WarningCount() const {
  int n = 0;
  for (int i = 0; i < mjNWARNING; ++i) n += data_->warning[i].number;
  return n;
}

void Simulation::ReadContacts(const std::vector<int>& slot_of_geom, std::vector<GeomContact>& out) {
  const mjModel* m = model_.raw();
  mjData* d = data_.get();
  for (auto& c : out) c = GeomContact{};
  have_efc_vel_ = false;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& con = d->contact[i];
    if (con.exclude) continue;
    // Which side of the contact is tracked; the normal points from geom1 to geom2.
    int slot = slot_of_geom[con.geom2];
    double sign = 1.0;
    if (slot < 0) {
      slot = slot_of_geom[con.geom1];
      sign = -1.0;
    }
    if (slot < 0) continue;
    // Contact force in the contact frame (normal, t1, t2) -> world force on the tracked geom.
    mjtNum f6[6];
    mj_contactForce(m, d, i, f6);
    if (f6[0] <= 0.0) continue;
    GeomContact& gc = out[slot];
    gc.in_contact = true;
    gc.normal_N += f6[0];
    if (con.dim >= 3 && con.friction[0] > 0.0 && con.friction[1] > 0.0) {
      const double use = std::hypot(f6[1] / con.friction[0], f6[2] / con.friction[1]) / f6[0];
      gc.cone_use = std::max(gc.cone_use, use);
    }
    for (int k = 0; k < 3; ++k) {
      const double fw = f6[0] * con.frame[k] + f6[1] * con.frame[3 + k] + f6[2] * con.frame[6 + k];
      gc.force_world[k] += sign * fw;
      gc.normal_world[k] = sign * con.frame[k];
    }
    gc.slip_speed_m_s = std::max(gc.slip_speed_m_s, SlipSpeed(i));
  }
}

double Simulation::SlipSpeed(int i) {
  // Tangential relative velocity at a contact point. Elliptic cones: rows 1 and 2 of the
  // contact are the tangent directions, so J * qvel gives it directly.
  const mjModel* m = model_.raw();
  mjData* d = data_.get();
  const mjContact& con = d->contact[i];
  if (m->opt.cone == mjCONE_ELLIPTIC && con.dim >= 3) {
    if (!have_efc_vel_) {
      mj_mulJacVec(m, d, efc_vel_.data(), d->qvel);
      have_efc_vel_ = true;
    }
    const double v1 = efc_vel_[con.efc_address + 1], v2 = efc_vel_[con.efc_address + 2];
    return std::sqrt(v1 * v1 + v2 * v2);
  }
  // Otherwise: difference of the two bodies' point velocities, normal part taken out.
  const int nv = m->nv;
  mj_jac(m, d, jac_a_.data(), nullptr, con.pos, m->geom_bodyid[con.geom2]);
  mj_jac(m, d, jac_b_.data(), nullptr, con.pos, m->geom_bodyid[con.geom1]);
  double v[3] = {0, 0, 0};
  for (int r = 0; r < 3; ++r) {
    for (int j = 0; j < nv; ++j) v[r] += (jac_a_[r * nv + j] - jac_b_[r * nv + j]) * d->qvel[j];
  }
  const double vn = v[0] * con.frame[0] + v[1] * con.frame[1] + v[2] * con.frame[2];
  double vt2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double t = v[k] - vn * con.frame[k];
    vt2 += t * t;
  }
  return std::sqrt(vt2);
}

}  // namespace tactip
