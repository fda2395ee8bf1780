"""The vector environment every task derives from: Gymnasium 1.x's VectorEnv
protocol over one manyworlds.Batch (one world per sub-environment).

Every per-step computation is over all worlds at once: actions are written
with one array call, the batch steps every world in C++, observations come
from one joint-coordinate read, rewards and terminations are numpy
expressions over [num_envs] arrays. No per-world Python loop anywhere.
"""

import numpy as np

from .. import _core, sharding
from . import _compat, streams
from ._compat import AutoresetMode

# The per-world randomisation options (make(..., name=(low, high)) or
# reset(options={name: (low, high)})): drawn uniformly per world at every
# reset of that world, for every dynamic body of the task's scene.
RANDOMIZATION_OPTIONS = {
    "mass_scale": "each dynamic body's mass and inertia times U(low, high), per world and body",
    "damping": "each dynamic body's linear and angular damping (1/s) = U(low, high), per world "
               "and body (the scenes have none: joint damping is applied as a torque instead)",
    "gravity_scale": "every body's gravity factor times U(low, high), one factor per world",
}


def _range(name, value):
    if value is None:
        return None
    try:
        low, high = (float(v) for v in value)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected a (low, high) pair, got {value!r}") from None
    if not (np.isfinite(low) and np.isfinite(high) and low <= high):
        raise ValueError(f"{name}: expected finite low <= high, got {value!r}")
    return low, high


def planar_states(x, y, angle, vx, vy, omega):
    """Body state rows [n, 13] of bodies moving in the X-Y plane and turning
    about -Z by `angle` (rad; the hinges of these tasks turn about -Z, so a
    positive angle tips a body's +Y axis towards +X, as dm_control's hinges
    about +Y tip +Z towards +X). Inputs are [n] arrays (float64)."""
    n = np.shape(angle)[0]
    rows = np.zeros((n, 13), np.float64)
    rows[:, 0], rows[:, 1] = x, y
    rows[:, 5] = -np.sin(0.5 * np.asarray(angle))
    rows[:, 6] = np.cos(0.5 * np.asarray(angle))
    rows[:, 7], rows[:, 8] = vx, vy
    rows[:, 12] = -np.asarray(omega)
    return rows


def rotate(angle, px, py):
    """(px, py) turned by `angle` about -Z: (px cos + py sin, -px sin + py cos)."""
    c, s = np.cos(angle), np.sin(angle)
    return px * c + py * s, -px * s + py * c


