#include "coinspect/record/run_header.h"

#include <sstream>

#include "coinspect/core/error.h"

namespace coinspect::record {
namespace {

constexpr const char* kMagic = "coinspect rawlog 1";

// Reads "<key>: <value>" from the next line of `in`.
std::string readField(std::istream& in, const std::string& key, const std::string& source) {
  std::string line;
  const std::string prefix = key + ": ";
  if (!std::getline(in, line) || line.compare(0, prefix.size(), prefix) != 0)
    throw InputError(source, "run header", "expected a line '" + prefix + "...'");
  return line.substr(prefix.size());
}

}  // namespace

std::string formatRunHeader(const RunHeader& header) {
  std::ostringstream out;
  out << kMagic << "\n"
      << "coinspect_version: " << header.coinspectVersion << "\n"
      << "seed: " << header.seed << "\n"
      << "scenario_hash: " << header.scenarioHash << "\n"
      << "config:\n"
      << header.configIni;
  return out.str();
}

RunHeader parseRunHeader(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kMagic)
    throw InputError(source, "run header", std::string("does not start with '") + kMagic + "'");
  RunHeader header;
  header.coinspectVersion = readField(in, "coinspect_version", source);
  const std::string seed = readField(in, "seed", source);
  try {
    size_t used = 0;
    header.seed = std::stoull(seed, &used);
    if (used != seed.size()) throw std::invalid_argument(seed);
  } catch (const std::exception&) {
    throw InputError(source, "run header", "seed '" + seed + "' is not an unsigned integer");
  }
  header.scenarioHash = readField(in, "scenario_hash", source);
  if (!std::getline(in, line) || line != "config:")
    throw InputError(source, "run header", "expected a line 'config:'");
  const auto configStart = static_cast<size_t>(in.tellg());
  header.configIni = configStart < text.size() ? text.substr(configStart) : "";
  return header;
}

}  // namespace coinspect::record
