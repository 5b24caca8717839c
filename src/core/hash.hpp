// A 64-bit FNV-1a hash: detects accidental changes of data (a flipped byte in a
// checkpoint) and names a run by its inputs. Not for adversaries.
#pragma once

#include <cstdint>
#include <string_view>

namespace cortex {

inline std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ull) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

}  // namespace cortex
