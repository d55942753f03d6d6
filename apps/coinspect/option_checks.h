// CLI11 checks for options that CLI11's own let through: CLI::Range compares the
// converted value, so "nan" passes it, and an unsigned option reads "-1" and
// "99999999999999999999" both as 18446744073709551615 without a word.
#pragma once

#include <CLI/CLI.hpp>

namespace coinspect::app {

// A finite number from min to max.
CLI::Validator finiteNumberIn(double min, double max);

// A seed: decimal digits only, at most 18446744073709551615.
CLI::Validator seedNumber();

// A path that is not empty: `--out ""` wrote nothing and exited 0, `--scenario ""` was ignored
// (found by fuzzing).
CLI::Validator nonEmptyPath();

}  // namespace coinspect::app
