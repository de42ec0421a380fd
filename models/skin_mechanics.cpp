#include "models/skin_mechanics.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "models/membrane_links.h"
#include "models/rim_anchor.h"

namespace tactip {

namespace {
constexpr double kSkinDensity = 1100.0;  // kg/m^3, silicone rubber
constexpr double kSkinPoisson = 0.5;     // rubber is nearly incompressible

// Two springs in series.
double Series(double k1, double k2) { return 1.0 / (1.0 / k1 + 1.0 / k2); }
}  // namespace

SkinMechanics SkinMechanics::From(const SkinConfig& skin, size_t n_pins) {
  SkinMechanics m;
  // The materials in SI units, and the skin plate's bending rigidity.
  const double E_gel = skin.gel_modulus_kpa * 1e3;
  const double h_gel = skin.gel_depth_mm * 1e-3;
  const double E_skin = skin.skin_modulus_mpa * 1e6;
  const double t = skin.thickness_mm * 1e-3;
  const double R = skin.radius_mm * 1e-3;
  const double D = E_skin * t * t * t / (12.0 * (1.0 - kSkinPoisson * kSkinPoisson));
  double a = skin.pitch_mm * 1e-3;  // neighbour distance
  double reach = skin.rings * a;    // arc radius of the lattice
  if (skin.Fingerprint()) {
    // A pin's cell on its ring, and its ridge's rocking (RidgeCell).
    const RidgeCell ridge = RidgeCell::Of(skin, D);
    a = ridge.step_m;
    m.cell_area_m2 = a * ridge.arc_m;
    reach = skin.pattern_radius_mm * 1e-3;
    m.k_rock_N_m = ridge.k_rock_N_m;
    m.marker_rock_factor = ridge.marker_rock_factor;
  } else {
    m.cell_area_m2 = std::sqrt(3.0) / 2.0 * a * a;
  }
  // Gel column under each pin (Winkler foundation): axial and shear stiffness.
  m.k_normal_N_m = E_gel * m.cell_area_m2 / h_gel;
  m.k_shear_N_m = skin.GelShearModulusPa() * m.cell_area_m2 / h_gel;
  // Skin plate bending: D / a^2 couples neighbouring pins' normal displacements.
  m.k_bend_N_m = D / (a * a);
  m.membrane_N_m = E_skin * t;
  m.corrugation = Corrugation::Of(skin);
  m.dome_radius_m = R;
  // Per-pin shear DOFs: the contact point rides on the gel in series with the ridge.
  m.k_tip_N_m = m.k_rock_N_m > 0.0 ? Series(m.k_shear_N_m, m.k_rock_N_m) : m.k_shear_N_m;
  // A triangular spring network with springs k has a 2-D Young's modulus 2k / sqrt 3.
  m.k_link_N_m = std::sqrt(3.0) / 2.0 * m.membrane_N_m;
  m.k_couple_N_m = m.k_rock_N_m > 0.0 ? 1.0 / (1.0 / m.k_link_N_m + 2.0 / m.k_rock_N_m) : m.k_link_N_m;
  m.central_links = skin.coupling == "membrane" && skin.membrane_links == "central";
  m.orthotropic_links = skin.coupling == "membrane" && skin.membrane_links == "orthotropic";
  m.pin_mass_kg = skin.pin_mass_g * 1e-3;
  const double alpha_max = reach / R;
  m.shell_mass_kg = kSkinDensity * t * 2.0 * std::numbers::pi * R * R * (1.0 - std::cos(alpha_max));
  // Damping from the requested damping ratio of each mode.
  m.pin_damping_Ns_m = 2.0 * skin.damping_ratio * std::sqrt(m.k_normal_N_m * m.pin_mass_kg);
  const double n = static_cast<double>(n_pins);
  m.shell_moving_mass_kg = m.shell_mass_kg + n * m.pin_mass_kg;
  m.shell_damping_Ns_m = 2.0 * skin.ShellDampingRatio() * std::sqrt(n * m.k_shear_N_m * m.shell_moving_mass_kg);
  m.tip_damping_Ns_m = 2.0 * skin.shear_damping_ratio * std::sqrt(m.k_tip_N_m * m.pin_mass_kg);
  return m;
}

namespace {
// Dome springs over the whole lattice (every pin may carry one): the widest pin's 1 / cos^2,
// and the widest shear row of a spring's k_n v v^T, v = (1, a, b), a = n_y / n_x, b = n_z / n_x
// (Gershgorin: k_n |a| (1 + |a| + |b|)).
void SetDomeBounds(SkinMechanics& m, const PinLattice& lattice) {
  for (const auto& pin : lattice.pins) {
    const double a = std::abs(pin.normal[1] / pin.normal[0]), b = std::abs(pin.normal[2] / pin.normal[0]);
    m.dome_gain = std::max(m.dome_gain, 1.0 + a * a + b * b);
    m.dome_shear_row_N_m = std::max(m.dome_shear_row_N_m, m.k_normal_N_m * std::max(a, b) * (1.0 + a + b));
  }
}
}  // namespace

SkinMechanics SkinMechanics::From(const SkinConfig& skin, const PinLattice& lattice) {
  SkinMechanics m = From(skin, lattice.size());
  // The most neighbours of any pin.
  std::vector<int> degree(lattice.size(), 0);
  for (const auto& e : lattice.neighbours) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  m.max_degree = degree.empty() ? 0 : *std::max_element(degree.begin(), degree.end());
  // The clamped rim: against the whole pattern, and an outer-ring pin's share (with its ridge).
  const RimAnchor rim = RimAnchor::Of(skin, lattice);
  m.k_rim_N_m = rim.k_N_m;
  m.rim_ring = rim.outer_ring;
  if (rim.outer_ring >= 0 && skin.coupling == "membrane") {
    const double share = rim.PerPinN_m();
    m.k_rim_pin_N_m = m.k_rock_N_m > 0.0 ? Series(share, m.k_rock_N_m) : share;
  }
  // The lattice's own bounds on its stiffest modes.
  if (m.central_links) m.central_row_max_N_m = CentralRowMax(m, lattice);
  if (m.orthotropic_links) m.orthotropic_row_max_N_m = OrthotropicRowMax(m, lattice);
  if (skin.DomeSprings()) SetDomeBounds(m, lattice);
  return m;
}

double SkinMechanics::StiffestOmega() const {
  return std::sqrt((k_normal_N_m * dome_gain + 12.0 * k_bend_N_m) / pin_mass_kg);
}

double SkinMechanics::StiffestShearOmega() const {
  // Isotropic links: each adds 2 k_couple to its pins' rows. Central links: the widest row of
  // the lattice itself (From(skin, lattice)), or, without the lattice, every link at its
  // largest row sum (1 + sqrt 2) k_link. The orthotropic membrane: its widest row
  // (From(skin, lattice)), or without the lattice the central links' bound (its triangles'
  // entries are k_couple / k_link of a sheet no stiffer than E t times the developed length).
  if (orthotropic_links && orthotropic_row_max_N_m > 0.0) {
    return std::sqrt((orthotropic_row_max_N_m + dome_shear_row_N_m) / pin_mass_kg);
  }
  if (central_links || orthotropic_links) {
    const double row = central_row_max_N_m > 0.0
                           ? central_row_max_N_m
                           : k_tip_N_m + k_rim_pin_N_m + max_degree * (1.0 + std::numbers::sqrt2) * k_link_N_m;
    return std::sqrt((row + dome_shear_row_N_m) / pin_mass_kg);
  }
  return std::sqrt((k_tip_N_m + k_rim_pin_N_m + 2.0 * max_degree * k_couple_N_m + dome_shear_row_N_m) / pin_mass_kg);
}

namespace {
// The tendon springs are integrated explicitly, joint damping implicitly: the damping
// that keeps a mode of frequency w stable at dt with a 20 % margin,
// MaxStableTimestep(w, zeta) >= 1.2 dt.
double StableDamping(double w, double mass, double timestep_s) {
  // needed zeta + sqrt(zeta^2 + 1)
  const double x = SkinMechanics::kDampingRaiseMargin * timestep_s * w / (0.9 * 2.0);
  const double zeta = x > 1.0 ? (x * x - 1.0) / (2.0 * x) : 0.0;
  return 2.0 * zeta * w * mass;
}
}  // namespace

double SkinMechanics::TipDamping(double timestep_s) const {
  // A dome spring's mode runs through the shear joints too (DomeSpringDamping): they take the
  // normal mode's floor as well.
  const double dome_floor = dome_gain > 1.0 ? StableDamping(StiffestOmega(), pin_mass_kg, timestep_s) : 0.0;
  return std::max({tip_damping_Ns_m, StableDamping(StiffestShearOmega(), pin_mass_kg, timestep_s), dome_floor});
}

double SkinMechanics::NormalDamping(double timestep_s) const {
  return std::max(pin_damping_Ns_m, StableDamping(StiffestOmega(), pin_mass_kg, timestep_s));
}

double SkinMechanics::DomeSpringDamping(double c_normal, double c_tip) const {
  if (!(dome_gain > 1.0)) return c_normal;
  return 1.0 / (1.0 / c_normal + (dome_gain - 1.0) / c_tip);
}

}  // namespace tactip
