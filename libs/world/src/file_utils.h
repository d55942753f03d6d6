// Private helpers of the file readers and writers: whole files in and out, and little-endian
// binary values.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

namespace coinspect::world::detail {

// The whole content of the file; throws InputError "cannot open <what>" when it cannot be opened.
std::string readWholeFile(const std::filesystem::path& path, const char* what);

// Replaces the file by `bytes`; throws InputError when it cannot be opened or written.
void writeWholeFile(const std::filesystem::path& path, const std::string& bytes);

// Binary files are little endian whatever the host: write each value byte by byte.
inline void putU32(std::string& buffer, uint32_t value) {
  for (int i = 0; i < 4; ++i)
    buffer.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

inline void putF32(std::string& buffer, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  putU32(buffer, bits);
}

}  // namespace coinspect::world::detail
