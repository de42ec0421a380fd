#include "scenarios/studies/contact_checks/pressed_rig.h"

#include <algorithm>

namespace tactip {

namespace {

// Quintic smooth step 0 -> 1.
double Smooth(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

}  // namespace

PressedRig::PressedRig(const ContactRigSpec& spec, double depth_m)
    : model_(CompiledModel::FromXml(BuildContactRig(spec))),
      sim_(model_),
      lattice(PinLattice::Build(spec.skin)),
      n(static_cast<int>(lattice.size())),
      contacts(static_cast<size_t>(n)),
      slot_(static_cast<size_t>(model_.ngeom()), -1),
      servo_x_(model_.ActuatorId(ContactRigNames::kServoNormal)),
      servo_y_(model_.ActuatorId(ContactRigNames::kServoShear)),
      qy_(model_.JointQposAdr(model_.JointId(ContactRigNames::kShear))),
      press_(spec.gap_m + depth_m),
      dt_(model_.timestep()) {
  for (int i = 0; i < n; ++i) {
    try {
      slot_[model_.GeomId(SkinNames{}.PinGeom(i))] = i;
    } catch (const ModelError&) {
      // culled pin: cannot reach the plate
    }
  }
}

void PressedRig::Press() {
  while (t < 1.3) Drive(press_ * Smooth(t / 1.0), 0.0);
  ReadContacts();
}

void PressedRig::Drive(double x_target, double y_target) {
  sim_.SetControl(servo_x_, -x_target);
  sim_.SetControl(servo_y_, y_target);
  sim_.Step();
  t += dt_;
}

}  // namespace tactip
