// A strategy's optional config keys, read strictly: a value outside its range is an InputError
// naming the file and "[section] key" (a silent default would fly a different mission).
#pragma once

#include <string>

#include "coinspect/core/config.h"

namespace coinspect::strategies::runtime {

// `range` describes the accepted values in the message ("in [0, 10] m"); empty: "in [low, high]".
double readNumber(const Config& config, const std::string& section, const std::string& key,
                  double fallback, double low, double high, const std::string& range = {});
long long readInteger(const Config& config, const std::string& section, const std::string& key,
                      long long fallback, long long low, long long high);

}  // namespace coinspect::strategies::runtime
