"""The vector environments sharded over MPI ranks (comm=), checked under
mpirun: ctest python_mpi_envs_{1,2,3}_ranks run

    mpirun -n R --oversubscribe /usr/bin/python3 -m mpi4py python/tests/mpi_envs_check.py

(-m mpi4py: an uncaught exception on any rank aborts every rank, so a
failed assertion fails the run instead of hanging it).

What must hold on every rank, for every environment id and autoreset mode:
- the rank's environment holds its shard of the worlds (the C++
  ShardOfWorlds rule), and the shards tile the total;
- everything it returns (observations, rewards, terminations,
  truncations, final observations and their masks, randomised parameters)
  is bit for bit the rows of its worlds in one process's environment of all
  the worlds, across autoresets with randomisation on;
- a NaN action in one world ends that world's episode on its rank only;
- a bad input on one rank (wrong action shape, unknown reset option)
  raises RankError naming that rank on every rank, and the next step works
  (no rank left waiting);
- a first reset without a seed gives every rank the same key.
"""

import sys

import numpy as np
from mpi4py import MPI

import manyworlds
import manyworlds.envs as envs
from manyworlds.envs import RankError

COMM = MPI.COMM_WORLD
RANK, RANKS = COMM.Get_rank(), COMM.Get_size()
TOTAL = 37  # 3 blocks: with 2 ranks 16 + 21 worlds, with 3 ranks 16 + 16 + 5
STEPS = 40
OPTIONS = dict(max_episode_steps=13, mass_scale=(0.8, 1.2), damping=(0.0, 0.1),
               gravity_scale=(0.9, 1.1))


def bits(a):
    a = np.ascontiguousarray(a)
    return a.view({4: np.uint32, 8: np.uint64, 1: np.uint8}[a.dtype.itemsize])


def rollout(env, actions, seed):
    """Every output; SAME_STEP's final_obs and its mask as zeros and False
    on steps without the key (Gymnasium adds it only when some world of the
    environment ended, and a shard may have none of those)."""
    out = [env.reset(seed=seed)[0]]
    for a in actions:
        obs, reward, terminated, truncated, info = env.step(a)
        out += [obs, reward, terminated, truncated]
        out += [info.get("final_obs", np.zeros_like(obs)),
                info.get("_final_obs", np.zeros(env.num_envs, np.bool_))]
    return out


def check_equal_to_one_process(env_id, mode):
    where = f"rank {RANK}/{RANKS}, {env_id}, {mode}"
    sharded = envs.make(env_id, num_envs=TOTAL, comm=COMM, autoreset_mode=mode, **OPTIONS)
    whole = envs.make(env_id, num_envs=TOTAL, autoreset_mode=mode, **OPTIONS)
    first, count = manyworlds.shard_of_worlds(TOTAL, RANK, RANKS)
    assert (sharded.world_offset, sharded.num_envs) == (first, count), where
    assert sharded.global_num_envs == TOTAL, where
    assert COMM.allreduce(sharded.num_envs) == TOTAL, where
    rows = slice(first, first + count)
    shape = (STEPS, TOTAL, *whole.single_action_space.shape)
    actions = np.random.default_rng(5).uniform(-1, 1, shape).astype(np.float32)
    actions[7, 30] = np.nan  # world 30 (the last rank's) breaks at step 8
    a = rollout(sharded, actions[:, rows], seed=3)
    b = rollout(whole, actions, seed=3)
    assert len(a) == len(b), f"{where}: {len(a)} outputs, one process {len(b)}"
    for i, (x, y) in enumerate(zip(a, b)):
        assert np.array_equal(bits(x), bits(y[rows])), f"{where}: output {i} differs"
    for name, values in sharded.world_parameters.items():
        assert np.array_equal(bits(values), bits(whole.world_parameters[name][rows])), \
            f"{where}: world_parameters[{name}] differs"
    return sharded


def check_refusals():
    env = envs.make("cartpole-balance", num_envs=TOTAL, comm=COMM)
    env.reset(seed=1)
    last = RANKS - 1
    good = np.zeros((env.num_envs, 1), np.float32)
    bad = np.zeros((env.num_envs + 1, 1), np.float32)
    try:
        env.step(bad if RANK == last else good)
        raise AssertionError(f"rank {RANK}: no RankError for rank {last}'s bad actions")
    except RankError as e:
        assert e.rank == last and "actions: expected shape" in str(e), str(e)
    try:
        env.reset(options={"frobnicate": 1} if RANK == 0 else None)
        raise AssertionError(f"rank {RANK}: no RankError for rank 0's bad option")
    except RankError as e:
        assert e.rank == 0 and "frobnicate" in str(e), str(e)
    obs, *_ = env.step(good)  # still in step with each other
    assert obs.shape == (env.num_envs, 5)


def check_entropy_key():
    env = envs.make("pendulum-swingup", num_envs=TOTAL, comm=COMM)
    env.reset()
    keys = COMM.allgather(env._stream_key)
    assert len(set(keys)) == 1, f"ranks drew different keys: {keys}"


def main():
    for env_id in envs.ids():
        for mode in ("NEXT_STEP", "SAME_STEP"):
            check_equal_to_one_process(env_id, mode)
    check_refusals()
    check_entropy_key()
    COMM.Barrier()
    if RANK == 0:
        print(f"mpi_envs_check: {RANKS} ranks, {len(envs.ids())} environments x 2 autoreset "
              f"modes bit for bit equal to one process; refusals raised on every rank")
    return 0


if __name__ == "__main__":
    sys.exit(main())
