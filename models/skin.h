#pragma once
// The TacTip skin as a pin lattice: this header only includes its parts, one concern each.

#include "models/contact_config.h"      // the `contact.` section: friction and the contact's softness
#include "models/fingerprint_ridges.h"  // a fingerprint pin's ridge cell and the ridges' corrugation
#include "models/membrane_links.h"      // a membrane lattice's links and their shear-row bounds
#include "models/pin_lattice.h"         // the pins on the dome and their neighbours
#include "models/skin_config.h"         // the `skin.` section: keys, derived quantities, rules
#include "models/skin_mechanics.h"      // stiffnesses, masses and damping from the materials
#include "models/skin_part.h"           // the MJCF part: BuildSkin, SkinPart, SkinNames
#include "models/skin_presets.h"        // the `--skin NAME` presets
#include "models/skin_timesteps.h"      // the skins' validated steps
