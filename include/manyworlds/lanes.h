// Lane width and the aligned lane arrays every block is made of.
//
// Worlds are grouped into blocks of kLaneWidth worlds. A block stores every
// field as kLaneWidth consecutive floats (one per world), so body k of 16
// worlds loads with one aligned vector load on AVX-512, two on AVX2 and four
// on SSE4/NEON. The width is a compile-time constant at least as wide as the
// widest target so that a block never depends on the machine it runs on.
#pragma once

#include <cstddef>

namespace manyworlds {

inline constexpr std::size_t kLaneWidth = 16;
inline constexpr std::size_t kLaneAlignment = 64;  // one AVX-512 vector / cache line

// One float field of a block: lane i belongs to world (block * kLaneWidth + i).
struct alignas(kLaneAlignment) LaneArray {
  float lanes[kLaneWidth];

  float& operator[](std::size_t lane) { return lanes[lane]; }
  float operator[](std::size_t lane) const { return lanes[lane]; }
};

struct Vec2Lanes {
  LaneArray x, y;
};

struct Vec3Lanes {
  LaneArray x, y, z;
};

// Quaternion (x, y, z, w), w the real part (Jolt's convention).
struct QuatLanes {
  LaneArray x, y, z, w;
};

// Symmetric 2x2 matrix: K is symmetric for every two-row part, so is K^-1.
struct Sym22Lanes {
  LaneArray xx, xy, yy;
};

struct Sym33Lanes {
  LaneArray xx, xy, xz, yy, yz, zz;
};

// Row-major 3x3: m[row][column].
struct Mat33Lanes {
  LaneArray m[3][3];
};

// Per-lane flags stored as floats: 0 = off, anything else = on. Floats keep the
// flags in the same aligned vector loads as the data they select.
using LaneFlags = LaneArray;

}  // namespace manyworlds
