#include "coinspect/strategies/runtime/option_reader.h"

#include "coinspect/core/error.h"

namespace coinspect::strategies::runtime {

double readNumber(const Config& config, const std::string& section, const std::string& key,
                  double fallback, double low, double high, const std::string& range) {
  const double value = config.getDouble(section, key, fallback);
  if (!(value >= low && value <= high))
    throw InputError(
        config.source(), "[" + section + "] " + key,
        "must be " +
            (range.empty() ? "in [" + std::to_string(low) + ", " + std::to_string(high) + "]"
                           : range) +
            ", got " + std::to_string(value));
  return value;
}

long long readInteger(const Config& config, const std::string& section, const std::string& key,
                      long long fallback, long long low, long long high) {
  const long long value = config.getInt(section, key, fallback);
  if (value < low || value > high)
    throw InputError(config.source(), "[" + section + "] " + key,
                     "must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) +
                         "], got " + std::to_string(value));
  return value;
}

}  // namespace coinspect::strategies::runtime
