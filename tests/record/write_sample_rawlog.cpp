// Writes the record tests' sample run (libs/record/tests/sample_run.h) to the path given, for
// the rawlog-edit end-to-end test, and prints its expected "<label> <count>" lines.
#include <exception>
#include <iostream>

#include "coinspect/core/error.h"
#include "sample_run.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_sample_rawlog <file.rawlog>\n";
    return 2;
  }
  try {
    coinspect::record::sample::writeSampleRun(argv[1]);
  } catch (const coinspect::InputError& error) {
    std::cerr << error.what() << "\n";
    return 1;
  }
  for (const auto& [label, count] : coinspect::record::sample::kSampleCounts)
    std::cout << label << " " << count << "\n";
  return 0;
}
