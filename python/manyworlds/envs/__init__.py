"""manyworlds.envs: vector environments over manyworlds batches, following
Gymnasium 1.x's VectorEnv protocol (docs/envs.md).

    import numpy as np
    import manyworlds.envs as envs

    env = envs.make("cartpole-balance", num_envs=4096)
    obs, info = env.reset(seed=0)
    for _ in range(1000):
        actions = env.action_space.sample()        # [4096, 1] in [-1, 1]
        obs, reward, terminated, truncated, info = env.step(actions)

One world of one Batch per sub-environment; everything per step is one
array operation over all worlds. With gymnasium installed the environments
are gymnasium.vector.VectorEnv subclasses with gymnasium.spaces; without it
(Debian has no package), small stand-ins with the same names (_compat.py).
"""

from ._compat import HAVE_GYMNASIUM, AutoresetMode, Box, Discrete, MultiDiscrete
from .arms import RagdollPoseEnv, ReacherEnv
from .control import AcrobotSwingupEnv, CartpoleEnv, PendulumSwingupEnv, cartpole_reward
from .locomotion import HopperForwardEnv, QuadrupedForwardEnv
from .rewards import tolerance
from ..sharding import RankError
from .vector import RANDOMIZATION_OPTIONS, ManyWorldsVectorEnv

__all__ = [
    "make", "ids", "AutoresetMode", "HAVE_GYMNASIUM", "Box", "Discrete", "MultiDiscrete",
    "ManyWorldsVectorEnv", "CartpoleEnv", "PendulumSwingupEnv", "AcrobotSwingupEnv",
    "ReacherEnv", "RagdollPoseEnv", "HopperForwardEnv", "QuadrupedForwardEnv", "tolerance",
    "cartpole_reward", "RANDOMIZATION_OPTIONS",
    "RankError",
]

# id -> (class, fixed keyword arguments)
_REGISTRY = {
    "cartpole-balance": (CartpoleEnv, {"swing_up": False}),
    "cartpole-swingup": (CartpoleEnv, {"swing_up": True}),
    "pendulum-swingup": (PendulumSwingupEnv, {}),
    "acrobot-swingup": (AcrobotSwingupEnv, {}),
    "reacher-2link": (ReacherEnv, {}),
    "ragdoll-pose": (RagdollPoseEnv, {}),
    "hopper-forward": (HopperForwardEnv, {}),
    "quadruped-forward": (QuadrupedForwardEnv, {}),
}


def ids():
    """The environment ids make() accepts."""
    return list(_REGISTRY)


def make(id, num_envs=1, **options):  # noqa: A002 - Gymnasium's name
    """A vector environment of `num_envs` worlds.

    options: autoreset_mode (AutoresetMode, its name or value; default
    NEXT_STEP), max_episode_steps (default: the task's), threads (0: every
    core), comm (an mpi4py communicator: the worlds sharded over its ranks,
    docs/scale-out.md), and the randomisation ranges mass_scale, damping, gravity_scale
    as (low, high) pairs (RANDOMIZATION_OPTIONS). Unknown ids raise
    ValueError listing the valid ones; unknown options TypeError.
    """
    try:
        cls, fixed = _REGISTRY[id]
    except (KeyError, TypeError):
        raise ValueError(f"unknown environment id {id!r}; valid: {', '.join(_REGISTRY)}") from None
    return cls(num_envs, **fixed, **options)
