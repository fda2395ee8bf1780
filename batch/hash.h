// SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014): one step of its sequence as a 64-bit hash, every
// input bit reaching every output bit. The reference scenes' actions are
// keyed with it (batch/scenes.cc), the run report's state digest
// (tools/run_report.cc) is built from it.
#pragma once

#include <cstdint>

namespace manyworlds {

constexpr std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace manyworlds
