// FNV-1a, 64-bit: a fingerprint of bytes that catches accidental change (a flipped bit, a
// truncated or edited file), not deliberate forgery.
#pragma once

#include <cstddef>
#include <cstdint>

namespace radiant {

inline constexpr uint64_t fnv_offset = 0xcbf29ce484222325ull;

// `hash` continued over `size` bytes at `data`; start from fnv_offset.
inline uint64_t fnv1a(uint64_t hash, const void* data, size_t size) {
  constexpr uint64_t fnv_prime = 0x100000001b3ull;
  const unsigned char* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * fnv_prime;
  return hash;
}

}  // namespace radiant
