"""What comm= costs an environment's step (docs/scale-out.md): run as

    mpirun -n R /usr/bin/python3 python/tests/bench_mpi_envs.py [--worlds N] [--smoke]

Every rank times `--steps` steps of its N cartpole-balance worlds sharded
with comm= (one allreduce per step, the refusal check) and of a plain
environment of N worlds, alternately, 5 times; rank 0 prints the medians
(the slowest rank's) and the difference per step. --smoke: a few steps
(the ctest run, no time checked).
"""

import argparse
import time

import numpy as np
from mpi4py import MPI

import manyworlds.envs as envs


def seconds_per_step(env, steps, comm):
    env.reset(seed=1)
    actions = np.zeros((env.num_envs, 1), np.float32)
    comm.Barrier()
    start = time.perf_counter()
    for _ in range(steps):
        env.step(actions)
    return comm.allreduce((time.perf_counter() - start) / steps, op=MPI.MAX)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--worlds", type=int, default=2048, help="worlds per rank")
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--smoke", action="store_true")
    args = parser.parse_args()
    comm = MPI.COMM_WORLD
    ranks = comm.Get_size()
    steps, repeats = (3, 1) if args.smoke else (args.steps, 5)
    sharded = envs.make("cartpole-balance", num_envs=args.worlds * ranks, comm=comm, threads=1)
    plain = envs.make("cartpole-balance", num_envs=args.worlds, threads=1)
    with_comm, without = [], []
    for _ in range(repeats):
        with_comm.append(seconds_per_step(sharded, steps, comm))
        without.append(seconds_per_step(plain, steps, comm))
    a, b = np.median(with_comm), np.median(without)
    if comm.Get_rank() == 0:
        print(f"bench_mpi_envs: {ranks} ranks, {args.worlds} cartpole-balance worlds each: "
              f"comm= {a * 1e6:.1f} us per step, plain {b * 1e6:.1f} us, comm= adds "
              f"{(a - b) * 1e6:.1f} us ({100 * (a - b) / b:.1f} %)")


if __name__ == "__main__":
    main()
