// gzip file streams for MRPT archives, on zlib directly. MRPT's CFileGZOutputStream cannot
// flush (crash safety needs Z_SYNC_FLUSH) and hides write errors; its input stream cannot tell
// a clean end of file from a truncated one. Both matter for rawlogs, so coinspect owns these.
#pragma once

#include <mrpt/io/CStream.h>
#include <zlib.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace coinspect::record::detail {

// Writes a gzip file. zlib's gzip header has no name and mtime 0, so the bytes depend only on
// the data and the compression level. Compression and file writes run on a worker thread: the
// caller only copies bytes into 1 MiB chunks (MRPT archives write field by field), so recording
// costs the simulator little wall time on a second core. At most kMaxQueued chunks wait, which
// keeps memory bounded. Errors are sticky and reported by the next call after the worker met
// them: failed() and error() tell why.
class GzipOutput : public mrpt::io::CStream {
 public:
  GzipOutput(const std::string& path, int level);  // check failed() afterwards
  ~GzipOutput() override;
  GzipOutput(const GzipOutput&) = delete;
  GzipOutput& operator=(const GzipOutput&) = delete;

  size_t Read(void*, size_t) override { return 0; }
  size_t Write(const void* buffer, size_t count) override;
  uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override;
  uint64_t getTotalBytesCount() const override { return written_; }
  uint64_t getPosition() const override { return written_; }

  // Hands everything written so far to the worker, which pushes it to the OS as a complete
  // deflate block: once it has, a reader of the file (even if this process dies) can decompress
  // all of it. Flushes are pipelined: a call first waits until the worker has completed the
  // previous flush, so a killed process leaves at least everything up to the flush before its
  // last call. Returns false if an error is already known. With `wait`, returns only once the
  // worker has written everything (and then reports its errors): for the run header, so that an
  // unwritable or full disk is reported before a mission starts.
  bool syncFlush(bool wait = false);
  // Waits for the worker, writes the gzip trailer and closes the file; false (with error()) if
  // anything failed.
  bool close();
  bool failed() const;
  std::string error() const;

 private:
  static constexpr size_t kChunkBytes = size_t{1} << 20;
  static constexpr size_t kMaxQueued = 8;
  struct Chunk {
    std::vector<unsigned char> bytes;
    bool flush = false;
  };

  void hand(bool flush);  // moves pending_ (and a flush request) to the worker's queue
  void work();            // the worker's loop
  void stopWorker();
  void fail(const char* what);  // worker side, with mutex_ held

  gzFile file_ = nullptr;
  uint64_t written_ = 0;
  std::vector<unsigned char> pending_;  // caller's thread only

  mutable std::mutex mutex_;
  std::condition_variable queued_;  // worker: a chunk or the stop request arrived
  std::condition_variable room_;    // caller: the queue has room, or the worker is idle
  std::deque<Chunk> queue_;
  bool stopping_ = false;
  bool busy_ = false;          // the worker is writing a chunk it took off the queue
  uint64_t flushesAsked_ = 0;  // caller's thread only
  uint64_t flushesDone_ = 0;
  std::string error_;
  std::atomic<bool> failed_{false};  // error_ is set: checked at every Write without the lock
  std::thread worker_;
};

// Reads a gzip file with zlib's inflate, handing out every byte as soon as it is decompressed
// (gzread decompresses ahead and drops what it had when it meets damage). Read() returns fewer
// bytes than asked at the end of the data or at damage; then atCleanEnd() and damage() say which.
class GzipInput : public mrpt::io::CStream {
 public:
  explicit GzipInput(const std::string& path);  // check isOpen()
  ~GzipInput() override;
  GzipInput(const GzipInput&) = delete;
  GzipInput& operator=(const GzipInput&) = delete;

  bool isOpen() const { return file_ != nullptr; }
  size_t Read(void* buffer, size_t count) override;
  size_t Write(const void*, size_t) override { return 0; }
  uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override;
  uint64_t getTotalBytesCount() const override { return 0; }
  uint64_t getPosition() const override { return position_; }  // decompressed bytes handed out
  uint64_t compressedPosition() const { return consumed_; }    // file bytes inflated so far

  // True when no byte is left and the gzip stream ended with a valid trailer.
  bool atCleanEnd();
  // What went wrong ("" when nothing did).
  const std::string& damage() const { return damage_; }

 private:
  size_t inflateInto(unsigned char* out, size_t count);

  std::FILE* file_ = nullptr;
  z_stream stream_{};
  bool inflateReady_ = false;
  bool streamEnded_ = false;
  bool fileEnded_ = false;
  unsigned char input_[16384];
  uint64_t position_ = 0;
  uint64_t consumed_ = 0;
  bool hasPeeked_ = false;
  unsigned char peeked_ = 0;
  std::string damage_;
};

}  // namespace coinspect::record::detail
