#include "gzip_streams.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace coinspect::record::detail {

GzipOutput::GzipOutput(const std::string& path, int level) {
  const std::string mode = "wb" + std::to_string(level);
  errno = 0;
  file_ = gzopen(path.c_str(), mode.c_str());
  if (file_ == nullptr) {
    error_ = std::string("cannot create the file: ") +
             (errno != 0 ? std::strerror(errno) : "zlib could not open it");
    failed_ = true;
    return;
  }
  gzbuffer(file_, 256 * 1024);  // fewer, larger write() calls
  pending_.reserve(kChunkBytes);
  worker_ = std::thread([this] { work(); });
}

GzipOutput::~GzipOutput() {
  stopWorker();
  if (file_ != nullptr) gzclose(file_);
}

bool GzipOutput::failed() const {
  return failed_.load(std::memory_order_acquire);
}

std::string GzipOutput::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

void GzipOutput::fail(const char* what) {
  if (!error_.empty()) return;
  int zlibError = Z_OK;
  const char* zlibMessage = file_ != nullptr ? gzerror(file_, &zlibError) : "";
  // zlib reports failed write() calls as Z_ERRNO: errno holds the reason (e.g. no space left).
  error_ = std::string(what) + ": " +
           (zlibError == Z_ERRNO ? std::strerror(errno) : std::string(zlibMessage));
  failed_.store(true, std::memory_order_release);
}

void GzipOutput::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    queued_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, nothing left
    Chunk chunk = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    const bool skip = !error_.empty();
    lock.unlock();
    room_.notify_all();
    int status = Z_OK;
    bool wroteAll = true;
    if (!skip) {
      errno = 0;
      if (!chunk.bytes.empty())
        wroteAll = gzwrite(file_, chunk.bytes.data(), static_cast<unsigned>(chunk.bytes.size())) ==
                   static_cast<int>(chunk.bytes.size());
      if (wroteAll && chunk.flush) status = gzflush(file_, Z_SYNC_FLUSH);
    }
    lock.lock();
    if (!wroteAll) fail("cannot write");
    if (status != Z_OK) fail("cannot flush");
    if (chunk.flush) ++flushesDone_;
    busy_ = false;
    room_.notify_all();
  }
}

void GzipOutput::hand(bool flush) {
  if (!worker_.joinable()) return;
  Chunk chunk;
  chunk.bytes.swap(pending_);
  chunk.flush = flush;
  pending_.reserve(kChunkBytes);
  std::unique_lock<std::mutex> lock(mutex_);
  room_.wait(lock, [this] { return queue_.size() < kMaxQueued; });
  queue_.push_back(std::move(chunk));
  lock.unlock();
  queued_.notify_one();
}

void GzipOutput::stopWorker() {
  if (!worker_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  queued_.notify_one();
  worker_.join();
}

size_t GzipOutput::Write(const void* buffer, size_t count) {
  if (file_ == nullptr || count > static_cast<size_t>(INT_MAX) || failed()) return 0;
  if (count == 0) return 0;
  const auto* bytes = static_cast<const unsigned char*>(buffer);
  pending_.insert(pending_.end(), bytes, bytes + count);
  written_ += count;
  if (pending_.size() >= kChunkBytes) hand(false);
  return count;
}

uint64_t GzipOutput::Seek(int64_t, mrpt::io::CStream::TSeekOrigin) {
  throw std::logic_error("GzipOutput cannot seek");
}

bool GzipOutput::syncFlush(bool wait) {
  if (file_ == nullptr || failed()) return false;
  if (worker_.joinable()) {
    std::unique_lock<std::mutex> lock(mutex_);
    room_.wait(lock, [this] { return flushesDone_ >= flushesAsked_; });
  }
  hand(true);
  ++flushesAsked_;
  if (wait) {
    std::unique_lock<std::mutex> lock(mutex_);
    room_.wait(lock, [this] { return queue_.empty() && !busy_; });
  }
  return !failed();
}

bool GzipOutput::close() {
  if (file_ == nullptr) return !failed();
  if (!failed()) hand(false);
  stopWorker();  // the worker writes what is queued first
  errno = 0;
  const int status = gzclose(file_);
  file_ = nullptr;
  std::lock_guard<std::mutex> lock(mutex_);
  if (status != Z_OK && error_.empty()) {
    error_ = std::string("cannot close: ") +
             (status == Z_ERRNO ? std::strerror(errno) : "zlib error " + std::to_string(status));
    failed_ = true;
  }
  return error_.empty();
}

GzipInput::GzipInput(const std::string& path) {
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr) return;
  // 16 + MAX_WBITS: expect a gzip wrapper (header and CRC/size trailer), not raw zlib.
  inflateReady_ = inflateInit2(&stream_, 16 + MAX_WBITS) == Z_OK;
  if (!inflateReady_) damage_ = "zlib could not start";
}

GzipInput::~GzipInput() {
  if (inflateReady_) inflateEnd(&stream_);
  if (file_ != nullptr) std::fclose(file_);
}

size_t GzipInput::inflateInto(unsigned char* out, size_t count) {
  size_t got = 0;
  while (got < count && !streamEnded_ && damage_.empty() && inflateReady_) {
    if (stream_.avail_in == 0 && !fileEnded_) {
      const size_t n = std::fread(input_, 1, sizeof input_, file_);
      if (n < sizeof input_) fileEnded_ = true;
      stream_.next_in = input_;
      stream_.avail_in = static_cast<uInt>(n);
    }
    const uInt availIn = stream_.avail_in;
    stream_.next_out = out + got;
    stream_.avail_out = static_cast<uInt>(std::min<size_t>(count - got, 1u << 20));
    const uInt availOut = stream_.avail_out;
    const int status = inflate(&stream_, Z_NO_FLUSH);
    got += availOut - stream_.avail_out;
    consumed_ += availIn - stream_.avail_in;
    if (status == Z_STREAM_END) {
      streamEnded_ = true;
    } else if (status == Z_OK || status == Z_BUF_ERROR) {
      const bool progress = availIn != stream_.avail_in || availOut != stream_.avail_out;
      if (!progress && stream_.avail_in == 0 && fileEnded_)
        damage_ = "unexpected end of file (truncated gzip stream)";
    } else {
      damage_ = stream_.msg != nullptr ? stream_.msg : "zlib error " + std::to_string(status);
    }
  }
  return got;
}

size_t GzipInput::Read(void* buffer, size_t count) {
  if (file_ == nullptr || count == 0) return 0;
  auto* out = static_cast<unsigned char*>(buffer);
  size_t got = 0;
  if (hasPeeked_) {
    out[0] = peeked_;
    hasPeeked_ = false;
    got = 1;
  }
  got += inflateInto(out + got, count - got);
  position_ += got;
  return got;
}

uint64_t GzipInput::Seek(int64_t, mrpt::io::CStream::TSeekOrigin) {
  throw std::logic_error("GzipInput cannot seek");
}

bool GzipInput::atCleanEnd() {
  if (file_ == nullptr) return false;
  if (!hasPeeked_) hasPeeked_ = inflateInto(&peeked_, 1) == 1;
  return !hasPeeked_ && streamEnded_ && damage_.empty();
}

}  // namespace coinspect::record::detail
