"""manyworlds.sharding.ShardedBatch under mpirun: ctest
python_mpi_batch_{1,2,3}_ranks run

    mpirun -n R --oversubscribe /usr/bin/python3 -m mpi4py python/tests/mpi_batch_check.py

What must hold on every rank:
- the shards tile the worlds (the C++ rule), and after stepping with the
  scene's actions keyed by global world, the gathered states, joint
  coordinates and health are bit for bit one process's batch of all the
  worlds (ragdoll and cartpole; a NaN world flagged on its rank only);
- reduce_health counts every rank's worlds;
- a refusal on one rank (bad step settings on the last rank, after which no
  rank has stepped; a gather with the wrong row count on rank 0, or with
  another dtype on the last rank; too few worlds) raises RankError naming
  that rank on every rank, and the next collective call works.
"""

import sys

import numpy as np
from mpi4py import MPI

import manyworlds as mw
from manyworlds.sharding import RankError, ShardedBatch

COMM = MPI.COMM_WORLD
RANK, RANKS = COMM.Get_rank(), COMM.Get_size()
TOTAL = 37
SEED = 7


def bits(a):
    a = np.ascontiguousarray(a)
    return a.view({4: np.uint32, 1: np.uint8}[a.dtype.itemsize])


def expect_rank_error(rank, words, call):
    try:
        call()
    except RankError as e:
        assert e.rank == rank and words in str(e), f"rank {RANK}: {e}"
        return
    raise AssertionError(f"rank {RANK}: no RankError (rank {rank}, {words!r})")


def check_equal_to_one_process(scene_id, steps):
    scene = mw.make_scene(scene_id)
    actions = mw.SceneActions(scene_id)
    sharded = ShardedBatch(COMM, scene, TOTAL, threads=1)
    assert (sharded.first, sharded.count) == mw.shard_of_worlds(TOTAL, RANK, RANKS)
    assert COMM.allreduce(sharded.count) == TOTAL
    nan_world = 30
    last_body = len(scene.bodies) - 1
    for step in range(steps):
        actions.apply(sharded.local, step, SEED, sharded.first)
        if step == 5:  # on the last body, which the scene's actions never push
            forces = np.zeros((TOTAL, 3), np.float32)
            forces[nan_world, 0] = np.nan
            sharded.local.set_body_forces(last_body, forces[sharded.first:][:sharded.count])
        sharded.step(mw.StepSettings())
    states = sharded.gather(sharded.local.get_state())
    joints = sharded.gather(sharded.local.get_joint_coordinates())
    health = sharded.gather(np.asarray(sharded.local.health))
    counts = sharded.reduce_health()
    if RANK != 0:
        assert states is None and joints is None and health is None and counts is None
        return
    one = mw.Batch(scene, TOTAL, threads=1)
    for step in range(steps):
        actions.apply(one, step, SEED)
        if step == 5:
            forces = np.zeros((TOTAL, 3), np.float32)
            forces[nan_world, 0] = np.nan
            one.set_body_forces(last_body, forces)
        one.step(mw.StepSettings())
    assert np.array_equal(bits(states), bits(one.get_state())), f"{scene_id}: states differ"
    assert np.array_equal(bits(joints), bits(one.get_joint_coordinates())), scene_id
    assert np.array_equal(health, np.asarray(one.health)), f"{scene_id}: health differs"
    assert np.flatnonzero(health).tolist() == [nan_world], health
    assert counts["unhealthy"] == 1 and counts["non_finite_state"] == 1, counts
    assert not np.array_equal(one.get_state()[0], mw.Batch(scene, 1).get_state()[0])


def check_refusals():
    sharded = ShardedBatch(COMM, mw.make_scene("cartpole"), TOTAL, threads=1)
    last = RANKS - 1
    bad = mw.StepSettings()
    bad.substeps = 0
    before = sharded.gather(sharded.local.get_state())
    expect_rank_error(last, "substeps",
                      lambda: sharded.step(bad if RANK == last else mw.StepSettings()))
    after = sharded.gather(sharded.local.get_state())  # no rank stepped
    assert RANK != 0 or np.array_equal(bits(before), bits(after)), "a rank stepped"
    rows = sharded.count + (1 if RANK == 0 else 0)
    expect_rank_error(0, "expected", lambda: sharded.gather(np.zeros(rows, np.float32)))
    if RANKS > 1:  # rows unlike rank 0's need a second rank
        dtype = np.float64 if RANK == last else np.float32
        expect_rank_error(last, "rank 0's",
                          lambda: sharded.gather(np.zeros(sharded.count, dtype)))
        expect_rank_error(last, "reduce_health: root",
                          lambda: sharded.reduce_health(1 if RANK == last else 0))
    expect_rank_error(0, "not one of", lambda: sharded.gather(np.zeros(sharded.count), RANKS))
    expect_rank_error(0, "every rank needs at least one world",
                      lambda: ShardedBatch(COMM, mw.make_scene("cartpole"), RANKS - 1))
    sharded.step(mw.StepSettings())  # still in step with each other
    assert sharded.reduce_health() in (None, {"unhealthy": 0, "non_finite_state": 0,
                                              "velocity_overflow": 0, "out_of_range": 0,
                                              "non_finite_input": 0, "not_stepped": 0})


def main():
    check_equal_to_one_process("ragdoll", 30)
    check_equal_to_one_process("cartpole", 60)
    check_refusals()
    COMM.Barrier()
    if RANK == 0:
        print(f"mpi_batch_check: {RANKS} ranks: gathered worlds bit for bit one process; "
              "refusals raised on every rank")
    return 0


if __name__ == "__main__":
    sys.exit(main())
