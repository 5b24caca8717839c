// Counter-based random streams (Random123 Philox4x64-10; Salmon et al., SC 2011).
//
// A stream is named by (seed, stream id); its whole state is one 64-bit counter, so a
// checkpoint stores a single integer and a resumed run draws exactly the same numbers.
// Every consumer of randomness has its own stream id, listed here, so adding a consumer
// never shifts another's numbers.
#pragma once

#include <Random123/philox.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/types.hpp"

namespace cortex {

enum class StreamId : std::uint64_t {
  kChemistry = 1,
  kInitialConditions = 2,
  kFilamentPlacement = 3,
  kSurfaceSpeciesPlacement = 4,
  kCopyTransport = 5,
};

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, StreamId id, std::uint64_t counter = 0)
      : key_{{seed, static_cast<std::uint64_t>(id)}}, counter_(counter) {}

  // Uniform in (0, 1): never exactly 0 or 1, so logarithms are safe.
  double uniform() {
    if (used_ == 4) refill();
    const std::uint64_t bits = block_[used_++] >> 11;  // 53 random bits
    return (static_cast<double>(bits) + 0.5) * 0x1.0p-53;
  }
  double exponential(double rate) { return -std::log(uniform()) / rate; }

  // Raw 64-bit draws: a uniform random bit generator for the standard distributions
  // (whose algorithms are the standard library's: same build, same numbers).
  using result_type = std::uint64_t;
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  result_type operator()() {
    if (used_ == 4) refill();
    return block_[used_++];
  }

  // Position in the stream, for checkpoints: blocks of four numbers drawn so far, plus
  // how many of the current block are used.
  std::uint64_t counter() const { return counter_; }
  int usedInBlock() const { return used_; }
  void restore(std::uint64_t counter, int used_in_block) {
    counter_ = counter;
    if (used_in_block < 4 && counter_ > 0) {
      --counter_;
      refill();
    }
    used_ = used_in_block;
  }

 private:
  void refill() {
    const r123::Philox4x64::ctr_type ctr = {{counter_++, 0, 0, 0}};
    const auto out = r123::Philox4x64()(ctr, key_);
    for (int i = 0; i < 4; ++i) block_[i] = out.v[i];
    used_ = 0;
  }

  r123::Philox4x64::key_type key_;
  std::uint64_t counter_ = 0;
  std::uint64_t block_[4] = {0, 0, 0, 0};
  int used_ = 4;
};

// A direction uniform on the unit sphere (uniform z and azimuth: Archimedes), from two
// numbers of the stream.
inline Vec3 uniformDirection(RandomStream& random) {
  const double z = 2.0 * random.uniform() - 1.0;
  const double phi = 2.0 * std::numbers::pi * random.uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return Vec3(s * std::cos(phi), s * std::sin(phi), z);
}

}  // namespace cortex
