// ShardOfWorlds (manyworlds/shard.h).

#include "manyworlds/shard.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "manyworlds/lanes.h"

namespace manyworlds {

WorldShard ShardOfWorlds(std::size_t total_worlds, int rank, int ranks) {
  if (ranks < 1 || rank < 0 || rank >= ranks) {
    throw std::invalid_argument("rank " + std::to_string(rank) + " is not one of " +
                                std::to_string(ranks) + " ranks");
  }
  const std::size_t n = std::size_t(ranks);
  const std::size_t r = std::size_t(rank);
  if (total_worlds < n) {
    throw std::invalid_argument("total worlds " + std::to_string(total_worlds) +
                                " is fewer than the " + std::to_string(ranks) +
                                " ranks: every rank needs at least one world");
  }
  const std::size_t blocks = (total_worlds + kLaneWidth - 1) / kLaneWidth;
  std::size_t first = 0, end = 0;
  if (blocks >= n) {
    // Whole blocks: only the last rank may step a partly empty block.
    // (The products fit 64 bits below 2^37 worlds, far past any batch.)
    first = std::min(blocks * r / n * kLaneWidth, total_worlds);
    end = std::min(blocks * (r + 1) / n * kLaneWidth, total_worlds);
  } else {
    first = total_worlds * r / n;
    end = total_worlds * (r + 1) / n;
  }
  return {first, end - first};
}

}  // namespace manyworlds
