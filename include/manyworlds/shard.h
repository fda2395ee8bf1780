// How a batch of worlds is split over processes (MPI ranks): one
// contiguous share each, the same rule in C++ (ShardedBatch,
// manyworlds/sharded_batch.h) and Python (envs' comm=), so that a world's
// global index means the same everywhere (docs/scale-out.md). Needs no MPI.
#pragma once

#include <cstddef>

namespace manyworlds {

// The global worlds [first, first + count) one rank owns.
struct WorldShard {
  std::size_t first = 0;
  std::size_t count = 0;
};

// The share of rank `rank` (0 <= rank < ranks) of `total_worlds`: contiguous,
// in rank order, and balanced to whole blocks of kLaneWidth (16) worlds
// while there are at least as many blocks as ranks, so that no rank steps a
// half-empty block it could have given away; else balanced to single
// worlds. Throws std::invalid_argument, naming the counts, for a rank out of
// range or total_worlds < ranks (a rank without worlds is a mistake of the
// launch, not something to step).
WorldShard ShardOfWorlds(std::size_t total_worlds, int rank, int ranks);

}  // namespace manyworlds
