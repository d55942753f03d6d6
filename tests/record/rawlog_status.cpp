// Reads a coinspect rawlog to its end or to the first damage and prints what it found, for the
// end-to-end recording tests (a killed or disk-full run must leave a readable prefix):
//   objects <N>            objects read, header comment included
//   clean <1|0>            0 when the file is damaged (truncated, corrupted)
//   status <message>       the reader's message ("" when clean): objects read and byte offsets
//   <label> <count>        one line per sensor label, sorted
// Exit status 0 when the header could be read (damaged or not), 2 otherwise.
#include <mrpt/obs/CObservation.h>

#include <exception>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "coinspect/core/error.h"
#include "coinspect/record/rawlog_reader.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: rawlog_status <run.rawlog>\n";
    return 2;
  }
  try {
    coinspect::record::RawlogReader reader(argv[1]);
    std::map<std::string, size_t> counts;
    std::shared_ptr<mrpt::obs::CObservation> observation;
    while (reader.next(observation))
      ++counts[observation->sensorLabel];
    const auto& status = reader.status();
    std::cout << "objects " << status.objects << "\n"
              << "clean " << (status.clean ? 1 : 0) << "\n"
              << "status " << status.message << "\n";
    for (const auto& [label, count] : counts)
      std::cout << label << " " << count << "\n";
  } catch (const coinspect::InputError& error) {
    std::cerr << error.what() << "\n";
    return 2;
  }
  return 0;
}
