"""Gymnasium when it is importable, else small stand-ins with the same names.

With gymnasium (1.x) installed, the environments subclass
gymnasium.vector.VectorEnv, use gymnasium.spaces and Gymnasium's own
AutoresetMode. Without it (Debian has no gymnasium package), they use the
classes below: the same attribute names, values and semantics as far as the
environments use them, so that code written against Gymnasium's vector API
runs unchanged.
"""

import enum

import numpy as np

try:  # pragma: no cover - not installed on the machines this is tested on
    import gymnasium as _gym
    from gymnasium import spaces as _gym_spaces
    from gymnasium.vector import VectorEnv as _GymVectorEnv
    from gymnasium.vector.utils import batch_space as _gym_batch_space

    try:
        from gymnasium.vector import AutoresetMode as _GymAutoresetMode
    except ImportError:  # gymnasium 1.0 has no enum; its metadata holds strings
        _GymAutoresetMode = None
    HAVE_GYMNASIUM = True
except ImportError:
    _gym = None
    HAVE_GYMNASIUM = False


class _FallbackAutoresetMode(enum.Enum):
    """gymnasium.vector.AutoresetMode's names and values."""

    NEXT_STEP = "NextStep"
    SAME_STEP = "SameStep"
    DISABLED = "Disabled"


if HAVE_GYMNASIUM and _GymAutoresetMode is not None:  # pragma: no cover
    AutoresetMode = _GymAutoresetMode
else:
    AutoresetMode = _FallbackAutoresetMode


def autoreset_mode(value):
    """An AutoresetMode from the enum itself, its name ("NEXT_STEP") or its
    value ("NextStep"), or ValueError listing the accepted ones."""
    if isinstance(value, AutoresetMode):
        return value
    if isinstance(value, enum.Enum):  # e.g. the other enum class
        value = value.value
    for mode in AutoresetMode:
        if value in (mode.name, mode.value):
            return mode
    accepted = ", ".join(f"{m.name} ({m.value!r})" for m in AutoresetMode)
    raise ValueError(f"autoreset_mode: expected one of {accepted}, got {value!r}")


# ---------------------------------------------------------------- spaces


class Space:
    """What gymnasium.spaces.Space offers that the environments use."""

    def __init__(self, shape, dtype, seed=None):
        self._shape = tuple(shape)
        self.dtype = np.dtype(dtype)
        self._np_random = None
        if seed is not None:
            self.seed(seed)

    @property
    def shape(self):
        return self._shape

    @property
    def np_random(self):
        if self._np_random is None:
            self.seed()
        return self._np_random

    def seed(self, seed=None):
        """Seeds sample(); returns [seed] as Gymnasium does."""
        self._np_random = np.random.default_rng(seed)
        return [seed]

    def __contains__(self, x):
        return self.contains(x)


class Box(Space):
    """gymnasium.spaces.Box: an array of `shape` and `dtype` with elementwise
    bounds low <= x <= high (scalars or arrays, broadcast to `shape`)."""

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        dtype = np.dtype(dtype)
        if shape is None:
            shape = np.broadcast(np.asarray(low), np.asarray(high)).shape
        shape = tuple(int(n) for n in shape)
        self.low = np.broadcast_to(np.asarray(low, dtype), shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype), shape).copy()
        if np.any(self.low > self.high):
            raise ValueError("Box: low must be <= high everywhere")
        super().__init__(shape, dtype, seed)

    def is_bounded(self, manner="both"):
        below, above = np.all(np.isfinite(self.low)), np.all(np.isfinite(self.high))
        return {"both": below and above, "below": below, "above": above}[manner]

    def sample(self, mask=None):
        """Uniform within finite bounds; normal or exponential where unbounded
        (as Gymnasium's Box.sample)."""
        rng = self.np_random
        low = self.low.astype(np.float64)
        high = self.high.astype(np.float64)
        sample = np.empty(self.shape, np.float64)
        bounded = np.isfinite(low) & np.isfinite(high)
        below = np.isfinite(low) & ~np.isfinite(high)
        above = ~np.isfinite(low) & np.isfinite(high)
        free = ~np.isfinite(low) & ~np.isfinite(high)
        sample[bounded] = rng.uniform(low[bounded], high[bounded])
        sample[below] = low[below] + rng.exponential(size=int(below.sum()))
        sample[above] = high[above] - rng.exponential(size=int(above.sum()))
        sample[free] = rng.normal(size=int(free.sum()))
        if np.issubdtype(self.dtype, np.integer):
            sample = np.floor(sample)
        return np.clip(sample, low, high).astype(self.dtype)

    def contains(self, x):
        if not isinstance(x, np.ndarray):
            try:
                x = np.asarray(x, dtype=self.dtype)
            except (ValueError, TypeError):
                return False
        return bool(np.can_cast(x.dtype, self.dtype) and x.shape == self.shape
                    and np.all(x >= self.low) and np.all(x <= self.high))

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"

    def __eq__(self, other):
        return (isinstance(other, Box) and self.shape == other.shape
                and self.dtype == other.dtype and np.array_equal(self.low, other.low)
                and np.array_equal(self.high, other.high))


