// ShardOfWorlds (manyworlds/shard.h): how worlds split over MPI ranks, the
// same rule for ShardedBatch and the Python environments' comm=. Checked for
// every total and rank count below: shares tile [0, total) in rank order,
// every rank has a world, shards start on block boundaries while blocks are
// at least as many as ranks, and shares differ by at most a block (a world).

#include "manyworlds/shard.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "manyworlds/lanes.h"

namespace manyworlds {
namespace {

TEST(ShardOfWorldsTest, SharesAreContiguousBalancedAndWholeBlocks) {
  for (const std::size_t total : {1, 2, 15, 16, 17, 37, 100, 4096, 4099}) {
    for (int ranks = 1; ranks <= 7; ++ranks) {
      if (total < std::size_t(ranks)) {
        EXPECT_THROW(ShardOfWorlds(total, 0, ranks), std::invalid_argument);
        continue;
      }
      std::size_t next = 0, smallest = total, largest = 0;
      const std::size_t blocks = (total + kLaneWidth - 1) / kLaneWidth;
      for (int r = 0; r < ranks; ++r) {
        const WorldShard shard = ShardOfWorlds(total, r, ranks);
        EXPECT_EQ(shard.first, next) << total << " worlds, rank " << r << " of " << ranks;
        EXPECT_GE(shard.count, 1u) << total << " worlds, rank " << r << " of " << ranks;
        if (blocks >= std::size_t(ranks)) {
          EXPECT_EQ(shard.first % kLaneWidth, 0u) << "a shard starts inside a block";
        }
        next = shard.first + shard.count;
        smallest = std::min(smallest, shard.count);
        largest = std::max(largest, shard.count);
      }
      EXPECT_EQ(next, total);
      // Balanced to a block (or to a world when blocks are fewer than ranks).
      EXPECT_LE(largest - smallest, blocks >= std::size_t(ranks) ? kLaneWidth : 1u)
          << total << " worlds over " << ranks << " ranks";
    }
  }
  EXPECT_THROW(ShardOfWorlds(100, 3, 3), std::invalid_argument);
  EXPECT_THROW(ShardOfWorlds(100, -1, 3), std::invalid_argument);
}

}  // namespace
}  // namespace manyworlds
