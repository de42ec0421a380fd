#pragma once
// Validators shared by the options of every subcommand: finite numbers in a readable
// range, non-empty text and seeds. Each refuses a bad value at parse time, before any work,
// with one line naming the option and what it accepts.

#include <CLI/CLI.hpp>

#include <string>

namespace tactip::cli {

/// A finite number (no NaN, no infinity).
CLI::Validator FiniteNumber();

/// A finite number > `lo`.
CLI::Validator NumberAbove(double lo);

/// A finite number in [`lo`, `hi`].
CLI::Validator NumberWithin(double lo, double hi);

/// Text that is not empty; `expected` says what to give (e.g. "a file name").
CLI::Validator NonEmpty(const std::string& expected);

/// Registers `--seed` on `c`: a decimal whole number from 0 to 2^64 - 1; a sign, digits
/// beyond that range or anything else is refused (not wrapped or saturated).
CLI::Option* AddSeedOption(CLI::App* c, unsigned long long& seed, const std::string& help);

}  // namespace tactip::cli
