// FNV-1a (64 bits): the project's one hash of bytes where a value must be the same on every
// machine and run (the mission's state digest, a scenario's identity, relayed messages).
#pragma once

#include <cstddef>
#include <cstdint>

namespace coinspect::core {

constexpr uint64_t kFnv1aOffset = 14695981039346656037ull;

// `hash` continued over `size` bytes at `data` (start from kFnv1aOffset).
inline uint64_t fnv1a(const void* data, size_t size, uint64_t hash = kFnv1aOffset) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i)
    hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

}  // namespace coinspect::core
