#include "models/skin_part.h"

#include <array>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "models/membrane_elements.h"
#include "models/skin_mechanics.h"
#include "sim/pressing_axis.h"

namespace tactip {

std::string SkinNames::PinBody(int i) const { return prefix + fmt::format("pin{}", i); }
std::string SkinNames::PinJoint(int i) const { return prefix + fmt::format("pin{}_n", i); }
std::string SkinNames::PinShearJoint(int i, char axis) const { return prefix + fmt::format("pin{}_t{}", i, axis); }
std::string SkinNames::PinDomeSpring(int i) const { return prefix + fmt::format("pin{}_dome_spring", i); }
std::string SkinNames::PinGeom(int i) const { return prefix + fmt::format("pin{}_pad", i); }
std::string SkinNames::PinSite(int i) const { return prefix + fmt::format("pin{}_inner", i); }
std::string SkinNames::PinOuterSite(int i) const { return prefix + fmt::format("pin{}_outer", i); }

SkinPart BuildSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                   const std::vector<bool>& collidable, double timestep_s) {
  return BuildSkin(skin, contact, lattice, collidable, timestep_s, std::vector<bool>(lattice.size(), true));
}

namespace {

// What every pin body of one skin shares: the radii, the joints' damping and which pins
// carry a normal DOF, a contact geom and an outer site.
struct PinBodyPlan {
  const SkinConfig& skin;
  const ContactConfig& contact;
  const SkinMechanics& mech;
  const SkinNames& names;
  const std::vector<bool>& collidable;  // pins with a contact geom
  const std::vector<bool>& outer_site;  // pins with a site at their outer contact point
  double rc = 0.0;        // contact sphere radius (m)
  double rb = 0.0;        // pin body origin = centre of the contact sphere, from the dome centre (m)
  double r_marker = 0.0;  // the marker (pin inner end) from the dome centre (m)
  double c_tip = 0.0, c_normal = 0.0;
  bool shell_mode = false;
  std::vector<bool> normal_dof{};  // pins with a normal slide joint
};

// The skin shell body: a comment with the mechanics, its inertia, and in shell mode its two
// in-plane slide joints on the gel (shear springs of all pins in parallel).
void AddShell(mjcf::Element& shell, const PinBodyPlan& plan, size_t n_pins) {
  const SkinConfig& skin = plan.skin;
  const SkinMechanics& mech = plan.mech;
  // The name, the mechanics as a comment, and the membrane's inertia.
  shell.Set("name", plan.names.Shell());
  shell.Comment(fmt::format("{} skin ({} coupling): {} pins, k_n {:.3g} N/m, k_shear {:.3g} N/m per pin, k_bend {:.3g} "
                            "N/m, membrane E*t {:.3g} N/m, k_rock {:.3g} N/m, k_tip {:.3g} N/m, k_couple {:.3g} N/m, "
                            "{} membrane links, {} normal springs, shear damping {:.3g} N s/m, normal damping "
                            "{:.3g} N s/m, clamped rim {:.3g} N/m",
                            skin.pattern, skin.coupling, n_pins, mech.k_normal_N_m, mech.k_shear_N_m,
                            mech.k_bend_N_m, mech.membrane_N_m, mech.k_rock_N_m, mech.k_tip_N_m, mech.k_couple_N_m,
                            skin.membrane_links, skin.DomeSprings() ? "dome" : "axial", plan.c_tip, plan.c_normal,
                            mech.k_rim_N_m));
  shell.Add("inertial").Set("pos", std::vector<double>{0, 0, 0}).Set("mass", mech.shell_mass_kg)
      .Set("diaginertia", std::vector<double>{1e-7, 1e-7, 1e-7});
  // The in-plane slide joints (shell mode only).
  if (!plan.shell_mode) return;
  for (const char* axis : {"y", "z"}) {
    shell.Add("joint")
        .Set("name", plan.names.Part(std::string("skin_shear_") + axis))
        .Set("type", "slide")
        .Set("axis", std::string(axis) == "y" ? std::vector<double>{0, 1, 0} : std::vector<double>{0, 0, 1})
        .Set("stiffness", mech.ShellShearStiffness(n_pins))
        .Set("damping", mech.shell_damping_Ns_m);
  }
}

// One pin body: a normal slide joint on its gel column, its own shear joints unless the
// shell carries them, a spherical contact patch whose outer surface lies on the contact
// surface, and sites at both ends.
void AddPinBody(mjcf::Element& shell, const PinBodyPlan& plan, const PinGeometry& pin) {
  const int i = pin.index;
  const auto& nrm = pin.normal;
  const SkinMechanics& mech = plan.mech;
  const SkinNames& names = plan.names;
  const double rb = plan.rb, rc = plan.rc;
  // The body at the contact sphere's centre, and its mass.
  mjcf::Element& b = shell.Add("body");
  b.Set("name", names.PinBody(i)).Set("pos", std::vector<double>{rb * nrm[0], rb * nrm[1], rb * nrm[2]});
  b.Add("inertial").Set("pos", std::vector<double>{0, 0, 0}).Set("mass", mech.pin_mass_kg)
      .Set("diaginertia", std::vector<double>{1e-9, 1e-9, 1e-9});
  if (plan.normal_dof[i]) {
    // With dome springs the gel column's spring is the pin's tendon (DomeSpringTendon).
    b.Add("joint")
        .Set("name", names.PinJoint(i))
        .Set("user", std::vector<double>{kCompressionJointUser})
        .Set("type", "slide")
        .Set("axis", std::vector<double>{1, 0, 0})
        .Set("stiffness", plan.skin.DomeSprings() ? 0.0 : mech.k_normal_N_m)
        .Set("damping", plan.c_normal);
  }
  if (!plan.shell_mode) {
    // The pin's own shear springs: gel column (in series with its ridge).
    for (char axis : {'y', 'z'}) {
      b.Add("joint")
          .Set("name", names.PinShearJoint(i, axis))
          .Set("type", "slide")
          .Set("axis", axis == 'y' ? std::vector<double>{0, 1, 0} : std::vector<double>{0, 0, 1})
          .Set("stiffness", mech.TipStiffness(pin.ring))
          .Set("damping", plan.c_tip);
    }
  }
  if (plan.collidable[i]) {
    // The contact patch.
    const ContactConfig& contact = plan.contact;
    b.Add("geom")
        .Set("name", names.PinGeom(i))
        .Set("type", "sphere")
        .Set("size", std::vector<double>{rc})
        .SetInt("contype", 0)
        .SetInt("conaffinity", 2)
        .SetInt("condim", 3)
        .Set("friction", std::vector<double>{contact.friction, 0.005, 0.0001})
        .Set("solref", std::vector<double>{contact.timeconst_s, 1.0})
        .Set("solimp", contact.Solimp())
        .Set("rgba", std::vector<double>{0.9, 0.9, 0.9, 1});
  }
  // The marker sites: the inner end, and the outer contact point where asked for.
  const double inner = plan.r_marker - rb;
  b.Add("site").Set("name", names.PinSite(i)).Set("pos", std::vector<double>{inner * nrm[0], inner * nrm[1], inner * nrm[2]})
      .Set("size", std::vector<double>{0.0005});
  if (plan.outer_site[i]) {
    b.Add("site").Set("name", names.PinOuterSite(i)).Set("pos", std::vector<double>{rc * nrm[0], rc * nrm[1], rc * nrm[2]})
        .Set("size", std::vector<double>{0.0003});
  }
}

// A central membrane link (skin.membrane_links = central): one spring along the link's
// direction e in the sensor's y-z plane, L = e . (u_0 - u_1) over the two pins' shear joints,
// whose stiffness takes the ridges' rocking by the link's radial share
// (SkinMechanics::CentralLinkBetween).
mjcf::Element CentralLinkTendon(const PinBodyPlan& plan, const PinLattice& lattice, const std::array<int, 2>& e) {
  const SkinMechanics::CentralLink l = plan.mech.CentralLinkBetween(lattice.pins[e[0]], lattice.pins[e[1]]);
  const SkinNames& names = plan.names;
  mjcf::Element t("fixed");
  t.Set("name", names.Part(fmt::format("membrane_{}_{}", e[0], e[1]))).Set("stiffness", l.k_N_m);
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? 1.0 : -1.0;
    t.Add("joint").Set("joint", names.PinShearJoint(e[side], 'y')).Set("coef", sign * l.ey);
    t.Add("joint").Set("joint", names.PinShearJoint(e[side], 'z')).Set("coef", sign * l.ez);
  }
  return t;
}

