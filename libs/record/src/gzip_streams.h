// gzip file streams for MRPT archives, on zlib directly. MRPT's CFileGZOutputStream cannot
// flush (crash safety needs Z_SYNC_FLUSH) and hides write errors; its input stream cannot tell
// a clean end of file from a truncated one. Both matter for rawlogs, so coinspect owns these.
#pragma once

#include <mrpt/io/CStream.h>
#include <zlib.h>

#include <cstdio>
#include <string>

namespace coinspect::record::detail {

// Writes a gzip file. zlib's gzip header has no name and mtime 0, so the bytes depend only on
// the data and the compression level. Write errors are sticky: failed() and error() tell why.
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

  // Pushes everything written so far to the OS as a complete deflate block: a reader of the file
  // (even if this process dies now) can decompress all of it.
  bool syncFlush();
  // Writes the gzip trailer and closes the file; false (with error()) if that failed.
  bool close();
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }

 private:
  void fail(const char* what);
  gzFile file_ = nullptr;
  uint64_t written_ = 0;
  std::string error_;
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
