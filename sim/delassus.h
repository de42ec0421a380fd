#pragma once
// The friction rows' Delassus operator A = J (M + h B)^-1 J' and the linear solves the
// friction pass needs with it.
//
// The friction rows usually touch only a few dofs that are shared (skin shell, arm,
// object) besides each pin's own: with C those k columns, A = J_C P J_C' where
// P = ((M + h B)^-1)_CC takes one solve per column instead of one per row, and a solve
// with A_SS + R_S (R > 0: compliant rows) takes a k x k factor (Woodbury), the few rigid
// rows by their Schur complement. Otherwise A is formed densely (one solve per row) and
// the free subsystem factored by Cholesky.

#include <vector>

#include "sim/friction_rows.h"

struct mjModel_;
struct mjData_;

namespace tactip {

class Delassus {
 public:
  Delassus(const mjModel_* m, int max_rows);
  /// Builds A for `rows`; d->qLD must hold the factor of M + h B.
  void Build(const mjModel_* m, mjData_* d, const FrictionRows& rows);
  /// A(r, l).
  double At(int r, int l) const;
  /// out = A f over all rows, or over the rows with mask[l] != 0 only.
  void Multiply(const double* f, const char* mask, double* out) const;
  /// Row-by-row updates (Gauss-Seidel): Track(f) starts from forces f, then
  /// RowTimesTracked(r) = (A f)_r and Change(l, delta) adds delta to f_l.
  void Track(const double* f);
  double RowTimesTracked(int r) const;
  void Change(int l, double delta);
  /// Solves (A_SS + diag(reg_S) + E) x = rhs over the free rows S = free[0..ns), where
  /// rows with reg = 0 are rigid and get the tiny weight E = eps / cap^2 (eps relative to
  /// A's diagonal, cap = capacity relative to the largest): among the solutions of a
  /// singular rigid system it takes the one that loads rows in proportion to capacity.
  void SolveFree(int ns, const int* free, const double* reg, const double* capacity, const double* rhs, double* x);

 private:
  bool BuildLowRank(const mjModel_* m, mjData_* d, const FrictionRows& rows);
  void BuildDense(const mjModel_* m, mjData_* d, const FrictionRows& rows);
  void SolveWoodbury(int ns, const int* free, const double* reg, const double* capacity, const double* rhs,
                     double* x);
  void SolveDense(int ns, const int* free, const double* reg, const double* capacity, const double* rhs, double* x);
  void FactorCompliant(int ns, const int* free, const double* reg);
  void CompliantSolve(int ns, const int* free, const double* reg, const double* in, double* out) const;
  double RowTimes(int ns, const int* free, const double* reg, int row, const double* x) const;
  double RigidWeight(int ns, const int* free, const double* capacity, int k) const;

  static constexpr int kMaxLowRank = 24;  // most shared columns for the low-rank form
  static constexpr int kMaxRigid = 8;     // most rigid free rows for the low-rank solve
  int nv_ = 0, n_ = 0, k_ = 0;
  bool low_rank_ = false;
  std::vector<double> A_, L_, Js_, X_;  // dense form: A, factor scratch, J and (M + hB)^-1 J'
  std::vector<int> support_, column_slot_;
  std::vector<double> Y_, P_, Pinv_, Jc_, Z_, U_, scratch_;
  double woodbury_[kMaxLowRank * kMaxLowRank] = {0};
  double tracked_[kMaxLowRank] = {0};  // J_C' f
  const double* tracked_f_ = nullptr;  // dense form: the forces Track() was given
};

}  // namespace tactip
