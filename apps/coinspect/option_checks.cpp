#include "option_checks.h"

#include <charconv>
#include <cstdint>
#include <cstdio>

#include "coinspect/core/text.h"

namespace coinspect::app {

CLI::Validator finiteNumberIn(double min, double max) {
  char range[64];
  std::snprintf(range, sizeof range, "%g to %g", min, max);
  const std::string rangeText = range;
  return CLI::Validator(
      [min, max, rangeText](std::string& text) -> std::string {
        const auto value = parseFiniteDouble(text);
        if (value && *value >= min && *value <= max) return {};
        return "'" + text + "' is not a finite number from " + rangeText;
      },
      "FINITE " + rangeText, "finite number");
}

CLI::Validator seedNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto parsed = std::from_chars(text.data(), end, value);
        const bool digitsOnly = !text.empty() && text.find_first_not_of("0123456789") == text.npos;
        if (digitsOnly && parsed.ec == std::errc() && parsed.ptr == end) return {};
        return "'" + text + "' is not a seed: a whole number from 0 to 18446744073709551615";
      },
      "UINT64", "seed");
}

CLI::Validator nonEmptyPath() {
  return CLI::Validator(
      [](std::string& text) -> std::string { return text.empty() ? "an empty path" : ""; }, "PATH",
      "path");
}

}  // namespace coinspect::app