// The orthotropic membrane (skin.membrane_links = orthotropic): one fixed tendon per stiffness
// mode of each triangle, L = a . u over its three pins' shear joints, stiffness k.
std::vector<mjcf::Element> OrthotropicTendons(const PinBodyPlan& plan, const PinLattice& lattice) {
  std::vector<mjcf::Element> tendons;
  const SkinNames& names = plan.names;
  const std::vector<MembraneMode> modes = OrthotropicMembraneModes(plan.mech, lattice);
  for (size_t m = 0; m < modes.size(); ++m) {
    const MembraneMode& mode = modes[m];
    mjcf::Element t("fixed");
    t.Set("name", names.Part(fmt::format("membrane_mode_{}", m)))
        .Set("stiffness", mode.k_N_m);
    for (int c = 0; c < 6; ++c) {
      t.Add("joint").Set("joint", names.PinShearJoint(mode.pins[c / 2], c % 2 == 0 ? 'y' : 'z')).Set("coef", mode.coef[c]);
    }
    tendons.push_back(std::move(t));
  }
  return tendons;
}

// Skin bending couples the normal motion of neighbouring pins; in a membrane lattice the
// membrane (through the ridges) couples their shear motion. Each spring between two DOFs
// (or from one DOF to the anchored skin) is a fixed tendon.
std::vector<mjcf::Element> CouplingTendons(const PinBodyPlan& plan, const PinLattice& lattice) {
  std::vector<mjcf::Element> tendons;
  const SkinNames& names = plan.names;
  // A spring between two joints, attached to each only where that joint exists.
  auto spring = [&](const std::string& name, const std::string& j0, bool m0, const std::string& j1, bool m1,
                    double k) {
    if ((!m0 && !m1) || k <= 0.0) return;
    mjcf::Element t("fixed");
    t.Set("name", names.Part(name)).Set("stiffness", k);
    if (m0) t.Add("joint").Set("joint", j0).Set("coef", 1.0);
    if (m1) t.Add("joint").Set("joint", j1).Set("coef", -1.0);
    tendons.push_back(std::move(t));
  };
  if (plan.skin.coupling == "none") return tendons;
  const bool membrane = plan.skin.coupling == "membrane";
  // Each link's bending spring and, in a membrane lattice, its shear link(s).
  for (const auto& e : lattice.neighbours) {
    const bool m0 = plan.normal_dof[e[0]], m1 = plan.normal_dof[e[1]];
    spring(fmt::format("bend_{}_{}", e[0], e[1]), names.PinJoint(e[0]), m0, names.PinJoint(e[1]), m1,
           plan.mech.k_bend_N_m);
    if (!membrane || plan.mech.orthotropic_links) continue;
    if (plan.mech.central_links) {
      tendons.push_back(CentralLinkTendon(plan, lattice, e));
      continue;
    }
    for (char axis : {'y', 'z'}) {
      spring(fmt::format("membrane_{}_{}_{}", e[0], e[1], axis), names.PinShearJoint(e[0], axis), true,
             names.PinShearJoint(e[1], axis), true, plan.mech.k_couple_N_m);
    }
  }
  // The orthotropic membrane couples through its triangles instead.
  if (membrane && plan.mech.orthotropic_links) {
    for (auto& t : OrthotropicTendons(plan, lattice)) tendons.push_back(std::move(t));
  }
  return tendons;
}

