#pragma once
// Ownership of MuJoCo models and data, fixed-step stepping with stability checks, and
// contact read-out. This folder is the only code that includes <mujoco/mujoco.h>.

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/base/errors.h"
#include "sim/friction_plane.h"
#include "sim/step_profile.h"
#include "sim/friction_pass.h"
#include "sim/sim_config.h"

struct mjModel_;
struct mjData_;

namespace tactip {

/// Warnings MuJoCo has sent to its warning hook in this process so far: from any model or
/// mjData, stepped by a Simulation or not. MuJoCo 2.2.2 sends a kind of warning only the
/// first time it occurs in an mjData (Simulation::WarningCount counts every occurrence).
/// For tests: work that raised no warning leaves it unchanged. Installs tactip's handlers.
int MujocoWarningsRaised();

/// Deleters so MuJoCo structs live in std::unique_ptr.
struct MjModelDeleter {
  void operator()(mjModel_* m) const;
};
struct MjDataDeleter {
  void operator()(mjData_* d) const;
};

/// A compiled MuJoCo model. One instance may be read by many Simulations (each with
/// its own mjData); per-run variations use Copy() and the setters.
class CompiledModel {
 public:
  /// Compiles MJCF text; throws ModelError with MuJoCo's message. Serialised by a lock
  /// because MuJoCo's XML loader is not thread-safe.
  static CompiledModel FromXml(const std::string& xml);
  /// Deep copy, for per-run parameter changes.
  CompiledModel Copy() const;

  /// Ids by name; throw ModelError naming the missing element.
  int BodyId(const std::string& name) const;
  int JointId(const std::string& name) const;
  int GeomId(const std::string& name) const;
  int SiteId(const std::string& name) const;
  int ActuatorId(const std::string& name) const;
  /// A tendon's id, or -1 when the model has none of that name.
  int FindTendon(const std::string& name) const;
  /// Index of a joint's first qpos / first dof.
  int JointQposAdr(int joint) const;
  int JointDofAdr(int joint) const;

  /// Makes MuJoCo compute the mechanical energy each step (for Simulation's energy audit).
  void EnableEnergy();
  /// Sets the sliding friction coefficient of one geom (the contact uses the max of the pair).
  void SetGeomFriction(int geom, double mu);
  /// Sets the viscous damping of one dof (N s/m; MuJoCo integrates it implicitly).
  void SetDofDamping(int dof, double damping);
  double DofDamping(int dof) const;
  /// Sliding friction coefficient of one geom.
  double GeomFriction(int geom) const;
  /// Physics timestep in seconds.
  double timestep() const;
  /// Changes the physics step from the next step on (a run refines it at an event).
  void SetTimestep(double seconds);
  /// Gravity magnitude in m/s^2.
  double gravity() const;
  int nv() const;
  int nu() const;
  int ngeom() const;

  /// The raw model, for code inside sim/.
  const mjModel_* raw() const { return model_.get(); }

 private:
  explicit CompiledModel(mjModel_* m) : model_(m) {}
  std::unique_ptr<mjModel_, MjModelDeleter> model_;
};

/// Contact state of one tracked geom at the current step, forces on that geom.
struct GeomContact {
  bool in_contact = false;                ///< at least one active contact
  double normal_N = 0.0;                  ///< summed normal force magnitude
  std::array<double, 3> force_world{};    ///< total contact force on the geom, world frame
  std::array<double, 3> normal_world{};   ///< contact normal pointing into the geom
  double slip_speed_m_s = 0.0;            ///< tangential relative speed at the contact point
  /// Friction force over its Coulomb limit, in the contact's own friction rows:
  /// |(f_1 / mu_1, f_2 / mu_2)| / f_n, 1 on the cone (the largest of the geom's contacts).
  /// The friction rows of a sloped pin lie across its pressing axis (FrictionPlane), not in
  /// the contact's tangent plane, so the world-frame split of force_world into normal and
  /// tangential parts puts a sliding contact at |f_t| / (mu f_n) = cos(tilt) < 1.
  double cone_use = 0.0;
};

/// One simulation instance: mjData plus the stepping loop. The CompiledModel must
/// outlive it. Not thread-safe; use one per thread.
class Simulation {
 public:
  explicit Simulation(const CompiledModel& model);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Simulated time in seconds.
  double time() const;
  /// Sets one actuator's control input.
  void SetControl(int actuator, double value);
  /// Advances one timestep; throws SimulationError on BADQACC/BADQPOS/BADQVEL (NaN or
  /// reset state), CONTACTFULL or CNSTRFULL (silently dropped constraints), and on a MuJoCo
  /// internal error ("MuJoCo internal error: ..."), after which this Simulation is unusable.
  void Step();
  /// Runs forward kinematics and contacts without advancing time (for the initial state).
  void Forward();

