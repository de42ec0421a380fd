// Test support: the message of an expected InputError.
#pragma once

#include <string>

#include "sim/config.h"

namespace tactip {

/// Message of the InputError thrown by `f` ("" if none was thrown).
template <class F>
std::string InputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace tactip
