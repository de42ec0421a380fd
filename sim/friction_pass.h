#pragma once
// tactip's friction post-pass, run between MuJoCo's constraint solve and its integration
// in place of MuJoCo's noslip pass (sim.noslip = exact).
//
// MuJoCo's friction rows have no position term, so a sticking contact creeps unless a
// post-pass removes its slip. MuJoCo's noslip pass does that with Gauss-Seidel sweeps,
// which converge slowly when many contacts share a few heavy bodies and each also moves a
// light body of its own, and it holds every contact rigidly, including the tangential
// component of a pin's compression along its axis on a sloped surface, so such a contact
// can neither compress nor stay unloaded tangentially.
//
// This pass:
//  - solves the friction forces of all contacts at once (a direct solve of the friction
//    rows' Delassus system on the integrator's own velocity update, which treats joint
//    damping implicitly), clamping contacts whose force leaves the friction cone onto it
//    (they slide) and solving the rest again (an active set, warm-started from the last
//    step);
//  - gives every sticking contact an elastic pre-sliding displacement delta: its
//    friction force is f = -K s - C v with s the tangential displacement since it stuck,
//    K = mu N / delta (so every contact reaches its Coulomb limit mu N at the same
//    displacement, and contacts share a tangential load in proportion to their normal
//    force) and C = K h. Like a brush whose bristles grow with the normal force, load added
//    to a contact is carried by unstretched bristles (s shrinks by N_old / N_new) and load
//    taken off removes bristles with their stretch (s stays). delta = 0 gives rigid stick,
//    with the load shared in proportion to the normal forces where rigid contacts share
//    bodies.

#include <cstdint>
#include <vector>

#include "sim/delassus.h"
#include "sim/friction_rows.h"

struct mjModel_;
struct mjData_;

namespace tactip {

/// What one friction pass did.
struct FrictionPassStats {
  int rows = 0;     ///< friction rows solved
  int sliding = 0;  ///< contacts (or dry-friction rows) held on their friction limit
  int rounds = 0;   ///< linear solves
};

/// Settings of the pass, read from the model's custom numeric kFrictionPassNumeric.
struct FrictionPassSettings {
  int max_rounds = 10;         ///< clamp-and-solve rounds
  double presliding_m = 1e-5;  ///< tangential displacement at the Coulomb limit (0: rigid stick)
};

/// The friction post-pass. Buffers are sized once for the model's constraint budget, so
/// Apply() allocates nothing (beyond growing its contact table to the contact budget).
class FrictionPass {
 public:
  FrictionPass(const mjModel_* m, const FrictionPassSettings& settings);

  /// Call between mj_fwdConstraint and integration. Replaces the friction forces in
  /// d->efc_force, then recomputes d->qfrc_constraint and d->qacc.
  FrictionPassStats Apply(const mjModel_* m, mjData_* d);

 private:
  // A contact's stick state between steps, keyed by its geom pair.
  struct Stick {
    std::uint64_t key = 0;
    double s[3] = {0, 0, 0};  // tangential displacement since it stuck, world frame
    double f[3] = {0, 0, 0};  // friction force at the end of the last step, world frame
    double normal_N = 0.0;    // normal force in the last step
    bool sliding = false;     // on its friction limit at the end of the last step
    bool seen = false;
  };

  void BuildSystem(const mjModel_* m, mjData_* d);
  void ContactSprings(const mjModel_* m, const mjData_* d);
  void StartFromLastState(const mjData_* d);
  int DryDof(const mjData_* d, int k) const;
  void SolveFree();
  int UpdateClampedGroups();
  int ClampOutsideLimits();
  void SaveState(const mjModel_* m, const mjData_* d);
  void WriteBack(const mjModel_* m, mjData_* d);
  bool UseDampedMass(const mjModel_* m, mjData_* d, bool on);
  Stick* FindStick(std::uint64_t key);
  Stick& StickOf(std::uint64_t key);

  FrictionPassSettings settings_;
  int nv_ = 0, n_ = 0;             // dofs; friction rows in use
  FrictionRows rows_;
  Delassus delassus_;
  std::vector<double> reg_;        // per row: R = 1 / (h (K h + C)), 0 for rigid rows
  std::vector<double> spring_;     // per row: the anchor spring's pull, R K s (rigid: s / h^2)
  std::vector<double> disp_;       // per row: s along the row's direction
  std::vector<double> stiff_;      // per row: K (0 for rigid rows)
  std::vector<double> capacity_;   // per row: mu N (or frictionloss)
  std::vector<char> clamped_;      // per row: held on its limit
  std::vector<double> target_;     // per row: -(v / h + J qacc_nf), the rigid-stick right-hand side
  std::vector<double> f0_, f_, af_;  // friction forces: the main solver's, the pass's; A f
  std::vector<double> rhs_, x_;    // the free subsystem
  std::vector<int> free_;          // local indices of the free rows
  std::vector<double> qfrc_, qacc0_;  // nv scratch; (M + h B)^-1 (smooth + constraint forces but friction)
  std::vector<double> qfrc_nf_;    // nv: constraint forces without friction
  std::vector<double> qLD_, qLDiagInv_, qLDiagSqrtInv_, qM_diag_;  // M's factor and diagonal, kept aside
  std::vector<Stick> sticks_;      // contacts' stick states, sorted by key
  std::vector<char> dof_sliding_;  // per dof: its dry friction was on its limit at the end of the last step
};

}  // namespace tactip
