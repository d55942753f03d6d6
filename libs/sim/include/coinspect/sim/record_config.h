// The [record] section of a run's INI file: whether `coinspect run --out` writes run.rawlog and
// what the recorder puts in it (doc/config.md, "[record]"; layout in doc/recording.md).
#pragma once

#include "coinspect/core/config.h"
#include "coinspect/record/rawlog_writer.h"

namespace coinspect::sim {

struct RecordConfig {
  bool rawlog = true;  // `coinspect run --out DIR` writes DIR/run.rawlog
  record::RecordOptions options;

  // Reads [record] strictly (marking the keys used). ground_truth_rate must be > 0 and at most
  // one sample per physics step; flush_period > 0; lidar = keyframes | all | none.
  static RecordConfig read(const Config& config, double physicsStep);
};

}  // namespace coinspect::sim
