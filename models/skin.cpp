#include "models/skin.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace tactip {

namespace {
constexpr double kSkinDensity = 1100.0;  // kg/m^3, silicone rubber
constexpr double kSkinPoisson = 0.5;     // rubber is nearly incompressible
}  // namespace

void SkinConfig::ValidateRules() const {
  const double alpha_max = rings * pitch_mm / radius_mm;
  if (alpha_max >= 0.5 * std::numbers::pi) {
    FailRule("skin.rings", rings,
             fmt::format("lattice reaches {:.2f} rad from the apex; rings * pitch_mm must be < pi/2 * radius_mm "
                         "({:.1f} mm)",
                         alpha_max, 0.5 * std::numbers::pi * radius_mm));
  }
  if (thickness_mm + pin_length_mm >= radius_mm) {
    FailRule("skin.pin_length_mm", pin_length_mm, "thickness_mm + pin_length_mm must be < radius_mm");
  }
  if (contact_radius_mm >= radius_mm) {
    FailRule("skin.contact_radius_mm", contact_radius_mm, "must be < radius_mm");
  }
}

PinLattice PinLattice::Build(const SkinConfig& skin) {
  const double a = skin.pitch_mm * 1e-3;
  const double R = skin.radius_mm * 1e-3;
  struct Planar {
    int ring;
    double az;
    double x, y;
  };
  std::vector<Planar> pts;
  // Hexagonal lattice in axial coordinates (q, r); hex distance = ring.
  for (int q = -skin.rings; q <= skin.rings; ++q) {
    for (int r = -skin.rings; r <= skin.rings; ++r) {
      const int ring = std::max({std::abs(q), std::abs(r), std::abs(q + r)});
      if (ring > skin.rings) continue;
      const double x = a * (q + 0.5 * r);
      const double y = a * (std::sqrt(3.0) / 2.0 * r);
      double az = std::atan2(y, x);
      if (az < 0) az += 2.0 * std::numbers::pi;
      if (ring == 0) az = 0.0;
      pts.push_back({ring, az, x, y});
    }
  }
  std::sort(pts.begin(), pts.end(), [](const Planar& p, const Planar& q) {
    if (p.ring != q.ring) return p.ring < q.ring;
    return p.az < q.az;
  });
  PinLattice lat;
  for (size_t i = 0; i < pts.size(); ++i) {
    // Wrap onto the dome: arc length from the apex equals the planar distance.
    const double rho = std::hypot(pts[i].x, pts[i].y);
    PinGeometry g;
    g.index = static_cast<int>(i);
    g.ring = pts[i].ring;
    g.polar_rad = rho / R;
    g.azimuth_rad = pts[i].az;
    g.normal = {std::cos(g.polar_rad), std::sin(g.polar_rad) * std::cos(g.azimuth_rad),
                std::sin(g.polar_rad) * std::sin(g.azimuth_rad)};
    lat.pins.push_back(g);
  }
  // Neighbours: planar distance equal to the pitch.
  for (size_t i = 0; i < pts.size(); ++i) {
    for (size_t j = i + 1; j < pts.size(); ++j) {
      const double d = std::hypot(pts[i].x - pts[j].x, pts[i].y - pts[j].y);
      if (std::abs(d - a) < 1e-6 * a) lat.neighbours.push_back({static_cast<int>(i), static_cast<int>(j)});
    }
  }
  return lat;
}

