#pragma once
// Test support: a fixture that fails a test in which MuJoCo raised a warning.

#include <gtest/gtest.h>

#include "sim/simulation.h"

namespace tactip::testing {

/// Fails the test (in TearDown, non-fatally, naming the count) if MuJoCo sent a warning to
/// its hook while the test ran: from any model compiled or mjData stepped, including ones
/// whose counters no Simulation checks. MuJoCo reports a kind of warning once per mjData
/// (its first occurrence). Derive the fixture of tests that run MuJoCo from it; a fixture
/// that overrides SetUp or TearDown calls these too.
class MujocoWarningGuard : public ::testing::Test {
 protected:
  void SetUp() override { warnings_before_ = MujocoWarningsRaised(); }
  void TearDown() override {
    const int raised = MujocoWarningsRaised() - warnings_before_;
    if (raised > 0) {
      ADD_FAILURE() << "MuJoCo raised " << raised << " warning(s) during this test (each kind counts once per mjData)";
    }
  }

 private:
  int warnings_before_ = 0;
};

}  // namespace tactip::testing
