#include "coinspect/record/rawlog_reader.h"

#include <mrpt/maps/registerAllClasses.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <limits>
#include <sstream>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "coinspect/record/observations.h"
#include "gzip_streams.h"

namespace coinspect::record {
namespace {

// MRPT exceptions carry nested "Message:" lines plus call stacks; keep only the messages.
std::string shortReason(const std::string& what) {
  std::istringstream lines(what);
  std::string line;
  std::string reason;
  const std::string key = "Message:";
  while (std::getline(lines, line)) {
    const auto at = line.find(key);
    if (at == std::string::npos) continue;
    auto text = line.substr(at + key.size());
    text.erase(0, text.find_first_not_of(' '));
    reason += (reason.empty() ? "" : ": ") + text;
  }
  return reason.empty() ? what : reason;
}

}  // namespace

RawlogReader::RawlogReader(const std::filesystem::path& path)
    : path_(path),
      in_(std::make_unique<detail::GzipInput>(path.string())),
      latestTime_(std::numeric_limits<double>::infinity()) {
  if (!in_->isOpen()) throw InputError(path_.string(), "open", "cannot open the rawlog");
  std::error_code error;
  if (std::filesystem::file_size(path_, error) == 0 && !error)
    throw InputError(path_.string(), "run header", "the rawlog is empty");
  // Programs that link coinspect_record_types statically-ish (no dlopen) still get the classes.
  registerObservationClasses();
  // LiDAR sweeps are mrpt-maps classes (CObservationPointCloud): a program that only reads
  // would not load mrpt-maps (the linker drops it as unused) and could not read them.
  mrpt::maps::registerAllClasses_mrpt_maps();
  std::shared_ptr<mrpt::obs::CObservation> first;
  if (!next(first))
    throw InputError(path_.string(), "run header",
                     status_.clean ? "the rawlog is empty" : status_.message);
  const auto comment = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(first);
  if (!comment)
    throw InputError(path_.string(), "run header",
                     "the first object is not a CObservationComment run header");
  header_ = parseRunHeader(comment->text, path_.string());
}

RawlogReader::~RawlogReader() = default;

void RawlogReader::markDamaged(uint64_t offset, const std::string& why) {
  status_.clean = false;
  status_.offset = offset;
  status_.compressedOffset = in_->compressedPosition();
  status_.message = path_.string() + ": " + std::to_string(status_.objects) +
                    " objects read, damage at byte offset " + std::to_string(offset) +
                    " (decompressed stream; compressed offset " +
                    std::to_string(status_.compressedOffset) + "): " + printableText(why);
}

std::shared_ptr<mrpt::obs::CObservation> RawlogReader::readObject() {
  auto archive = mrpt::serialization::archiveFrom(*in_);
  auto object = archive.ReadObject();
  auto observation = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object);
  if (!observation)
    throw std::runtime_error(std::string("object of class ") +
                             object->GetRuntimeClass()->className + " is not an observation");
  return observation;
}

bool RawlogReader::next(std::shared_ptr<mrpt::obs::CObservation>& observation) {
  observation.reset();
  if (finished_) return false;
  const uint64_t start = in_->getPosition();
  if (in_->atCleanEnd()) {
    finished_ = true;
    return false;
  }
  if (!in_->damage().empty()) {  // no byte left and the stream did not end properly
    finished_ = true;
    markDamaged(start, "gzip: " + in_->damage());
    return false;
  }
  try {
    observation = readObject();
  } catch (const std::exception& e) {
    finished_ = true;
    const std::string& zlib = in_->damage();
    markDamaged(start, zlib.empty() ? shortReason(e.what()) : "gzip: " + zlib);
    observation.reset();
    return false;
  }
  // A timestamp flipped by damage still deserializes; the readers downstream trust the order
  // (one 0xFF.. time once made a replay write frames until the disk was full).
  const std::string timeFault = timestampFault(mrpt::Clock::toDouble(observation->timestamp));
  if (!timeFault.empty()) {
    finished_ = true;
    markDamaged(start, observation->sensorLabel + ": " + timeFault);
    observation.reset();
    return false;
  }
  ++status_.objects;
  return true;
}

std::string RawlogReader::timestampFault(double time) {
  // MRPT's clock counts unsigned 100 ns ticks: a damaged time is never negative or NaN, but may
  // be anything up to 58,000 years.
  char text[160];
  if (time < previousTime_) {
    std::snprintf(text, sizeof(text),
                  "timestamp %.6f s comes before the previous object's %.6f s (objects are "
                  "written in time order)",
                  time, previousTime_);
    return text;
  }
  if (time > latestTime_) {
    std::snprintf(text, sizeof(text),
                  "timestamp %.6f s is after the latest time the run can reach, %.6f s", time,
                  latestTime_);
    return text;
  }
  previousTime_ = time;
  return "";
}

}  // namespace coinspect::record
