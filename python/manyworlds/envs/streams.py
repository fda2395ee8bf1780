"""Random numbers per world: what a world draws at a reset depends only on
(the environment's key, its global world index, its episode number, what
is drawn), never on how many worlds there are, which other worlds reset
with it, or how the worlds are sharded over MPI ranks (docs/envs.md,
"Seeding"; docs/scale-out.md).

A counter-based generator in numpy, vectorised over worlds: the value of
element k of a world's d-th draw is a hash of (key, world, episode,
purpose, d, k), with SplitMix64's finaliser as the hash (its outputs pass
BigCrush as a sequence; Steele, Lea and Flood, "Fast splittable
pseudorandom number generators", OOPSLA 2014). Uniform doubles take the top
53 bits; normals come from the Box-Muller transform of two uniforms.

The draw methods have numpy.random.Generator's names and argument order, so
the tasks' _reset_states(idx, rng) code reads the same; `size` is required
and its first dimension is the number of worlds.
"""

import numpy as np

_GOLDEN = np.uint64(0x9E3779B97F4A7C15)
_M1 = np.uint64(0xBF58476D1CE4E5B9)
_M2 = np.uint64(0x94D049BB133111EB)
_S30, _S27, _S31 = np.uint64(30), np.uint64(27), np.uint64(31)
_TOP53 = np.uint64(11)
_UNIT = 1.0 / 9007199254740992.0  # 2^-53

# What a draw is for, so that the states and the randomisation of a reset
# never share numbers.
PURPOSE_RESET = 1
PURPOSE_RANDOMIZATION = 2


def mix(x):
    """SplitMix64's finaliser on a uint64 array (wrapping arithmetic)."""
    x = np.asarray(x, np.uint64)
    x = (x ^ (x >> _S30)) * _M1
    x = (x ^ (x >> _S27)) * _M2
    return x ^ (x >> _S31)


def key_of(seed):
    """The 64-bit key of a seed (an int or a list of ints), through numpy's
    SeedSequence, as np.random.default_rng(seed) uses it."""
    return int(np.random.SeedSequence(seed).generate_state(1, np.uint64)[0])


class WorldRandom:
    """Draws for a set of worlds, one independent stream per world.

    worlds: global world indices [n]; episodes: each world's episode number
    [n] (how many resets it had before this one); purpose: PURPOSE_*.
    """

    def __init__(self, key, worlds, episodes, purpose):
        worlds = np.asarray(worlds, np.uint64)
        episodes = np.asarray(episodes, np.uint64)
        with np.errstate(over="ignore"):
            base = mix(mix(np.uint64(key) ^ np.uint64(purpose) * _GOLDEN) ^ worlds)
            self._base = mix(base ^ episodes * _GOLDEN)
        # Each world's own draw counter: a world's d-th draw is the same
        # numbers whichever other worlds drew with it (rows() below).
        self._draws = np.zeros(len(self._base), np.uint64)
        self._rows = np.arange(len(self._base))

    @property
    def n(self):
        return len(self._rows)

    def rows(self, mask):
        """The same streams for the worlds where mask is True (a boolean array
        over this object's worlds), sharing their draw counters: rejection
        sampling that redraws only the rejected worlds."""
        subset = WorldRandom.__new__(WorldRandom)
        subset._base, subset._draws = self._base, self._draws
        subset._rows = self._rows[np.asarray(mask, np.bool_)]
        return subset

    def _bits(self, size):
        shape = (size,) if np.isscalar(size) else tuple(size)
        if not shape or shape[0] != self.n:
            raise ValueError(f"size {size}: the first dimension must be the {self.n} worlds")
        per_world = int(np.prod(shape[1:], dtype=np.int64))
        element = mix(np.arange(per_world, dtype=np.uint64) + _GOLDEN)
        with np.errstate(over="ignore"):
            draw = self._draws[self._rows] * _GOLDEN
            bits = mix(self._base[self._rows][:, None] ^ mix(draw[:, None] ^ element[None, :]))
        self._draws[self._rows] += np.uint64(1)
        return bits.reshape(shape)

    def random(self, size):
        """Uniform float64 in [0, 1)."""
        return (self._bits(size) >> _TOP53).astype(np.float64) * _UNIT

    def uniform(self, low, high, size):
        """Uniform in [low, high), as Generator.uniform: low + (high - low) u."""
        return low + (high - low) * self.random(size)

    def standard_normal(self, size):
        """Standard normal float64 (Box-Muller; 1 - u keeps the log finite)."""
        u1 = self.random(size)
        u2 = self.random(size)
        return np.sqrt(-2.0 * np.log1p(-u1)) * np.cos(2.0 * np.pi * u2)

    def normal(self, loc, scale, size):
        return loc + scale * self.standard_normal(size)
