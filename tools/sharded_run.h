// `mpirun -n R manyworlds run ...`: the run command with its worlds sharded
// over the MPI ranks (ShardedBatch, docs/scale-out.md). Built only with the
// MPI layer (MANYWORLDS_MPI); tools/manyworlds.cc calls it when
// StartedByMpirun().
#pragma once

namespace manyworlds::tools {

// Initialises MPI, steps this rank's shard of --worlds exactly as `run`
// steps those worlds in one process (same actions, same bits), and prints
// on rank 0 the report over every rank's worlds with the total and per-rank
// world-steps/s. Collective: every rank must call it with the same
// arguments. Returns the exit code (as `run`): an error raised on every
// rank alike (arguments; a refusal on one rank is a RankError on all) is
// printed once, by rank 0; an error of one rank alone aborts every rank.
int ShardedRun(int argc, char** argv);

}  // namespace manyworlds::tools