SkinMechanics SkinMechanics::From(const SkinConfig& skin, size_t n_pins) {
  SkinMechanics m;
  const double a = skin.pitch_mm * 1e-3;
  const double E_gel = skin.gel_modulus_kpa * 1e3;
  const double h_gel = skin.gel_depth_mm * 1e-3;
  const double E_skin = skin.skin_modulus_mpa * 1e6;
  const double t = skin.thickness_mm * 1e-3;
  const double R = skin.radius_mm * 1e-3;
  // Gel column under each pin (Winkler foundation): axial and shear stiffness.
  m.cell_area_m2 = std::sqrt(3.0) / 2.0 * a * a;
  m.k_normal_N_m = E_gel * m.cell_area_m2 / h_gel;
  m.k_shear_N_m = (E_gel / 3.0) * m.cell_area_m2 / h_gel;
  // Skin plate bending: D / a^2 couples neighbouring pins' normal displacements.
  const double D = E_skin * t * t * t / (12.0 * (1.0 - kSkinPoisson * kSkinPoisson));
  m.k_bend_N_m = D / (a * a);
  m.membrane_N_m = E_skin * t;
  m.pin_mass_kg = skin.pin_mass_g * 1e-3;
  const double alpha_max = skin.rings * a / R;
  m.shell_mass_kg = kSkinDensity * t * 2.0 * std::numbers::pi * R * R * (1.0 - std::cos(alpha_max));
  // Damping from the requested damping ratio of each mode.
  m.pin_damping_Ns_m = 2.0 * skin.damping_ratio * std::sqrt(m.k_normal_N_m * m.pin_mass_kg);
  const double n = static_cast<double>(n_pins);
  const double shell_total_mass = m.shell_mass_kg + n * m.pin_mass_kg;
  m.shell_damping_Ns_m = 2.0 * skin.shear_damping_ratio * std::sqrt(n * m.k_shear_N_m * shell_total_mass);
  return m;
}

double SkinMechanics::StiffestOmega() const {
  return std::sqrt((k_normal_N_m + 12.0 * k_bend_N_m) / pin_mass_kg);
}

std::string SkinNames::PinBody(int i) { return fmt::format("pin{}", i); }
std::string SkinNames::PinJoint(int i) { return fmt::format("pin{}_n", i); }
std::string SkinNames::PinShearJoint(int i, char axis) { return fmt::format("pin{}_t{}", i, axis); }
std::string SkinNames::PinGeom(int i) { return fmt::format("pin{}_pad", i); }
std::string SkinNames::PinSite(int i) { return fmt::format("pin{}_inner", i); }
std::string SkinNames::PinOuterSite(int i) { return fmt::format("pin{}_outer", i); }

