#include "scenarios/app/cli/option_checks.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "sim/base/number_text.h"

namespace tactip::cli {

namespace {

// `text` as a finite number; false when it is not one.
bool ReadFinite(const std::string& text, double& v) {
  return CLI::detail::lexical_cast(text, v) && std::isfinite(v);
}

}  // namespace

CLI::Validator FiniteNumber() {
  return CLI::Validator(
      [](std::string& text) {
        double v = 0.0;
        return ReadFinite(text, v) ? std::string() : fmt::format("'{}': must be a finite number", text);
      },
      "FINITE");
}

CLI::Validator NumberAbove(double lo) {
  return CLI::Validator(
      [lo](std::string& text) {
        double v = 0.0;
        return ReadFinite(text, v) && v > lo ? std::string() : fmt::format("'{}': must be a number > {:g}", text, lo);
      },
      fmt::format("> {:g}", lo));
}

CLI::Validator NumberWithin(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) {
        double v = 0.0;
        return ReadFinite(text, v) && v >= lo && v <= hi
                   ? std::string()
                   : fmt::format("'{}': must be a number in [{:g}, {:g}]", text, lo, hi);
      },
      fmt::format("in [{:g}, {:g}]", lo, hi));
}

CLI::Validator NonEmpty(const std::string& expected) {
  return CLI::Validator(
      [expected](std::string& text) { return text.empty() ? "empty; give " + expected : std::string(); }, "");
}

CLI::Option* AddSeedOption(CLI::App* c, unsigned long long& seed, const std::string& help) {
  // CLI11 would read "-1" and too many digits as 2^64 - 1 and "010" as octal: the text is
  // read here as decimal and handed on in canonical form.
  const CLI::Validator whole(
      [](std::string& text) {
        std::uint64_t v = 0;
        if (!ParseWhole(text, v)) {
          return fmt::format("'{}': must be a whole number from 0 to {}", text,
                             std::numeric_limits<std::uint64_t>::max());
        }
        text = std::to_string(v);
        return std::string();
      },
      "0 to 2^64-1");
  return c->add_option("--seed", seed, help)->transform(whole);
}

}  // namespace tactip::cli
