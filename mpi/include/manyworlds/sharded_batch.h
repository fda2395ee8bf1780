// A batch of worlds sharded over the ranks of an MPI communicator: each rank
// steps its own contiguous share of the worlds in its own Batch (its own TBB
// arena, its own threads), with the same global world numbering as one
// process. Worlds never interact, so a world's trajectory is bit for bit the
// same whatever the rank count: only the caller's per-world inputs (actions,
// seeds) must be keyed by the global world index, as SceneActions' are.
//
//   MPI_Init(&argc, &argv);
//   ShardedBatch batch(MPI_COMM_WORLD, scene, 1 << 20);    // collective
//   const SceneActions actions("cartpole");
//   for (std::uint64_t step = 0; step < 1000; ++step) {
//     actions.Apply(batch.local(), step, seed, batch.shard().first);
//     batch.Step(StepSettings{});                          // collective
//   }
//   const HealthCounts health = batch.ReduceHealth();      // on root, all worlds
//   const std::vector<float> states = batch.GatherStates(worlds_to_look_at);
//
// Collective calls (the constructor, Step, AllOrNone, the gathers) must be
// made by every rank of the communicator in the same order. A refusal on one
// rank (a bad per-world input, bad step settings, a bad index) is reported
// on every rank as a RankError naming the rank and its message, instead of
// one rank leaving and the others waiting for it forever. Everything else
// (local(), shard()) is the rank's own and needs no communication.
//
// This layer is optional at build time (MANYWORLDS_MPI, found with
// find_package(MPI)); docs/scale-out.md has the design, the measurements
// and how it scales.
#pragma once

// Only MPI's C API is used: skip the deprecated MPI-2 C++ bindings, whose
// OpenMPI headers do not compile warning-free under -Wextra.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#ifndef MPICH_SKIP_MPICXX
#define MPICH_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "manyworlds/batch.h"
#include "manyworlds/scene.h"
#include "manyworlds/shard.h"

namespace manyworlds {

// A refusal on some rank of a collective call, raised on every rank.
class RankError : public std::runtime_error {
 public:
  RankError(int rank, const std::string& message);
  // The lowest rank that refused.
  int rank() const { return rank_; }

 private:
  int rank_;
};

// WorldHealthBits counted over every world of every rank (ReduceHealth).
struct HealthCounts {
  std::uint64_t unhealthy = 0;          // worlds with any bit set
  std::uint64_t non_finite_state = 0;   // kNonFiniteState
  std::uint64_t velocity_overflow = 0;  // kVelocityOverflow
  std::uint64_t out_of_range = 0;       // kPositionOutOfRange
  std::uint64_t non_finite_input = 0;   // kNonFiniteInput
  std::uint64_t not_stepped = 0;        // kNotStepped
};

class ShardedBatch {
 public:
  // Collective. Each rank builds a Batch of its shard of total_worlds
  // (ShardOfWorlds, manyworlds/shard.h) with `options` (threads: per rank). The communicator is
  // duplicated, so the batch's messages never meet the caller's. Throws
  // RankError on every rank when any rank's Batch refuses (SceneError's
  // message, naming the body or constraint) or total_worlds < ranks.
  ShardedBatch(MPI_Comm comm, const Scene& scene, std::size_t total_worlds,
               BatchOptions options = {});
  ~ShardedBatch();
  ShardedBatch(const ShardedBatch&) = delete;
  ShardedBatch& operator=(const ShardedBatch&) = delete;

  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  std::size_t total_worlds() const { return total_worlds_; }
  WorldShard shard() const { return shard_; }
  WorldShard shard_of(int rank) const;
  // The rank that owns a global world (std::out_of_range beyond the total).
  int owner(std::size_t global_world) const;

  // This rank's worlds: local world i is global world shard().first + i.
  // Every Batch call works on it as on any Batch (no communication).
  Batch& local() { return *local_; }
  const Batch& local() const { return *local_; }

  // Collective: fn(local()) on every rank, then one allreduce of whether
  // any rank threw. If one did, every rank throws RankError with the lowest
  // failing rank's message (its batch unchanged where the library refuses
  // before writing, as it does for every bad input); the others' calls have
  // run. For per-world inputs that one rank may refuse.
  void AllOrNone(const std::function<void(Batch&)>& fn);

  // Collective: one Step of every rank's worlds. Every rank's arguments are
  // checked (Batch::CheckStep) before any rank steps: if one rank refuses,
  // every rank throws RankError and no world has stepped. Costs one
  // allreduce of an int besides the step. A step that fails on one rank
  // after passing the check (out of memory) calls MPI_Abort: the other
  // ranks could not go on without it.
  void Step(const StepSettings& settings);
  // Collective: the same with the StepIo of the local worlds (its spans are
  // [local world]...; see Batch::Step).
  void Step(const StepSettings& settings, const StepIo& io);

  // Collective reductions and gathers to `root`. On other ranks they return
  // an empty result. Worlds are in global order. Every rank must pass the
  // same root (and per_world, list): a rank that passes another throws
  // RankError on every rank, naming it, instead of a mismatched gather.
  HealthCounts ReduceHealth(int root = 0) const;
  // Every world's WorldHealth byte, [total_worlds].
  std::vector<std::uint8_t> GatherHealth(int root = 0) const;
  // A caller's per-world values (returns, rewards, errors): each rank gives
  // [shard().count][per_world], root gets [total_worlds][per_world].
  std::vector<float> GatherPerWorld(std::span<const float> local_values, std::size_t per_world,
                                    int root = 0) const;
  // The states ([body][13] each, GetWorldState) of chosen global worlds, in
  // the order given: [worlds.size()][body_count][13] on root. Every rank must
  // pass the same list; a world out of range throws RankError on every rank.
  std::vector<float> GatherStates(std::span<const std::size_t> global_worlds,
                                  int root = 0) const;

  MPI_Comm comm() const { return comm_; }

 private:
  std::vector<int> WorldsPerRank() const;  // shard_of(r).count for every rank
  // Collective: throws RankError on every rank, naming the lowest rank
  // whose `values` differ from rank 0's or whose local_check() throws, or
  // for a root that is not a rank.
  void CheckSameAsRankZero(const char* call, std::vector<std::uint64_t> values,
                           const std::vector<const char*>& names, int root,
                           const std::function<void()>& local_check) const;
  MPI_Comm comm_ = MPI_COMM_NULL;  // our duplicate of the caller's
  int rank_ = 0;
  int ranks_ = 1;
  std::size_t total_worlds_ = 0;
  WorldShard shard_;
  std::optional<Batch> local_;  // built in the constructor's collective check
};

// Collective over `comm`: runs fn() on every rank; if it threw on any rank
// (std::exception), throws RankError on every rank with the lowest failing
// rank's message. ShardedBatch::AllOrNone is this for a shard's batch; this
// form is for work before a batch exists or beside it.
void AllRanksOrNone(MPI_Comm comm, const std::function<void()>& fn);

}  // namespace manyworlds
