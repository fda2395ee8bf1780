"""ctest example_ppo_cartpole_mpi: `mpirun -n 2 python3 examples/ppo_cartpole.py`
trains with 2 ranks (docs/scale-out.md): the 64 worlds sharded 32 + 32
(envs.make(..., comm=)), gradients averaged with an allreduce.

Seed 1, at most 200k environment steps over both ranks (about 25 s here).
As in test_ppo_cartpole.py, PPO must reach twice the random policy's
return (~275, so ~550): a broken gradient average (ranks drifting apart),
a wrong shard or unreduced observation statistics stay near the random
return and fail it. Measured: solved (930.7 then 970.7) at 147k steps in
15.5 s.
"""

import os
import re
import shutil
import subprocess
import sys

PPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ppo_cartpole.py")


def test_ppo_learns_cartpole_balance_with_two_mpi_ranks():
    mpirun = os.environ.get("MPIEXEC") or shutil.which("mpirun")
    assert mpirun, "mpirun not found: scripts/install-deps installs openmpi-bin"
    # OpenMPI refuses root without these two; they change nothing else.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = [mpirun, "-n", "2", "--oversubscribe", sys.executable, PPO,
               "--steps", "200000", "--seed", "1", "--out", ""]
    result = subprocess.run(command, capture_output=True, text=True, timeout=900, env=env)
    print(result.stdout)
    header = re.findall(r"^cartpole-balance: 64 worlds over 2 MPI ranks, random policy return "
                        r"([0-9.]+)$", result.stdout, re.M)
    assert len(header) == 1, f"expected rank 0's header once: {result.stdout!r} {result.stderr!r}"
    assert re.search(r"^(solved|not solved): \d+ steps", result.stdout, re.M), \
        f"the run did not finish: {result.stderr!r}"
    random_return = float(header[0])
    evaluations = [float(e) for e in re.findall(r"evaluation +([0-9.]+)", result.stdout)]
    assert evaluations, "no evaluation was logged"
    best = max(evaluations)
    print(f"random policy {random_return:.1f}, best evaluation {best:.1f}")
    assert 200 < random_return < 400, f"random policy return {random_return}: the task changed"
    assert best >= 2.0 * random_return, (
        f"PPO with 2 ranks reached {best:.1f}, not twice the random policy's "
        f"{random_return:.1f}")
