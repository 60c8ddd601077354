#pragma once
// Counter-based random numbers: a pure function of (seed, counters). Results therefore do not
// depend on the number of ranks or on the order of work, and a restart needs no generator state.
#include <cstdint>

namespace picdem::core {

/// SplitMix64 finaliser: a bijective 64-bit mixer with good avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::uint64_t hash_counters(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0,
                                      std::uint64_t c = 0) {
  return mix64(mix64(mix64(mix64(seed) ^ a) ^ b) ^ c);
}

/// Uniform double in [0, 1) from the counters.
constexpr double uniform01(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0,
                           std::uint64_t c = 0) {
  return static_cast<double>(hash_counters(seed, a, b, c) >> 11) * 0x1.0p-53;
}

}  // namespace picdem::core
