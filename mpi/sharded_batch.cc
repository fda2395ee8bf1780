// ShardedBatch (manyworlds/sharded_batch.h): worlds split over MPI ranks.
//
// No step sends a world's data anywhere: a rank steps its own shard exactly
// as a one-process Batch steps the same worlds (a world's result never
// depends on its lane, block or neighbours), so the only messages are the
// refusal checks (one allreduce of an int per collective call; a gather
// also checks that every rank passed rank 0's arguments, one broadcast) and
// what the caller gathers. Gathers use MPI_Gatherv with one derived
// datatype per world, so counts and offsets are in worlds, not bytes or
// floats: MPI's int holds them up to 2^31 worlds in all.

#include "manyworlds/sharded_batch.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>


namespace manyworlds {
namespace {

int RankOf(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

int SizeOf(MPI_Comm comm) {
  int size = 0;
  MPI_Comm_size(comm, &size);
  return size;
}

// One world's worth of `count` values of `type`, as an MPI datatype; freed
// at scope end.
class WorldType {
 public:
  WorldType(std::size_t count, MPI_Datatype type) {
    MPI_Type_contiguous(int(count), type, &type_);
    MPI_Type_commit(&type_);
  }
  ~WorldType() { MPI_Type_free(&type_); }
  WorldType(const WorldType&) = delete;
  WorldType& operator=(const WorldType&) = delete;
  MPI_Datatype get() const { return type_; }

 private:
  MPI_Datatype type_ = MPI_DATATYPE_NULL;
};

// Gathers every rank's `local` (local_worlds[rank] worlds of `per_world`
// values of `type`) to root, in rank order; root's `out` must hold them all.
void GatherWorlds(MPI_Comm comm, int root, const void* local, int local_count,
                  const std::vector<int>& counts, std::size_t per_world, MPI_Datatype type,
                  void* out) {
  const WorldType world(per_world, type);
  std::vector<int> displacements(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) {
    displacements[r] = displacements[r - 1] + counts[r - 1];
  }
  MPI_Gatherv(local, local_count, world.get(), out, counts.data(), displacements.data(),
              world.get(), root, comm);
}

}  // namespace

RankError::RankError(int rank, const std::string& message)
    : std::runtime_error("rank " + std::to_string(rank) + ": " + message), rank_(rank) {}

void AllRanksOrNone(MPI_Comm comm, const std::function<void()>& fn) {
  std::string message;
  bool failed = false;
  try {
    fn();
  } catch (const std::exception& e) {
    message = e.what();
    failed = true;
  } catch (...) {
    message = "an exception that is not a std::exception";
    failed = true;
  }
  // The lowest failing rank, or INT_MAX when none failed: one allreduce in
  // the common case, a broadcast of the message only after a refusal.
  const int mine = failed ? RankOf(comm) : INT_MAX;
  int first = INT_MAX;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == INT_MAX) return;
  int length = int(message.size());
  MPI_Bcast(&length, 1, MPI_INT, first, comm);
  message.resize(std::size_t(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, first, comm);
  throw RankError(first, message);
}

ShardedBatch::ShardedBatch(MPI_Comm comm, const Scene& scene, std::size_t total_worlds,
                           BatchOptions options) {
  MPI_Comm_dup(comm, &comm_);
  rank_ = RankOf(comm_);
  ranks_ = SizeOf(comm_);
  total_worlds_ = total_worlds;
  try {
    AllRanksOrNone(comm_, [&] {
      shard_ = ShardOfWorlds(total_worlds, rank_, ranks_);
      local_.emplace(scene, shard_.count, options);
    });
  } catch (...) {
    MPI_Comm_free(&comm_);
    throw;
  }
}

ShardedBatch::~ShardedBatch() {
  // MPI_Comm_free is collective in principle but completes locally in
  // every implementation for a communicator with nothing pending. After
  // MPI_Finalize (a caller's mistake) no MPI call is allowed: leave it.
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (comm_ != MPI_COMM_NULL && !finalized) MPI_Comm_free(&comm_);
}

WorldShard ShardedBatch::shard_of(int rank) const {
  return ShardOfWorlds(total_worlds_, rank, ranks_);
}

int ShardedBatch::owner(std::size_t global_world) const {
  if (global_world >= total_worlds_) {
    throw std::out_of_range("world " + std::to_string(global_world) + " out of range [0, " +
                            std::to_string(total_worlds_) + ")");
  }
  // Shards are contiguous and in rank order: binary search over ranks.
  int low = 0, high = ranks_ - 1;
  while (low < high) {
    const int mid = (low + high + 1) / 2;
    if (shard_of(mid).first <= global_world) {
      low = mid;
    } else {
      high = mid - 1;
    }
  }
  return low;
}

std::vector<int> ShardedBatch::WorldsPerRank() const {
  std::vector<int> counts;
  for (int r = 0; r < ranks_; ++r) counts.push_back(int(shard_of(r).count));
  return counts;
}

void ShardedBatch::AllOrNone(const std::function<void(Batch&)>& fn) {
  AllRanksOrNone(comm_, [&] { fn(*local_); });
}

void ShardedBatch::Step(const StepSettings& settings) { Step(settings, StepIo{}); }

void ShardedBatch::Step(const StepSettings& settings, const StepIo& io) {
  // Every rank's arguments checked before any rank steps: a refusal leaves
  // every shard where it was, so the worlds stay those of one process.
  AllOrNone([&](Batch& batch) { batch.CheckStep(settings, io); });
  try {
    local_->Step(settings, io);
  } catch (const std::exception& e) {
    // Accepted by the check, failed here alone (out of memory, another
    // thread's call): the other ranks would wait for this one forever.
    std::fprintf(stderr, "manyworlds: ShardedBatch::Step failed on rank %d of %d after every "
                         "rank's check passed: %s; ending every rank\n",
                 rank_, ranks_, e.what());
    std::fflush(stderr);
    MPI_Abort(comm_, 1);
  }
}

void ShardedBatch::CheckSameAsRankZero(const char* call, std::vector<std::uint64_t> values,
                                       const std::vector<const char*>& names, int root,
                                       const std::function<void()>& local_check) const {
  std::vector<std::uint64_t> rank_zeros = values;
  MPI_Bcast(rank_zeros.data(), int(rank_zeros.size()), MPI_UINT64_T, 0, comm_);
  AllRanksOrNone(comm_, [&] {
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i] != rank_zeros[i]) {
        throw std::invalid_argument(std::string(call) + ": " + names[i] + " " +
                                    std::to_string(values[i]) + " differs from rank 0's " +
                                    std::to_string(rank_zeros[i]) +
                                    " (every rank must pass the same)");
      }
    }
    if (root < 0 || root >= ranks_) {
      throw std::invalid_argument(std::string(call) + ": root " + std::to_string(root) +
                                  " is not one of the " + std::to_string(ranks_) + " ranks");
    }
    local_check();
  });
}

