// The clamped rim in a running scene: the held object's weight and the skin's own shear the
// smooth skin's shell by (m + m_skin) g / (n k_shear + k_rim), the static equilibrium of its
// springs.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "models/skin.h"
#include "scenarios/rail/rail_run.h"

namespace tactip {
namespace {

constexpr double kGravity = 9.81;

// The soft gel's materials (assets/materials/soft-gel.yaml) with the given rim, shortened as
// ImagesAcceptanceTest's run: 20 mm lift, 5 mm/s retraction, 25 frames per second.
RailScenarioConfig SoftGelRun(const std::string& rim) {
  return LoadConfig<RailScenarioConfig>(
      "", {"skin.gel_shear_modulus_kpa=6.67", "skin.skin_modulus_mpa=0.4", "skin.rim=" + rim, "rail.lift_mm=20",
           "rail.retract_speed_mm_s=5", "sensor.frame_rate_hz=25", "contact.friction_jitter=0"});
}

// Mean pin displacement along gravity (world z) from the first frame to the retraction's start, m.
double PinSagAtRetraction(const RailScenarioConfig& c) {
  const RailScene ids(c, SceneOptions{});
  RunRecord rec;
  RailRun(c, ids, 0, 11).Execute(rec, nullptr);
  const SensorRecord& s = rec.sensors.at(0);
  const size_t n = static_cast<size_t>(s.n_pins);
  const size_t k = static_cast<size_t>(std::lower_bound(rec.time.begin(), rec.time.end(), rec.attrs.at("retract_start_s")) -
                                       rec.time.begin());
  EXPECT_LT(k, rec.frames());
  double sag = 0.0;
  for (size_t i = 0; i < n; ++i) sag += s.pos_m[3 * (k * n + i) + 2] - s.pos_m[3 * i + 2];
  return -sag / static_cast<double>(n);
}

TEST(RimAnchorSagTest, TheHeldWeightShearsTheShellByItsSpringsStaticDeflection) {
  for (const std::string rim : {"free", "clamped"}) {
    SCOPED_TRACE("skin.rim = " + rim);
    const RailScenarioConfig c = SoftGelRun(rim);
    const SkinMechanics mech = SkinMechanics::From(c.skin, PinLattice::Build(c.skin));
    const double k_shell = 127.0 * mech.k_shear_N_m + mech.k_rim_N_m;
    // The shell carries its own membrane and pins too. The rail's dry friction (5 mN) may carry
    // part of the weight: within 2 %.
    const double load_N = (c.object.mass_kg + mech.shell_moving_mass_kg) * kGravity;
    EXPECT_NEAR(PinSagAtRetraction(c) * k_shell / load_N, 1.0, 0.02) << "k " << k_shell;
  }
}

}  // namespace
}  // namespace tactip