// A pin's gel spring resting on the dome (skin.normal_spring = dome): L = q_n + (n_y q_y +
// n_z q_z) / n_x over its normal and shear joints, stiffness k_n. A shear along the dome's
// tangent plane leaves L unchanged, so the spring's rest point follows the dome.
mjcf::Element DomeSpringTendon(const PinBodyPlan& plan, const PinGeometry& pin) {
  const SkinNames& names = plan.names;
  const auto& n = pin.normal;
  mjcf::Element t("fixed");
  t.Set("name", names.PinDomeSpring(pin.index)).Set("stiffness", plan.mech.k_normal_N_m);
  t.Add("joint").Set("joint", names.PinJoint(pin.index)).Set("coef", 1.0);
  t.Add("joint").Set("joint", names.PinShearJoint(pin.index, 'y')).Set("coef", n[1] / n[0]);
  t.Add("joint").Set("joint", names.PinShearJoint(pin.index, 'z')).Set("coef", n[2] / n[0]);
  return t;
}

// The dome springs of every pin with a normal DOF (none with axial springs).
std::vector<mjcf::Element> DomeSpringTendons(const PinBodyPlan& plan, const PinLattice& lattice) {
  std::vector<mjcf::Element> tendons;
  if (!plan.skin.DomeSprings()) return tendons;
  for (const auto& pin : lattice.pins) {
    if (plan.normal_dof[pin.index]) tendons.push_back(DomeSpringTendon(plan, pin));
  }
  return tendons;
}

}  // namespace