class Discrete(Space):
    """gymnasium.spaces.Discrete: an integer in {start, ..., start + n - 1}."""

    def __init__(self, n, seed=None, start=0):
        self.n = np.int64(n)
        self.start = np.int64(start)
        if self.n <= 0:
            raise ValueError("Discrete: n must be positive")
        super().__init__((), np.int64, seed)

    def sample(self, mask=None):
        return np.int64(self.start + self.np_random.integers(self.n))

    def contains(self, x):
        if isinstance(x, (int, np.integer)):
            value = int(x)
        elif isinstance(x, np.ndarray) and x.shape == () and np.issubdtype(x.dtype, np.integer):
            value = int(x)
        else:
            return False
        return bool(self.start <= value < self.start + self.n)

    def __repr__(self):
        return f"Discrete({self.n})" if self.start == 0 else f"Discrete({self.n}, start={self.start})"

    def __eq__(self, other):
        return isinstance(other, Discrete) and self.n == other.n and self.start == other.start


class MultiDiscrete(Space):
    """gymnasium.spaces.MultiDiscrete: what batch_space makes of Discrete."""

    def __init__(self, nvec, dtype=np.int64, seed=None, start=None):
        self.nvec = np.asarray(nvec, dtype)
        self.start = (np.zeros_like(self.nvec) if start is None
                      else np.broadcast_to(np.asarray(start, dtype), self.nvec.shape).copy())
        super().__init__(self.nvec.shape, dtype, seed)

    def sample(self, mask=None):
        return (self.start + self.np_random.integers(self.nvec)).astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return bool(x.shape == self.shape and np.issubdtype(x.dtype, np.integer)
                    and np.all(x >= self.start) and np.all(x < self.start + self.nvec))

    def __repr__(self):
        return f"MultiDiscrete({self.nvec})"


def batch_space(space, n):
    """gymnasium.vector.utils.batch_space for Box and Discrete."""
    if isinstance(space, Box):
        return Box(np.broadcast_to(space.low, (n, *space.shape)),
                   np.broadcast_to(space.high, (n, *space.shape)), (n, *space.shape),
                   space.dtype)
    if isinstance(space, Discrete):
        return MultiDiscrete(np.full((n,), space.n, space.dtype), space.dtype,
                             start=np.full((n,), space.start, space.dtype))
    raise TypeError(f"batch_space: unsupported space {space!r}")


class _FallbackVectorEnv:
    """The parts of gymnasium.vector.VectorEnv the environments rely on."""

    metadata = {}
    spec = None
    render_mode = None
    closed = False
    num_envs = None
    observation_space = action_space = None
    single_observation_space = single_action_space = None
    _np_random = None
    _np_random_seed = None

    @property
    def np_random(self):
        if self._np_random is None:
            self._np_random = np.random.default_rng()
        return self._np_random

    @np_random.setter
    def np_random(self, value):
        self._np_random = value

    @property
    def np_random_seed(self):
        return self._np_random_seed

    @property
    def unwrapped(self):
        return self

    def close(self, **kwargs):
        if not self.closed:
            self.close_extras(**kwargs)
        self.closed = True

    def close_extras(self, **kwargs):
        pass

    def render(self):
        return None

    def __del__(self):
        if not getattr(self, "closed", True):
            try:
                self.close()
            except Exception:  # noqa: BLE001 - never raise from __del__
                pass

    def __enter__(self):
        return self

    def __exit__(self, *args):
        self.close()
        return False

    def __repr__(self):
        return f"{type(self).__name__}(num_envs={self.num_envs})"


if HAVE_GYMNASIUM:  # pragma: no cover
    VectorEnvBase = _GymVectorEnv

    def make_box(low, high, shape=None, dtype=np.float32):
        return _gym_spaces.Box(low, high, shape, dtype)

    def make_discrete(n, start=0):
        return _gym_spaces.Discrete(n, start=start)

    def batch(space, n):
        return _gym_batch_space(space, n)
else:
    VectorEnvBase = _FallbackVectorEnv

    def make_box(low, high, shape=None, dtype=np.float32):
        return Box(low, high, shape, dtype)

    def make_discrete(n, start=0):
        return Discrete(n, start=start)

    def batch(space, n):
        return batch_space(space, n)
