#pragma once
// The `--skin NAME` presets as a bare SkinConfig, shared by the model tests.

#include <gtest/gtest.h>

#include <string>

#include "models/skin.h"
#include "sim/sim_config.h"

namespace tactip {

/// A SkinConfig with the `--skin NAME` preset applied (the preset's keys carry the
/// "skin." section prefix, which a bare SkinConfig does not have).
inline SkinConfig PresetSkin(const std::string& name) {
  SkinConfig s;
  for (const auto& assignment : SkinPreset(name)) {
    auto [key, value] = ParseAssignment(assignment);
    EXPECT_EQ(key.rfind("skin.", 0), 0u) << "preset key outside the skin section: " << key;
    ApplyFlat(s, FlatConfig{{key.substr(5), value}});
  }
  ValidateConfig(s);
  return s;
}

}  // namespace tactip
