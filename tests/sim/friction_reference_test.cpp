// The friction rows' velocity target of fast-sliding contacts (sim/friction_reference.h):
// untouched up to the free-sliding speed, faded out continuously to zero at twice it, so
// a contact that speeds up through the threshold sees no jump in its target (a jump
// kicked the normal forces of the rail's sliding object: pins left the contact for a
// frame as it crossed 30 mm/s).

#include "sim/friction_reference.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <memory>

#include "sim/simulation.h"

namespace tactip {
namespace {

// A sphere resting on a plane in an elliptic cone (one contact, condim 3), sliding along
// x at `speed` without rolling; returns the friction rows' reference acceleration along x
// after FadeFrictionReference with the given threshold (threshold 0: MuJoCo's own).
double SlidingReference(double speed, double threshold) {
  static const CompiledModel model = CompiledModel::FromXml(
      "<mujoco><option cone='elliptic' timestep='0.001'/><worldbody>"
      "<geom type='plane' size='1 1 0.1' friction='1 0 0'/>"
      "<body pos='0 0 0.0099'><freejoint/><geom type='sphere' size='0.01' mass='0.01' condim='3'/></body>"
      "</worldbody></mujoco>");
  const std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(model.raw()), mj_deleteData);
  d->qvel[0] = speed;
  mj_fwdPosition(model.raw(), d.get());
  mj_fwdVelocity(model.raw(), d.get());
  EXPECT_EQ(d->ncon, 1);
  EXPECT_EQ(d->efc_type[0], mjCNSTR_CONTACT_ELLIPTIC);
  if (threshold > 0.0) FadeFrictionReference(d.get(), threshold);
  // Row 0 is the normal; rows 1, 2 the two tangent directions: the one along x carries it.
  return std::abs(d->efc_aref[1]) > std::abs(d->efc_aref[2]) ? d->efc_aref[1] : d->efc_aref[2];
}

TEST(FrictionReferenceTest, SlowContactsKeepMujocosTarget) {
  const double threshold = 0.03;
  for (double v : {0.001, 0.01, 0.02, 0.03}) {
    const double own = SlidingReference(v, 0.0);
    EXPECT_NE(own, 0.0) << v;
    EXPECT_DOUBLE_EQ(SlidingReference(v, threshold), own) << v;
  }
}

TEST(FrictionReferenceTest, TargetFadesContinuouslyToZeroAtTwiceTheThreshold) {
  const double threshold = 0.03;
  const double at = std::abs(SlidingReference(threshold, 0.0));  // MuJoCo's target at the threshold
  // Just above the threshold the target is (almost) what it was just below: no jump.
  EXPECT_NEAR(std::abs(SlidingReference(1.001 * threshold, threshold)), at, 0.01 * at);
  // Halfway through the fade: half of MuJoCo's target at that speed (which is -B v).
  const double mid = 1.5 * threshold;
  EXPECT_NEAR(SlidingReference(mid, threshold), 0.5 * SlidingReference(mid, 0.0), 1e-9 * at);
  // The fade only lowers the target's magnitude as the speed grows ...
  double previous = at;
  for (double f = 1.05; f < 2.0; f += 0.05) {
    const double now = std::abs(SlidingReference(f * threshold, threshold));
    EXPECT_LT(now, previous) << f;
    previous = now;
  }
  // ... and a contact sliding at twice the threshold or faster has none.
  for (double f : {2.0, 3.0, 10.0, 100.0}) EXPECT_EQ(SlidingReference(f * threshold, threshold), 0.0) << f;
}

}  // namespace
}  // namespace tactip