  double Qpos(int adr) const;
  double Qvel(int dof) const;
  /// World position of a site / body origin (metres).
  std::array<double, 3> SitePos(int site) const;
  std::array<double, 3> BodyPos(int body) const;
  /// A tendon's length (m for slide joints), as the last position pass computed it.
  double TendonLength(int tendon) const;
  /// World rotation of a body, row-major 3x3.
  std::array<double, 9> BodyRot(int body) const;

  /// Reads the contacts of the tracked geoms. `slot_of_geom` maps geom id -> output
  /// slot (or -1); `out` must have one entry per slot. Slip speed uses the velocity
  /// after the last step at the configuration the contacts were detected in, through the
  /// friction rows (across a pin's pressing axis: see FrictionPlane).
  void ReadContacts(const std::vector<int>& slot_of_geom, std::vector<GeomContact>& out);
  /// Number of active contacts.
  int ContactCount() const;
  /// Total number of warnings MuJoCo has raised in this run (all kinds).
  int WarningCount() const;
  /// Times every stage of Step from now on (see StepProfile).
  void EnableProfile() { profiling_ = true; }
  /// The stage times summed since EnableProfile().
  StepProfile profile() const;
  /// Energy audit of the last completed step (needs CompiledModel::EnableEnergy): the
  /// mechanical energy the integration created, E(after) - E(before) - work of actuators,
  /// damping and constraints (J; 0 until two steps are done), and the elastic energy stored
  /// in springs and tendons at the step's start (J).
  double energy_created_J() const { return energy_created_J_; }
  double elastic_energy_J() const { return elastic_energy_J_; }
  /// The raw data, for code inside sim/ (e.g. the renderer).
  const mjData_* raw() const { return data_.get(); }
  /// True when the model asks for tactip's friction pass (see FrictionPass).
  bool friction_pass() const { return friction_ != nullptr; }
  /// What the friction pass did in the last step (zeros when it is off).
  const FrictionPassStats& last_friction_pass() const { return last_friction_; }

 private:
  void CheckWarnings(double step_start_time);
  void AuditEnergy();
  double SlipSpeed(int contact);
  void StepProfiled();
  void PrepareConstraints();  // friction plane and friction reference, between position stage and solve
  const CompiledModel& model_;
  std::unique_ptr<mjData_, MjDataDeleter> data_;
  std::vector<double> jac_a_, jac_b_;  // 3 x nv scratch for contact-point Jacobians
  std::vector<double> efc_vel_;        // constraint-space velocity J * qvel (njmax)
  bool have_efc_vel_ = false;          // efc_vel_ holds this read-out's velocities
  FrictionPlane plane_;                // friction rows across the pins' pressing axes
  double free_sliding_speed_m_s_ = 0.0;  // faster contacts: friction velocity target faded out (0: off)
  std::array<int, 8> warn_seen_{};
  std::unique_ptr<FrictionPass> friction_;  // null: MuJoCo's own noslip (or none)
  FrictionPassStats last_friction_;
  bool profiling_ = false;
  StepProfile profile_;
  // Energy audit: energy and non-conservative power of the previous step.
  bool audit_started_ = false;
  double energy_prev_J_ = 0.0, power_prev_W_ = 0.0, step_prev_s_ = 0.0;
  double energy_created_J_ = 0.0, elastic_energy_J_ = 0.0;
};

}  // namespace tactip