HealthCounts ShardedBatch::ReduceHealth(int root) const {
  CheckSameAsRankZero("ReduceHealth", {std::uint64_t(root)}, {"root"}, root, [] {});
  std::uint64_t local[6] = {0, 0, 0, 0, 0, 0};
  for (const std::uint8_t bits : local_->WorldHealth()) {
    local[0] += bits != 0;
    for (int bit = 0; bit < 5; ++bit) local[1 + bit] += (bits >> bit) & 1u;
  }
  std::uint64_t total[6] = {0, 0, 0, 0, 0, 0};
  MPI_Reduce(local, total, 6, MPI_UINT64_T, MPI_SUM, root, comm_);
  if (rank_ != root) return {};
  return {total[0], total[1], total[2], total[3], total[4], total[5]};
}

std::vector<std::uint8_t> ShardedBatch::GatherHealth(int root) const {
  CheckSameAsRankZero("GatherHealth", {std::uint64_t(root)}, {"root"}, root, [] {});
  const std::vector<int> counts = WorldsPerRank();
  std::vector<std::uint8_t> out(rank_ == root ? total_worlds_ : 0);
  const std::span<const std::uint8_t> health = local_->WorldHealth();
  GatherWorlds(comm_, root, health.data(), int(health.size()), counts, 1, MPI_UINT8_T,
               out.data());
  return out;
}

