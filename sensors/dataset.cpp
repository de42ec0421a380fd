#include "sensors/dataset.h"

#include <cstdio>
#include <stdexcept>

namespace tactip {

// ---------------------------------------------------------------------------------------
// RunRecord

void RunRecord::CheckShapes() const {
  const std::string who = "RunRecord " + RunGroupName(index) + ": ";
  if (index < 0) throw std::logic_error("RunRecord: index must be >= 0, got " + std::to_string(index));
  if (time.empty()) throw std::logic_error(who + "time is empty (need T >= 1 frames)");
  if (n_pins < 1) throw std::logic_error(who + "n_pins must be >= 1, got " + std::to_string(n_pins));
  const size_t t = time.size();
  const size_t n = static_cast<size_t>(n_pins);
  const std::string dims = " (T=" + std::to_string(t) + ", N=" + std::to_string(n) + ")";
  // Each field against the product of its shape.
  auto check = [&](const char* field, size_t actual, size_t expected, const char* shape) {
    if (actual != expected) {
      throw std::logic_error(who + field + " has " + std::to_string(actual) + " values, expected " +
                             std::to_string(expected) + " = " + shape + dims);
    }
  };
  check("pos_px", pos_px.size(), t * n * 2, "T*N*2");
  check("valid", valid.size(), t * n, "T*N");
  check("pos_m", pos_m.size(), t * n * 3, "T*N*3");
  check("gross_slip", gross_slip.size(), t, "T");
  check("pin_slip", pin_slip.size(), t * n, "T*N");
  check("pin_contact", pin_contact.size(), t * n, "T*N");
  check("normal_N", normal_N.size(), t * n, "T*N");
  check("tangential_N", tangential_N.size(), t * n * 2, "T*N*2");
  check("object_height_m", object_height_m.size(), t, "T");
  check("incipient", incipient.size(), t, "T");
  if (!external_px.empty() || !external_m.empty()) {
    check("external_px", external_px.size(), t * n * 2, "T*N*2");
    check("external_m", external_m.size(), t * n * 3, "T*N*3");
  }
}

std::vector<std::uint8_t> PartialSlipLabels(const std::vector<std::uint8_t>& pin_contact,
                                            const std::vector<std::uint8_t>& pin_slip, int n_pins) {
  const size_t n = static_cast<size_t>(n_pins);
  std::vector<std::uint8_t> out(n == 0 ? 0 : pin_contact.size() / n, 0);
  for (size_t f = 0; f < out.size(); ++f) {
    int contact = 0, slip = 0;
    for (size_t i = 0; i < n; ++i) {
      contact += pin_contact[f * n + i];
      slip += pin_contact[f * n + i] && pin_slip[f * n + i];
    }
    out[f] = slip > 0 && slip < contact ? 1 : 0;
  }
  return out;
}

std::string RunGroupName(int index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "run_%04d", index);
  return buf;
}
}  // namespace tactip
