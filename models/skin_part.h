#pragma once
// The MJCF part of a skin: the shell body with its pin bodies (joints, contact geoms, marker
// sites) and the fixed tendons that couple them, built from the lattice and its mechanics, and
// the names its elements carry.

#include <string>
#include <vector>

#include "models/contact_config.h"
#include "models/mjcf.h"
#include "models/pin_lattice.h"
#include "models/skin_config.h"

namespace tactip {

/// Names of a skin's elements in the MJCF, so scenarios can look the parts up. Every name
/// starts with `prefix`: the sensor's name and '/' in a scene of named sensors ("left/pin3"),
/// "" in a scene of one skin.
struct SkinNames {
  std::string prefix;  ///< "" or the sensor's name and '/'

  std::string PinBody(int i) const;   ///< pin i's body
  std::string PinJoint(int i) const;  ///< pin i's normal slide joint on its gel column
  std::string PinShearJoint(int i, char axis) const;  ///< uncoupled skin: 'y' or 'z' shear DOF
  std::string PinDomeSpring(int i) const;  ///< skin.normal_spring = dome: the pin's gel spring (a fixed tendon)
  std::string PinGeom(int i) const;       ///< pin i's contact geom
  std::string PinSite(int i) const;       ///< inner end of the pin (what the camera sees)
  std::string PinOuterSite(int i) const;  ///< outer contact point (external markers)
  std::string Shell() const { return prefix + "skin_shell"; }  ///< the skin shell's body
  /// Any other element of the skin (shell joints, tendons): `prefix` + `name`.
  std::string Part(const std::string& name) const { return prefix + name; }
};

/// The MJCF part of a skin: a body subtree to hang under the sensor mount, tendons,
/// and which pins carry a collision geom.
struct SkinPart {
  mjcf::Element body{"body"};           ///< the shell body with every pin body under it
  std::vector<mjcf::Element> tendons;   ///< fixed tendons: coupling springs and dome springs
  std::vector<bool> collidable;  ///< per pin
  int n_collidable = 0;          ///< pins with a contact geom
};

/// Builds the skin part (skin.coupling chooses the shell, membrane or uncoupled lattice). `collidable[i]` says whether pin i gets a contact
/// geom (pins that cannot touch the stimulus get none; in a membrane lattice they also get
/// no DOFs: the skin beyond the contact anchors its neighbours). Contact bits: pins have
/// contype 0 / conaffinity 2, so they touch only geoms with contype 2.
/// `timestep_s` sets the floor of the membrane lattice's shear damping (its stiffest
/// shear mode must stay stable under explicit integration of the tendon springs).
/// Every pin carries a site at its inner end (the marker the internal camera sees) and,
/// where `outer_site[i]`, one at its outer contact point (external markers); the overload
/// without `outer_site` gives every pin both. Elements are named by `names`.
SkinPart BuildSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                   const std::vector<bool>& collidable, double timestep_s, const std::vector<bool>& outer_site,
                   const SkinNames& names = {});
/// BuildSkin with an outer site on every pin, named as in a scene of one skin.
SkinPart BuildSkin(const SkinConfig& skin, const ContactConfig& contact, const PinLattice& lattice,
                   const std::vector<bool>& collidable, double timestep_s);

}  // namespace tactip