SkinPart BuildSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                   const std::vector<bool>& collidable, double timestep_s, const std::vector<bool>& outer_site,
                   const SkinNames& names) {
  // The mechanics, and the radii of the contact spheres' centres.
  const SkinMechanics mech = SkinMechanics::From(skin, lattice);
  const double R = skin.radius_mm * 1e-3;
  const double R_out = skin.OuterRadiusMm() * 1e-3;
  const bool membrane = skin.coupling == "membrane";
  PinBodyPlan plan{skin, contact, mech, names, collidable, outer_site};
  plan.rc = skin.ContactRadiusMm() * 1e-3;
  plan.rb = R_out - plan.rc;
  // The marker the internal camera sees: the inner end of the pin.
  plan.r_marker = R - (skin.thickness_mm + skin.pin_length_mm) * 1e-3;
  if (skin.pattern == "fingerprint-v1") plan.r_marker = R - skin.thickness_mm * 1e-3;  // pins reach out into the ridges
  if (skin.pattern == "fingerprint-v2") plan.r_marker = R_out - skin.pin_length_mm * 1e-3;  // through the skin at the peak
  // The joints' damping (the membrane lattice's with its floors at this step).
  plan.c_tip = membrane ? mech.TipDamping(timestep_s) : mech.tip_damping_Ns_m;
  plan.c_normal = membrane ? mech.NormalDamping(timestep_s) : mech.pin_damping_Ns_m;
  plan.shell_mode = skin.coupling == "shell";
  // In a membrane lattice, pins that cannot touch anything keep their two shear DOFs but
  // no normal DOF: the skin beyond the contact rests on the gel and is dragged along by
  // the membrane (its coupling length spans several rings), while its normal motion is
  // not loaded by anything.
  plan.normal_dof = membrane ? collidable : std::vector<bool>(lattice.size(), true);

  SkinPart part;
  part.collidable = collidable;
  // The skin shell. In shell mode it translates in-plane on the gel: the membrane's
  // in-plane stiffness E t is two to three orders of magnitude above a pin's gel shear
  // stiffness, so pins move together tangentially and each has its own normal DOF.
  // Otherwise it is fixed and pins shear on their own.
  AddShell(part.body, plan, lattice.size());
  for (const auto& pin : lattice.pins) {
    AddPinBody(part.body, plan, pin);
    if (collidable[pin.index]) ++part.n_collidable;
  }
  // The tendons: coupling springs, then dome springs.
  part.tendons = CouplingTendons(plan, lattice);
  for (auto& t : DomeSpringTendons(plan, lattice)) part.tendons.push_back(std::move(t));
  return part;
}

}  // namespace tactip