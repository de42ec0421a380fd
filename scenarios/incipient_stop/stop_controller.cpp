#include "scenarios/incipient_stop/stop_controller.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sim/config.h"

namespace tactip {

void StopOptions::Validate() const {
  // Each option within a range a real loop could have; the detector checks its own.
  const auto check = [](const char* name, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi)) {
      throw InputError(fmt::format("--{} = {}: must be in [{}, {}]", name, config_detail::FormatReal(v),
                                   config_detail::FormatReal(lo), config_detail::FormatReal(hi)));
    }
  };
  check("step-mm", step_mm, 0.01, 2.0);
  check("pause-s", pause_s, 0.0, 5.0);
  check("hold-s", hold_s, 0.1, 10.0);
  if (markers != "internal" && markers != "external") {
    throw InputError(fmt::format("--markers '{}': must be internal or external", markers));
  }
  try {
    IncipientDetector{detector};
  } catch (const std::exception& e) {
    throw InputError(fmt::format("incipient detector: {}", e.what()));
  }
}

StopController::StopController(const RailSchedule& schedule, const StopOptions& options)
    : schedule_(schedule),
      options_(options),
      step_m_(options.step_mm * 1e-3),
      move_s_(step_m_ / schedule.retract_speed),
      period_s_(move_s_ + options.pause_s),
      detector_(options.detector) {}

double StopController::StepX(double t) const {
  // Step k moves step_m smoothly over move_s, then the arm pauses for pause_s.
  const double u = std::max(0.0, t - schedule_.retract_start);
  const double k = std::floor(u / period_s_);
  const double within = std::min(1.0, (u - k * period_s_) / move_s_);
  return schedule_.press_dist - step_m_ * (k + SmoothStep(within));
}

ArmTargets StopController::Targets(double t) {
  if (t < schedule_.retract_start) return {schedule_.X(t), schedule_.Z(t)};
  return {std::isnan(stop_s_) ? StepX(t) : x_stop_m_, schedule_.Z(t)};
}

void StopController::OnFrame(const FrameInput& input) {
  // Every frame goes through the detector; from the retraction on, its first alarm stops
  // the arm where it is.
  const PinFrame& f = *input.frames.at(0);
  PinFrame external;
  const PinFrame* seen = &f;
  if (options_.markers == "external") {
    external.time_s = f.time_s;
    external.pos_px = f.external_px;
    external.valid.assign(static_cast<size_t>(f.external_px.rows()), 1);
    seen = &external;
  }
  const Decision d = detector_.Update(*seen);
  if (!std::isnan(stop_s_) || input.time_s < schedule_.retract_start || !d.slip) return;
  stop_s_ = input.time_s;
  x_stop_m_ = StepX(input.time_s);
}

bool StopController::Done(double t) const { return !std::isnan(stop_s_) && t > stop_s_ + options_.hold_s; }

double StopController::GiveUpTime(const RailSchedule& schedule) const {
  // As far as the constant-speed protocol would retract, step by step.
  const double steps = std::ceil((schedule.press_dist + RailSchedule::kExtraRetractM) / step_m_);
  return schedule.retract_start + steps * period_s_;
}

std::vector<ControllerAction> StopController::Actions() const {
  if (std::isnan(stop_s_)) return {};
  return {{stop_s_, "stop"}};
}

}  // namespace tactip