SkinPart BuildSmoothSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                         const std::vector<bool>& collidable) {
  const SkinMechanics mech = SkinMechanics::From(skin, lattice.size());
  const double R = skin.radius_mm * 1e-3;
  const double rc = skin.contact_radius_mm * 1e-3;
  const double r_inner = R - (skin.thickness_mm + skin.pin_length_mm) * 1e-3;
  const double n = static_cast<double>(lattice.size());

  SkinPart part;
  part.collidable = collidable;
  // The skin shell: in-plane translation of the whole skin on the gel (shear springs
  // of all pins in parallel). The membrane's in-plane stiffness E t is two to three
  // orders of magnitude above a pin's gel shear stiffness, so pins move together
  // tangentially and each has its own normal DOF.
  mjcf::Element& shell = part.body;
  shell.Set("name", SkinNames::kShell);
  shell.Comment(fmt::format("smooth TacTip: {} pins, k_n {:.3g} N/m, k_shear {:.3g} N/m per pin, k_bend {:.3g} N/m, "
                            "membrane E*t {:.3g} N/m",
                            lattice.size(), mech.k_normal_N_m, mech.k_shear_N_m, mech.k_bend_N_m, mech.membrane_N_m));
  shell.Add("inertial").Set("pos", std::vector<double>{0, 0, 0}).Set("mass", mech.shell_mass_kg)
      .Set("diaginertia", std::vector<double>{1e-7, 1e-7, 1e-7});
  const bool coupled = skin.coupling == "shell";
  for (const char* axis : {"y", "z"}) {
    if (!coupled) break;  // uncoupled lattice: the shell is fixed, pins shear on their own
    shell.Add("joint")
        .Set("name", std::string("skin_shear_") + axis)
        .Set("type", "slide")
        .Set("axis", std::string(axis) == "y" ? std::vector<double>{0, 1, 0} : std::vector<double>{0, 0, 1})
        .Set("stiffness", n * mech.k_shear_N_m)
        .Set("damping", mech.shell_damping_Ns_m);
  }
  // One body per pin: a normal slide joint on its gel column, a spherical contact
  // patch whose outer surface lies on the dome, and sites at both ends.
  for (const auto& pin : lattice.pins) {
    const int i = pin.index;
    const auto& nrm = pin.normal;
    const double rb = R - rc;  // body origin = centre of the contact sphere
    mjcf::Element& b = shell.Add("body");
    b.Set("name", SkinNames::PinBody(i)).Set("pos", std::vector<double>{rb * nrm[0], rb * nrm[1], rb * nrm[2]});
    b.Add("inertial").Set("pos", std::vector<double>{0, 0, 0}).Set("mass", mech.pin_mass_kg)
        .Set("diaginertia", std::vector<double>{1e-9, 1e-9, 1e-9});
    b.Add("joint")
        .Set("name", SkinNames::PinJoint(i))
        .Set("type", "slide")
        .Set("axis", std::vector<double>{1, 0, 0})
        .Set("stiffness", mech.k_normal_N_m)
        .Set("damping", mech.pin_damping_Ns_m);
    if (!coupled) {
      // Brush model: each pin's own gel shear springs.
      const double c_shear = 2.0 * skin.shear_damping_ratio * std::sqrt(mech.k_shear_N_m * mech.pin_mass_kg);
      for (char axis : {'y', 'z'}) {
        b.Add("joint")
            .Set("name", SkinNames::PinShearJoint(i, axis))
            .Set("type", "slide")
            .Set("axis", axis == 'y' ? std::vector<double>{0, 1, 0} : std::vector<double>{0, 0, 1})
            .Set("stiffness", mech.k_shear_N_m)
            .Set("damping", c_shear);
      }
    }
    if (collidable[i]) {
      b.Add("geom")
          .Set("name", SkinNames::PinGeom(i))
          .Set("type", "sphere")
          .Set("size", std::vector<double>{rc})
          .SetInt("contype", 0)
          .SetInt("conaffinity", 2)
          .SetInt("condim", 3)
          .Set("friction", std::vector<double>{contact.friction, 0.005, 0.0001})
          .Set("solref", std::vector<double>{contact.timeconst_s, 1.0})
          .Set("solimp", std::vector<double>{contact.impedance, contact.impedance, 0.001, 0.5, 2})
          .Set("rgba", std::vector<double>{0.9, 0.9, 0.9, 1});
      ++part.n_collidable;
    }
    const double inner = r_inner - rb;
    b.Add("site").Set("name", SkinNames::PinSite(i)).Set("pos", std::vector<double>{inner * nrm[0], inner * nrm[1], inner * nrm[2]})
        .Set("size", std::vector<double>{0.0005});
    b.Add("site").Set("name", SkinNames::PinOuterSite(i)).Set("pos", std::vector<double>{rc * nrm[0], rc * nrm[1], rc * nrm[2]})
        .Set("size", std::vector<double>{0.0003});
  }
  // Skin bending couples the normal motion of neighbouring pins.
  if (coupled && mech.k_bend_N_m > 0.0) {
    for (const auto& e : lattice.neighbours) {
      mjcf::Element t("fixed");
      t.Set("name", fmt::format("bend_{}_{}", e[0], e[1])).Set("stiffness", mech.k_bend_N_m);
      t.Add("joint").Set("joint", SkinNames::PinJoint(e[0])).Set("coef", 1.0);
      t.Add("joint").Set("joint", SkinNames::PinJoint(e[1])).Set("coef", -1.0);
      part.tendons.push_back(std::move(t));
    }
  }
  return part;
}

}  // namespace tactip