std::vector<float> ShardedBatch::GatherPerWorld(std::span<const float> local_values,
                                                std::size_t per_world, int root) const {
  CheckSameAsRankZero("GatherPerWorld", {per_world, std::uint64_t(root)}, {"per_world", "root"},
                      root, [&] {
    if (per_world > std::size_t(INT_MAX) || local_values.size() != shard_.count * per_world) {
      throw std::invalid_argument("GatherPerWorld: expected " + std::to_string(shard_.count) +
                                  " worlds x " + std::to_string(per_world) + " values, got " +
                                  std::to_string(local_values.size()));
    }
  });
  if (per_world == 0) return {};  // nothing to send (an MPI type of no values)
  const std::vector<int> counts = WorldsPerRank();
  std::vector<float> out(rank_ == root ? total_worlds_ * per_world : 0);
  GatherWorlds(comm_, root, local_values.data(), int(shard_.count), counts, per_world, MPI_FLOAT,
               out.data());
  return out;
}

std::vector<float> ShardedBatch::GatherStates(std::span<const std::size_t> global_worlds,
                                              int root) const {
  const std::size_t per_world = local_->body_count() * kStateFloatsPerBody;
  // The owned worlds of the list, in list order, read on their rank.
  std::vector<float> mine;
  std::vector<int> owners(global_worlds.size());
  // The same list on every rank, or the ranks would send what root does not
  // expect: its length and a hash of it against rank 0's.
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a over the indices
  for (const std::size_t world : global_worlds) hash = (hash ^ world) * 1099511628211ull;
  CheckSameAsRankZero("GatherStates", {global_worlds.size(), hash, std::uint64_t(root)},
                      {"the list's length", "the list's hash", "root"}, root, [&] {
    for (std::size_t i = 0; i < global_worlds.size(); ++i) {
      owners[i] = owner(global_worlds[i]);
    }
  });
  std::vector<int> counts(std::size_t(ranks_), int{0});
  for (std::size_t i = 0; i < global_worlds.size(); ++i) {
    ++counts[std::size_t(owners[i])];
    if (owners[i] != rank_) continue;
    const std::size_t at = mine.size();
    mine.resize(at + per_world);
    local_->GetWorldState(global_worlds[i] - shard_.first,
                          std::span<float>(mine.data() + at, per_world));
  }
  std::vector<float> by_rank(rank_ == root ? global_worlds.size() * per_world : 0);
  GatherWorlds(comm_, root, mine.data(), counts[std::size_t(rank_)], counts, per_world,
               MPI_FLOAT, by_rank.data());
  if (rank_ != root) return {};
  // by_rank holds rank 0's worlds in list order, then rank 1's, ...: back
  // into the list's order.
  std::vector<std::size_t> next(std::size_t(ranks_), 0);
  for (int r = 1; r < ranks_; ++r) {
    next[std::size_t(r)] = next[std::size_t(r) - 1] + std::size_t(counts[std::size_t(r) - 1]);
  }
  std::vector<float> out(global_worlds.size() * per_world);
  for (std::size_t i = 0; i < global_worlds.size(); ++i) {
    const std::size_t slot = next[std::size_t(owners[i])]++;
    std::memcpy(out.data() + i * per_world, by_rank.data() + slot * per_world,
                per_world * sizeof(float));
  }
  return out;
}

}  // namespace manyworlds
