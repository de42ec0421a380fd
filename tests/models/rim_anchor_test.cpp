#include "models/rim_anchor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <mujoco/mujoco.h>
#include <fmt/format.h>

#include "input_error.h"
#include "models/rail_rig.h"
#include "models/skin.h"
#include "mujoco_warning_guard.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

// How the rigid disc moves: a unit translation along x, or a unit rotation about its centre.
enum class DiscMotion { kTranslation, kRotation };

using Node = std::pair<double, double>;

std::pair<double, double> RigidDisplacement(DiscMotion motion, const Node& n) {
  return motion == DiscMotion::kTranslation ? std::pair{1.0, 0.0} : std::pair{-n.second, n.first};
}

// A triangular spring network (spacing h, springs k) filling a disc a little beyond `outer`:
// nodes within `inner` move rigidly, nodes beyond `outer` are held, the rest find
// equilibrium. Returns the force along x (translation) or the torque (rotation) on the disc.
double NetworkAnnulusStiffness(double inner, double outer, double h, double k, DiscMotion motion) {
  const double reach = outer + 1.5 * h, row = h * std::sqrt(3.0) / 2.0;
  const int rows = static_cast<int>(reach / row) + 2, columns = static_cast<int>(reach / h) + rows / 2 + 2;
  std::vector<Node> nodes;
  std::map<std::pair<int, int>, int> index;
  for (int j = -rows; j <= rows; ++j) {
    for (int i = -columns; i <= columns; ++i) {
      const double x = (i + 0.5 * j) * h, y = j * row;
      if (std::hypot(x, y) > reach) continue;
      index[{i, j}] = static_cast<int>(nodes.size());
      nodes.emplace_back(x, y);
    }
  }
  enum Kind { kRigid, kFree, kHeld };
  std::vector<Kind> kind(nodes.size());
  std::vector<int> dof(nodes.size(), -1);
  int n_free = 0;
  for (size_t n = 0; n < nodes.size(); ++n) {
    const double r = std::hypot(nodes[n].first, nodes[n].second);
    kind[n] = r <= inner ? kRigid : (r >= outer ? kHeld : kFree);
    if (kind[n] == kFree) dof[n] = n_free++;
  }
  // Each spring's linearised stiffness k e e^T; the rigid nodes' displacement is the load.
  struct Tie {
    double ex, ey;
    int free_dof, rigid_node;
  };
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n_free);
  std::vector<Tie> ties;  // springs from a rigid node to a free one
  const int steps[3][2] = {{1, 0}, {0, 1}, {-1, 1}};
  for (const auto& [ij, a] : index) {
    for (const auto& s : steps) {
      const auto it = index.find({ij.first + s[0], ij.second + s[1]});
      if (it == index.end()) continue;
      const int b = it->second;
      const double ex = (nodes[b].first - nodes[a].first) / h, ey = (nodes[b].second - nodes[a].second) / h;
      const double kee[2][2] = {{k * ex * ex, k * ex * ey}, {k * ex * ey, k * ey * ey}};
      for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
        if (kind[p] != kFree) continue;
        const auto [ux, uy] = RigidDisplacement(motion, nodes[q]);
        for (int r = 0; r < 2; ++r) {
          for (int c = 0; c < 2; ++c) {
            triplets.emplace_back(2 * dof[p] + r, 2 * dof[p] + c, kee[r][c]);
            if (kind[q] == kFree) triplets.emplace_back(2 * dof[p] + r, 2 * dof[q] + c, -kee[r][c]);
          }
          if (kind[q] == kRigid) rhs[2 * dof[p] + r] += kee[r][0] * ux + kee[r][1] * uy;
        }
        if (kind[q] == kRigid) ties.push_back({ex, ey, dof[p], q});
      }
    }
  }
  Eigen::SparseMatrix<double> K(2 * n_free, 2 * n_free);
  K.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K);
  EXPECT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd u = solver.solve(rhs);
  // Each tie pulls its rigid node with k e (e . (u_free - u_rigid)).
  double load = 0.0;
  for (const Tie& t : ties) {
    const Node& n = nodes[t.rigid_node];
    const auto [ux, uy] = RigidDisplacement(motion, n);
    const double stretch = t.ex * (u[2 * t.free_dof] - ux) + t.ey * (u[2 * t.free_dof + 1] - uy);
    load += motion == DiscMotion::kTranslation ? k * stretch * t.ex : k * stretch * (n.first * t.ey - n.second * t.ex);
  }
  return -load;
}

// The network's plane-stress constants: E t = 2 k / sqrt 3, nu = 1/3, so mu t = sqrt(3) k / 4.
double NetworkShearModulusTimesThickness(double k) { return std::sqrt(3.0) * k / 4.0; }

TEST(RimAnchorTest, ClampedAnnulusFormulaMatchesASolvedSpringNetwork) {
  const double k = 100.0, h = 0.25, b = 31.4;  // springs in N/m, lengths in mm: the formulas are scale-free
  const double mu_t = NetworkShearModulusTimesThickness(k);
  for (const double a : {8.0, 18.0}) {
    // The network itself (its staircase edges cost it a few per cent): the rigid disc's rotation has the exact torsion stiffness
    // 4 pi mu t a^2 b^2 / (b^2 - a^2) whatever the Poisson ratio.
    const double torsion = 4.0 * std::numbers::pi * mu_t * a * a * b * b / (b * b - a * a);
    EXPECT_NEAR(NetworkAnnulusStiffness(a, b, h, k, DiscMotion::kRotation) / torsion, 1.0, 0.03) << "a " << a;
    // The translation the rim anchor uses.
    const double network = NetworkAnnulusStiffness(a, b, h, k, DiscMotion::kTranslation);
    const double formula = ClampedAnnulusTranslationStiffness(mu_t, kMembranePoisson, a, b);
    EXPECT_NEAR(network / formula, 1.0, 0.03) << "a " << a << ": network " << network << ", formula " << formula;
  }
}

