#pragma once
// The rows the friction pass solves, read from MuJoCo's constraint rows after its solve:
// the friction rows of every elliptic contact that pushes (their directions across the
// pin's pressing axis: see sim/friction_plane.h) and every dry-friction row.

#include <vector>

struct mjModel_;
struct mjData_;

namespace tactip {

/// Friction rows of one step, each a sparse row of the Jacobian.
struct FrictionRows {
  int n = 0;                     ///< rows in use
  int stride = 0;                ///< nv: room per row in col / val
  std::vector<int> efc;          ///< per row: its efc row
  std::vector<int> contact;      ///< per row: its contact, -1 for dry friction
  std::vector<int> group_size;   ///< per row: rows in its group (condim - 1 for a contact, 1 for dry friction)
  std::vector<double> limit;     ///< per row: the contact's normal force, or the frictionloss
  std::vector<double> mu;        ///< per row: friction coefficient along it (1 for dry friction)
  std::vector<double> dir;       ///< 3 per row: a contact's tangent direction (0 for torsion and rolling rows)
  std::vector<int> col;          ///< stride per row: columns of its non-zeros
  std::vector<double> val;       ///< stride per row: their values
  std::vector<int> count;        ///< per row: its non-zeros
  /// Velocity along row r for the generalized velocity qvel.
  double Velocity(int r, const double* qvel) const;
};

/// Reads FrictionRows from MuJoCo's constraint rows each step. Contacts that do not push
/// carry no friction: their friction forces are set to zero in d->efc_force.
void ReadFrictionRows(const mjModel_* m, mjData_* d, FrictionRows& rows);

}  // namespace tactip
