#include "sensors/labels.h"

namespace tactip {

FrameLabels LabelFrame(const std::vector<PinContactSample>& pins, const LabelConfig& cfg,
                       std::uint8_t* pin_contact, std::uint8_t* pin_slip) {
  FrameLabels out;
  for (size_t i = 0; i < pins.size(); ++i) {
    const bool contact = pins[i].in_contact;
    const bool slip =
        contact && pins[i].slip_speed_m_s > cfg.slip_speed_m_s && pins[i].cone_use >= cfg.cone_fraction;
    pin_contact[i] = contact ? 1 : 0;
    pin_slip[i] = slip ? 1 : 0;
    out.n_contact += contact ? 1 : 0;
    out.n_slip += slip ? 1 : 0;
  }
  // Gross slip: the whole contact slides.
  out.gross_slip = (out.n_contact > 0 && out.n_slip == out.n_contact) ? 1 : 0;
  return out;
}

}  // namespace tactip