TEST(RimAnchorTest, FormulaRefusesAnAnnulusThatIsNotOne) {
  EXPECT_THROW(ClampedAnnulusTranslationStiffness(1.0, kMembranePoisson, 2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ClampedAnnulusTranslationStiffness(0.0, kMembranePoisson, 1.0, 2.0), std::invalid_argument);
}

TEST(RimAnchorTest, AFreeRimAndTheUncoupledLatticeHoldNothing) {
  SkinConfig skin;
  EXPECT_EQ(RimAnchor::Of(skin, PinLattice::Build(skin)).k_N_m, 0.0);
  skin.rim = "clamped";
  skin.coupling = "none";
  EXPECT_EQ(RimAnchor::Of(skin, PinLattice::Build(skin)).k_N_m, 0.0);
}

TEST(RimAnchorTest, TheSmoothSkinsAnnulusRunsFromItsOuterRingToTheDomesBase) {
  SkinConfig skin;
  skin.rim = "clamped";
  const PinLattice lattice = PinLattice::Build(skin);
  const RimAnchor rim = RimAnchor::Of(skin, lattice);
  EXPECT_EQ(rim.outer_ring, 6);
  EXPECT_EQ(rim.outer_ring_pins, 36);
  // The hexagon's sixth ring lies between 15.6 mm (mid-sides) and 18 mm (corners) of arc.
  EXPECT_GT(rim.pattern_edge_m, (15.6 + 1.5) * 1e-3);
  EXPECT_LT(rim.pattern_edge_m, (18.0 + 1.5) * 1e-3);
  EXPECT_NEAR(rim.rim_m, 0.5 * std::numbers::pi * 20e-3, 1e-12);
  const double mu_t = 1e6 * 1e-3 * 3.0 / 8.0;  // E t / (2 (1 + 1/3)), 1 MPa, 1 mm
  EXPECT_NEAR(rim.k_N_m, ClampedAnnulusTranslationStiffness(mu_t, 1.0 / 3.0, rim.pattern_edge_m, rim.rim_m), 1e-9);
  // Linear in the skin's modulus and thickness.
  skin.skin_modulus_mpa = 0.4;
  EXPECT_NEAR(RimAnchor::Of(skin, lattice).k_N_m / rim.k_N_m, 0.4, 1e-12);
}

TEST(RimAnchorTest, APatternReachingTheBaseCannotBeClamped) {
  SkinConfig skin;
  skin.rim = "clamped";
  skin.rings = 10;  // 30 mm of arc, edge 31.5 mm: beyond the base at 31.4 mm
  const std::string what = InputErrorOf([&] { skin.ValidateRules(); });
  EXPECT_NE(what.find("skin.rim"), std::string::npos) << what;
  skin.rim = "free";
  EXPECT_NO_THROW(skin.ValidateRules());
}

class RimAnchorSceneTest : public testing::MujocoWarningGuard {};

TEST_F(RimAnchorSceneTest, TheShellAndTheOuterRingCarryTheAnnulus) {
  RailSceneSpec spec;
  spec.max_depth_m = 3.1e-3;
  spec.skin.rim = "clamped";
  const SkinMechanics shell = SkinMechanics::From(spec.skin, PinLattice::Build(spec.skin));
  const CompiledModel smooth = CompiledModel::FromXml(BuildRailScene(spec).xml);
  EXPECT_NEAR(smooth.raw()->jnt_stiffness[smooth.JointId("tactip/skin_shear_y")],
              127.0 * shell.k_shear_N_m + shell.k_rim_N_m, 1e-9);
  EXPECT_GT(shell.k_rim_N_m, 127.0 * shell.k_shear_N_m);  // the rubber annulus outweighs the gel

  for (const auto& assignment : SkinPreset("fingerprint-v2")) {
    auto [key, value] = ParseAssignment(assignment);
    ApplyFlat(spec.skin, FlatConfig{{key.substr(5), value}});
  }
  const PinLattice lattice = PinLattice::Build(spec.skin);
  const SkinMechanics mech = SkinMechanics::From(spec.skin, lattice);
  const RimAnchor rim = RimAnchor::Of(spec.skin, lattice);
  const double share = rim.PerPinN_m();
  EXPECT_NEAR(mech.k_rim_pin_N_m, 1.0 / (1.0 / share + 1.0 / mech.k_rock_N_m), 1e-9);
  const CompiledModel v2 = CompiledModel::FromXml(BuildRailScene(spec).xml);
  const int outer = static_cast<int>(lattice.size()) - 1, centre = 0;
  EXPECT_EQ(lattice.pins[outer].ring, rim.outer_ring);
  EXPECT_NEAR(v2.raw()->jnt_stiffness[v2.JointId(fmt::format("tactip/pin{}_ty", outer))],
              mech.k_tip_N_m + mech.k_rim_pin_N_m, 1e-9);
  EXPECT_NEAR(v2.raw()->jnt_stiffness[v2.JointId(fmt::format("tactip/pin{}_ty", centre))], mech.k_tip_N_m, 1e-9);
}

}  // namespace
}  // namespace tactip
