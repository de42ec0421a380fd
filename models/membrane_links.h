#pragma once
// The links of a membrane lattice (skin.coupling = membrane) between neighbouring pins: a
// central link's stiffness along itself, and the widest rows of the central and orthotropic
// membranes' shear stiffness, which bound the lattice's stiffest shear mode. Here too are
// SkinMechanics::CentralLinkStiffness and CentralLinkBetween. The orthotropic membrane's
// triangles are models/membrane_elements.h; the links' MJCF tendons are models/skin_part.cpp's.

#include "models/pin_lattice.h"
#include "models/skin_mechanics.h"

namespace tactip {

/// Widest row sum of a central-link lattice's shear stiffness matrix, each link's entries
/// added by magnitude: a link (e_y, e_z, k) adds k |e_a| (2 |e_y| + 2 |e_z|) to the row of
/// each of its pins' axes a (its tendon's four joints), on top of the pin's own shear spring.
/// At or above the matrix's own widest row, so a Gershgorin bound on the stiffest mode.
double CentralRowMax(const SkinMechanics& m, const PinLattice& lattice);

/// The same for the orthotropic membrane (OrthotropicMembraneModes): each mode k a a^T adds
/// k |a_r| sum |a_c| to row r.
double OrthotropicRowMax(const SkinMechanics& m, const PinLattice& lattice);

}  // namespace tactip