class ManyWorldsVectorEnv(_compat.VectorEnvBase):
    """Base of every manyworlds.envs environment (see docs/envs.md).

    A subclass sets `env_id`, `default_max_episode_steps`, `step_settings`
    and the spaces, and implements _make_scene(), _reset_states(idx, rng),
    _actions(actions) (the step's action keywords, e.g. {"body_forces":
    {body: [W, 3] array}}, written by the step itself: see Batch.step),
    _observe() and _reward(actions); optionally _terminated() and
    _on_reset(idx, rng). `rng` is a streams.WorldRandom over the worlds idx
    (Generator's draw methods, first dimension the worlds).

    With comm (an mpi4py communicator), the num_envs worlds are sharded over
    its ranks: this rank's environment holds the worlds [world_offset,
    world_offset + num_envs) of global_num_envs, and each world behaves
    exactly as in one process (docs/scale-out.md).
    """

    env_id = None
    default_max_episode_steps = 1000
    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP, "render_modes": []}

    def __init__(self, num_envs, *, autoreset_mode=AutoresetMode.NEXT_STEP,
                 max_episode_steps=None, threads=0, mass_scale=None, damping=None,
                 gravity_scale=None, comm=None, **unknown):
        if unknown:
            raise TypeError(f"{self.env_id}: unknown option(s) {sorted(unknown)}; accepted: "
                            "num_envs, autoreset_mode, max_episode_steps, threads, comm, "
                            + ", ".join(RANDOMIZATION_OPTIONS))
        num_envs = int(num_envs)
        if num_envs < 1:
            raise ValueError(f"num_envs: expected >= 1, got {num_envs}")
        # Sharding: the global worlds this rank owns (the C++ ShardOfWorlds).
        self.comm = comm
        self.global_num_envs = num_envs
        self.world_offset = 0
        if comm is not None:
            self.world_offset, num_envs = _core.shard_of_worlds(
                num_envs, comm.Get_rank(), comm.Get_size())
        self.num_envs = num_envs
        self.metadata = dict(type(self).metadata)
        self.metadata["autoreset_mode"] = _compat.autoreset_mode(autoreset_mode)
        self.render_mode = None
        self.max_episode_steps = int(max_episode_steps if max_episode_steps is not None
                                     else self.default_max_episode_steps)
        if self.max_episode_steps < 1:
            raise ValueError(f"max_episode_steps: expected >= 1, got {max_episode_steps}")
        self.randomization = {
            "mass_scale": _range("mass_scale", mass_scale),
            "damping": _range("damping", damping),
            "gravity_scale": _range("gravity_scale", gravity_scale),
        }

        self.scene = self._make_scene()
        self.batch = _core.Batch(self.scene, num_envs, threads=threads)
        bodies = self.scene.bodies
        self._dynamic = [i for i, b in enumerate(bodies)
                         if b.motion_type == _core.MotionType.DYNAMIC]
        self._masses = np.array([bodies[i].mass for i in self._dynamic], np.float32)
        self._inertias = np.array([bodies[i].inertia_diagonal for i in self._dynamic], np.float32)
        self._gravity_factors = np.array([bodies[i].gravity_factor for i in self._dynamic],
                                         np.float32)
        # The per-world parameters in force (what the last reset drew), [W, dynamic body].
        self.world_parameters = {
            "mass_scale": np.ones((num_envs, len(self._dynamic)), np.float32),
            "damping": np.zeros((num_envs, len(self._dynamic)), np.float32),
            "gravity_scale": np.ones(num_envs, np.float32),
        }

        self.single_observation_space = self._observation_space()
        self.single_action_space = self._action_space()
        self.observation_space = _compat.batch(self.single_observation_space, num_envs)
        self.action_space = _compat.batch(self.single_action_space, num_envs)
        self._action_low = np.asarray(self.single_action_space.low, np.float32)
        self._action_high = np.asarray(self.single_action_space.high, np.float32)

        # Every world's joint coordinates after the last step or reset
        # ([W, joint_coordinates_per_world], constraints in scene order), and
        # the body states when the task asks for them (needs_state).
        self._joints = np.zeros((num_envs, self.batch.joint_coordinates_per_world), np.float32)
        self._state = np.zeros((num_envs, self.batch.num_bodies, 13), np.float32)
        # The scene's initial state of one world: static bodies keep it at resets.
        self._initial_state = self.batch.get_state()[0].copy()
        self._elapsed = np.zeros(num_envs, np.int64)
        self._autoreset_envs = np.zeros(num_envs, np.bool_)
        self._needs_reset = True  # reset() must come first, as in Gymnasium
        self._np_random = None
        self._np_random_seed = None
        # The key of every world's random stream (streams.py) and how many
        # times each world was reset since it was seeded.
        self._stream_key = None
        self._episodes = np.zeros(num_envs, np.uint64)
        self._global_worlds = self.world_offset + np.arange(num_envs, dtype=np.uint64)

    # ------------------------------------------------------------ protocol

    @property
    def autoreset_mode(self):
        return self.metadata["autoreset_mode"]

    def reset(self, *, seed=None, options=None):
        """(obs [num_envs, ...], info). seed: an int (or list of ints) seeds
        every world's random stream (episode numbers start again); None
        keeps them (first reset: from entropy, rank 0's under MPI).
        options: {"reset_mask": bool [num_envs]} resets only those worlds
        (the others keep their observation), and any randomisation option
        overrides make()'s for this reset. Collective under MPI."""
        def check():
            mask, overrides = self._reset_arguments(options)
            return mask, overrides, (None if seed is None else streams.key_of(seed))

        mask, overrides, key = self._agreed(check)
        if self.comm is not None:
            # The same seed (or none) on every rank, or the shards would not
            # be one environment: every rank compares them all.
            sharding.same_on_every_rank(self.comm, key,
                                        lambda mine, zero: "reset: seed differs from rank 0's")
        if key is not None:
            self._np_random = np.random.default_rng(seed)
            self._np_random_seed = seed if isinstance(seed, int) else None
            self._stream_key = key
            self._episodes[:] = 0
        elif self._stream_key is None:
            # From entropy; every rank must use the same key.
            key = streams.key_of(None)
            self._stream_key = key if self.comm is None else self.comm.bcast(key, root=0)
            self._np_random = np.random.default_rng(self._stream_key)
        self._reset_worlds(mask, overrides)
        self._autoreset_envs[mask] = False
        self._needs_reset = False
        return self._observe(), {}

    def _reset_arguments(self, options):
        """(reset mask, randomisation overrides) of reset's options, or
        ValueError naming what is wrong."""
        options = dict(options or {})
        mask = options.pop("reset_mask", None)
        if mask is None:
            mask = np.ones(self.num_envs, np.bool_)
        else:
            if not isinstance(mask, np.ndarray) or mask.dtype != np.bool_ \
                    or mask.shape != (self.num_envs,):
                raise ValueError(f"reset_mask: expected a numpy bool array of shape "
                                 f"({self.num_envs},), got {type(mask).__name__} "
                                 f"{getattr(mask, 'dtype', '')} {getattr(mask, 'shape', '')}")
            # (Sharded, a rank's mask may select none of its worlds when
            # other ranks reset theirs.)
            if not mask.any() and self.comm is None:
                raise ValueError("reset_mask: selects no environment")
            if self._needs_reset and not mask.all():
                raise ValueError("reset_mask: the first reset must reset every environment")
        overrides = {}
        for name in list(options):
            if name in RANDOMIZATION_OPTIONS:
                overrides[name] = _range(name, options.pop(name))
        if options:
            raise ValueError(f"options: unknown key(s) {sorted(options)}; accepted: reset_mask, "
                             + ", ".join(RANDOMIZATION_OPTIONS))
        return mask, overrides

    def _agreed(self, check):
        """check()'s result. Sharded, every rank learns whether any rank's
        check raised (sharding.agreed: one allreduce), and then every rank
        raises RankError with the lowest failing rank's message: a bad input
        on one rank never leaves the others waiting in a later collective."""
        return check() if self.comm is None else sharding.agreed(self.comm, check)

    def step(self, actions):
        """(obs, reward, terminated, truncated, info), all [num_envs, ...]."""
        if self._needs_reset:
            raise RuntimeError(f"{self.env_id}: call reset() before step()")
        mode = self.metadata["autoreset_mode"]

        def check():
            checked = self._checked_actions(actions)
            if mode == AutoresetMode.DISABLED and self._autoreset_envs.any():
                raise AssertionError(
                    "autoreset_mode DISABLED: environments "
                    f"{np.flatnonzero(self._autoreset_envs).tolist()} terminated or truncated "
                    "and were not reset: call reset(options={'reset_mask': mask}) first")
            return checked

        actions = self._agreed(check)
        # NEXT_STEP: the worlds done last step are reset now; their action is
        # ignored (they step with zeros, then are overwritten by the reset).
        # The reset is done by the step itself, after each block's step and
        # before its observations are read (Batch.step(reset_mask=...)): the
        # reset states and task variables are drawn first, the per-world
        # randomisation after, in the generator order of a separate reset.
        pending = self._autoreset_envs.copy() if mode == AutoresetMode.NEXT_STEP else None
        resetting = pending is not None and pending.any()
        reset_states = None
        if resetting:
            actions = actions.copy()
            actions[pending] = 0.0
            reset_states = self._draw_reset(pending)

        self._step_batch(self._actions(actions), pending if resetting else None, reset_states)
        self._elapsed += 1
        if resetting:
            self._finish_reset(pending, {})

        unhealthy = self.batch.health != 0
        if pending is not None:
            unhealthy &= ~pending  # reset below: their episode already ended
        obs = self._observe()
        reward = np.asarray(self._reward(actions), np.float64)
        terminated = np.asarray(self._terminated(), np.bool_) | unhealthy
        truncated = self._elapsed >= self.max_episode_steps
        info = {}
        if unhealthy.any():
            # A broken world's numbers mean nothing: zeros, and the episode ends.
            obs[unhealthy] = 0.0
            reward = np.where(unhealthy, 0.0, reward)
            info["unhealthy"] = unhealthy
            info["_unhealthy"] = unhealthy.copy()

        if mode == AutoresetMode.NEXT_STEP:
            if resetting:  # obs above is already their new episode's first
                reward[pending] = 0.0
                terminated[pending] = False
                truncated[pending] = False
            self._autoreset_envs = terminated | truncated
        elif mode == AutoresetMode.SAME_STEP:
            done = terminated | truncated
            if done.any():
                final_obs = np.zeros_like(obs)
                final_obs[done] = obs[done]
                info["final_obs"] = final_obs
                info["_final_obs"] = done.copy()
                info["final_info"] = {}
                info["_final_info"] = done.copy()
                self._reset_worlds(done, {})
                obs = self._observe()
        else:  # DISABLED
            self._autoreset_envs = terminated | truncated
        return obs, reward, terminated, truncated, info

    # ------------------------------------------------------------ helpers

    def _checked_actions(self, actions):
        shape = (self.num_envs, *self.single_action_space.shape)
        array = np.asarray(actions)
        if array.shape != shape:
            raise ValueError(f"actions: expected shape {shape}, got {array.shape}")
        if not (np.issubdtype(array.dtype, np.floating) or np.issubdtype(array.dtype, np.integer)):
            raise TypeError(f"actions: expected a float array, got {array.dtype}")
        # Clipped into the action space, as dm_control clips controls into
        # ctrlrange (NaN stays NaN: the world is flagged and its episode ends).
        return np.clip(array.astype(np.float32, copy=False), self._action_low, self._action_high)

    needs_state = False

    def _read_state(self):
        self.batch.get_joint_coordinates(out=self._joints)
        if self.needs_state:
            self.batch.get_state(out=self._state)

    def _step_batch(self, actions, reset_mask, reset_states):
        """One step of every world; the actions (the keywords of _actions),
        the observations and the resets of reset_mask, if any, done by the
        step in the same pass over the worlds."""
        self.batch.step(self.step_settings, **actions, reset_mask=reset_mask,
                        reset_states=reset_states,
                        joints_out=self._joints,
                        state_out=self._state if self.needs_state else None)

    def _reset_worlds(self, mask, overrides):
        """Resets the worlds where mask is True: initial states and task
        variables drawn from their streams, randomisation re-applied."""
        states = self._draw_reset(mask)
        if mask.any():
            self.batch.reset_to(mask, states)
        self._finish_reset(mask, overrides)
        self._read_state()

    def _world_random(self, idx, purpose):
        """The random streams of the worlds idx for this reset (streams.py)."""
        return streams.WorldRandom(self._stream_key, self._global_worlds[idx],
                                   self._episodes[idx], purpose)

    def _draw_reset(self, mask):
        """The first half of a reset of the worlds where mask is True: their
        initial body states [num_envs, bodies, 13] (other rows unread) and
        task variables, drawn from their streams."""
        idx = np.flatnonzero(mask)
        states = np.empty((self.num_envs, self.batch.num_bodies, 13), np.float32)
        states[:] = self._initial_state
        if len(idx):
            rng = self._world_random(idx, streams.PURPOSE_RESET)
            states[idx] = self._reset_states(idx, rng)
            self._on_reset(idx, rng)
        return states

    def _finish_reset(self, mask, overrides):
        """The second half, once the batch has reset the worlds: per-world
        randomisation (a reset restored the scene's parameters), episode
        clocks and numbers."""
        idx = np.flatnonzero(mask)
        if len(idx):
            self._randomize(mask, idx, overrides)
        self._elapsed[mask] = 0
        self._episodes[mask] += np.uint64(1)

    def _randomize(self, mask, idx, overrides):
        ranges = {**self.randomization, **overrides}
        rng = self._world_random(idx, streams.PURPOSE_RANDOMIZATION)
        mask_u8 = mask.astype(np.uint8)
        n, nb = self.num_envs, len(self._dynamic)

        def per_world(values, shape):
            """[num_envs, ...] with the drawn rows at idx (others unread)."""
            full = np.ones((n, *shape), np.float32)
            full[idx] = values
            return full

        mass = ranges["mass_scale"]
        if mass is not None:
            scale = per_world(rng.uniform(mass[0], mass[1], (len(idx), nb)), (nb,))
            self.world_parameters["mass_scale"][mask] = scale[mask]
            for j, body in enumerate(self._dynamic):
                self.batch.set_mass_properties(
                    body, np.ascontiguousarray(self._masses[j] * scale[:, j]),
                    np.ascontiguousarray(self._inertias[j][None, :] * scale[:, j:j + 1]),
                    mask_u8)
        else:
            self.world_parameters["mass_scale"][mask] = 1.0
        damping = ranges["damping"]
        if damping is not None:
            values = per_world(rng.uniform(damping[0], damping[1], (len(idx), nb)), (nb,))
            self.world_parameters["damping"][mask] = values[mask]
            for j, body in enumerate(self._dynamic):
                column = np.ascontiguousarray(values[:, j])
                self.batch.set_damping(body, column, column, mask_u8)
        else:
            self.world_parameters["damping"][mask] = 0.0
        gravity = ranges["gravity_scale"]
        if gravity is not None:
            scale = per_world(rng.uniform(gravity[0], gravity[1], len(idx)), ())
            self.world_parameters["gravity_scale"][mask] = scale[mask]
            for j, body in enumerate(self._dynamic):
                self.batch.set_gravity_factor(
                    body, np.ascontiguousarray(self._gravity_factors[j] * scale), mask_u8)
        else:
            self.world_parameters["gravity_scale"][mask] = 1.0

    # ------------------------------------------------------------ task hooks

    def _make_scene(self):
        raise NotImplementedError

    def _observation_space(self):
        raise NotImplementedError

    def _action_space(self):
        raise NotImplementedError

    def _reset_states(self, idx, rng):
        """Initial body states [len(idx), bodies, 13] of the worlds idx."""
        raise NotImplementedError

    def _on_reset(self, idx, rng):
        """Per-episode task variables (targets) of the worlds idx."""

    def _actions(self, actions):
        raise NotImplementedError

    def _observe(self):
        raise NotImplementedError

    def _reward(self, actions):
        raise NotImplementedError

    def _terminated(self):
        return np.zeros(self.num_envs, np.bool_)

    def __repr__(self):
        shard = "" if self.comm is None else (
            f", worlds [{self.world_offset}, {self.world_offset + self.num_envs}) of "
            f"{self.global_num_envs} on rank {self.comm.Get_rank()}")
        return (f"{type(self).__name__}({self.env_id!r}, num_envs={self.num_envs}, "
                f"autoreset_mode={self.autoreset_mode.name}{shard})")
