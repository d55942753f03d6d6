// The run header of a coinspect rawlog: the first object of every rawlog is one
// CObservationComment whose text is formatRunHeader(header). One comment only, because MRPT's
// CRawlog keeps just the last comment and CObservationComment does not store a sensor label.
#pragma once

#include <cstdint>
#include <string>

namespace coinspect::record {

struct RunHeader {
  std::string coinspectVersion;  // coinspect::version() of the program that recorded
  uint64_t seed = 0;             // the run's master seed
  std::string scenarioHash;      // the scenario's content hash, as hex
  std::string configIni;         // the fully resolved config, as INI text
  bool operator==(const RunHeader& o) const {
    return coinspectVersion == o.coinspectVersion && seed == o.seed &&
           scenarioHash == o.scenarioHash && configIni == o.configIni;
  }
};

// Text layout (doc/recording.md):
//   coinspect rawlog 1
//   coinspect_version: <version>
//   seed: <decimal>
//   scenario_hash: <hex>
//   config:
//   <config INI, verbatim, to the end of the text>
std::string formatRunHeader(const RunHeader& header);

// Inverse of formatRunHeader. Throws InputError(source, "run header", ...) on another layout.
RunHeader parseRunHeader(const std::string& text, const std::string& source);

}  // namespace coinspect::record
