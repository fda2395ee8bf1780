"""manyworlds.envs: Gymnasium 1.x's VectorEnv protocol (spaces, the three
autoreset modes, reset masks), seeding bit for bit, rewards against a
transcription of dm_control's formulas, health, randomisation.

Gymnasium is not installed here: these tests exercise the fallback spaces
and base class (manyworlds.envs._compat), not the gymnasium subclass path.
"""

import math

import numpy as np
import pytest

import manyworlds.envs as envs
from manyworlds.envs.vector import planar_states

N = 16
IDS = ["cartpole-balance", "cartpole-swingup", "pendulum-swingup", "acrobot-swingup",
       "reacher-2link", "ragdoll-pose", "hopper-forward", "quadruped-forward"]
OBS_SIZE = {"cartpole-balance": 5, "cartpole-swingup": 5, "pendulum-swingup": 3,
            "acrobot-swingup": 6, "reacher-2link": 10, "ragdoll-pose": 52,
            "hopper-forward": 11, "quadruped-forward": 54}
ACTION_SIZE = {"reacher-2link": 2, "ragdoll-pose": 4, "hopper-forward": 3,
               "quadruped-forward": 8}
# The walkers end an episode when unhealthy (Gymnasium's rule: fallen); the
# other tasks only on a broken world.
TERMINATING = {"hopper-forward", "quadruped-forward"}


def bits(a):
    a = np.ascontiguousarray(a)
    return a.view({4: np.uint32, 8: np.uint64, 1: np.uint8}[a.dtype.itemsize])


def same_bits(a, b):
    np.testing.assert_array_equal(bits(a), bits(b))


def random_actions(env, seed, steps):
    rng = np.random.default_rng(seed)
    shape = (env.num_envs, *env.single_action_space.shape)
    return rng.uniform(-1, 1, (steps, *shape)).astype(np.float32)


def test_ids():
    assert envs.ids() == IDS
    with pytest.raises(ValueError, match="unknown environment id 'nope'; valid: cartpole-balance"):
        envs.make("nope")
    with pytest.raises(TypeError, match="unknown option"):
        envs.make("cartpole-balance", num_envs=2, colour="red")
    with pytest.raises(ValueError, match="autoreset_mode"):
        envs.make("cartpole-balance", num_envs=2, autoreset_mode="sometimes")
    with pytest.raises(ValueError, match="mass_scale"):
        envs.make("cartpole-balance", num_envs=2, mass_scale=(2, 1))


@pytest.mark.parametrize("env_id", IDS)
def test_spaces_and_random_rollout(env_id):
    env = envs.make(env_id, num_envs=N)
    obs_size, action_size = OBS_SIZE[env_id], ACTION_SIZE.get(env_id, 1)
    assert env.num_envs == N
    assert env.single_observation_space.shape == (obs_size,)
    assert env.single_observation_space.dtype == np.float32
    assert env.observation_space.shape == (N, obs_size)
    assert env.single_action_space.shape == (action_size,)
    assert env.single_action_space.dtype == np.float32
    np.testing.assert_array_equal(env.single_action_space.low, -1.0)
    np.testing.assert_array_equal(env.single_action_space.high, 1.0)
    assert env.action_space.shape == (N, action_size)
    assert env.metadata["autoreset_mode"] == envs.AutoresetMode.NEXT_STEP
    obs, info = env.reset(seed=5)
    assert isinstance(info, dict)
    assert obs.shape == (N, obs_size) and obs.dtype == np.float32
    assert obs in env.observation_space
    assert all(row in env.single_observation_space for row in obs)
    env.action_space.seed(1)
    for _ in range(200):
        actions = env.action_space.sample()
        assert actions in env.action_space
        obs, reward, terminated, truncated, info = env.step(actions)
        assert obs.shape == (N, obs_size) and obs.dtype == np.float32
        assert reward.shape == (N,) and reward.dtype == np.float64
        assert terminated.shape == truncated.shape == (N,)
        assert terminated.dtype == truncated.dtype == np.bool_
        assert np.isfinite(obs).all() and np.isfinite(reward).all()
        assert obs in env.observation_space
        if env_id not in TERMINATING:
            assert not terminated.any()  # no task terminates but for health
    assert env.batch.unhealthy_world_count == 0
    env.close()


def rollout(env, actions, seed, reset_options=None):
    """Every output of reset then len(actions) steps; SAME_STEP's final
    observations as zeros where no world ended (so that rollouts of
    different world counts line up step by step)."""
    out = [env.reset(seed=seed, options=reset_options)[0]]
    for a in actions:
        obs, reward, terminated, truncated, info = env.step(a)
        out += [obs, reward, terminated, truncated]
        if env.autoreset_mode == envs.AutoresetMode.SAME_STEP:
            out += [info.get("final_obs", np.zeros_like(obs)),
                    info.get("_final_obs", np.zeros(env.num_envs, np.bool_))]
    return out


@pytest.mark.parametrize("env_id", IDS)
def test_seeding_reproduces_every_bit(env_id):
    options = dict(max_episode_steps=40, mass_scale=(0.8, 1.2), damping=(0.0, 0.1),
                   gravity_scale=(0.9, 1.1))
    actions = random_actions(envs.make(env_id, num_envs=N), 3, 100)
    first = rollout(envs.make(env_id, num_envs=N, **options), actions, seed=11)
    # Another environment object, and the same one reset again.
    env = envs.make(env_id, num_envs=N, **options)
    rollout(env, actions[:17], seed=99)
    second = rollout(env, actions, seed=11)
    assert len(first) == len(second)
    for a, b in zip(first, second):
        same_bits(a, b)
    other = rollout(envs.make(env_id, num_envs=N, **options), actions, seed=12)
    assert not np.array_equal(first[0], other[0])


def world_rows(out, rows):
    """The rows of every per-world output of rollout() (info masks too)."""
    return [a[rows] for a in out]


@pytest.mark.parametrize("env_id", IDS)
def test_a_world_does_not_depend_on_how_many_worlds_there_are(env_id):
    # World i's draws come from its own stream (envs/streams.py): keyed by
    # (seed, global world, episode), so worlds 0-4 of a 5-world and of a
    # 21-world environment are the same bits, across autoresets (NEXT_STEP
    # and SAME_STEP) and randomisation. This is what makes a sharded
    # environment (comm=) equal to one process.
    options = dict(max_episode_steps=13, mass_scale=(0.8, 1.2), damping=(0.0, 0.1),
                   gravity_scale=(0.9, 1.1))
    for mode in ("NEXT_STEP", "SAME_STEP"):
        small = envs.make(env_id, num_envs=5, autoreset_mode=mode, **options)
        large = envs.make(env_id, num_envs=21, autoreset_mode=mode, **options)
        actions = random_actions(large, 5, 40)
        a = rollout(small, actions[:, :5], seed=3)
        b = rollout(large, actions, seed=3)
        assert len(a) == len(b)
        for x, y in zip(a, world_rows(b, slice(0, 5))):
            same_bits(x, y)
        same_bits(small.world_parameters["mass_scale"],
                  large.world_parameters["mass_scale"][:5])


def test_world_streams_are_per_world():
    from manyworlds.envs import streams
    worlds = np.array([4, 9, 100, 7])
    r = streams.WorldRandom(123, worlds, [0, 2, 0, 1], streams.PURPOSE_RESET)
    first = r.uniform(-1.0, 1.0, (4, 3))
    subset = r.rows(np.array([False, True, False, True]))
    normal = subset.standard_normal(2)
    last = r.random(4)
    # World 7 (episode 1) alone: the same draws in the same order.
    alone = streams.WorldRandom(123, [7], [1], streams.PURPOSE_RESET)
    same_bits(alone.uniform(-1.0, 1.0, (1, 3)), first[3:])
    same_bits(alone.standard_normal(1), normal[1:])
    same_bits(alone.random(1), last[3:])
    # Another episode, purpose or key: other numbers.
    for key, episode, purpose in ((123, 2, streams.PURPOSE_RESET),
                                  (123, 1, streams.PURPOSE_RANDOMIZATION),
                                  (124, 1, streams.PURPOSE_RESET)):
        other = streams.WorldRandom(key, [7], [episode], purpose).uniform(-1.0, 1.0, (1, 3))
        assert not np.array_equal(other, first[3:])
    with pytest.raises(ValueError, match="first dimension must be the 4 worlds"):
        r.random((3, 2))
    # Uniform and normal: moments of 200000 draws within 5 standard errors
    # (mean 1/2 and variance 1/12; mean 0 and variance 1).
    many = streams.WorldRandom(1, np.arange(200000), np.zeros(200000), streams.PURPOSE_RESET)
    u, z = many.random(200000), many.standard_normal(200000)
    se = 1.0 / math.sqrt(200000)
    assert abs(u.mean() - 0.5) < 5 * se * math.sqrt(1 / 12)
    assert abs(u.var() - 1 / 12) < 5 * se * 0.0745  # sd of (u - 1/2)^2 is 0.0745
    assert abs(z.mean()) < 5 * se and abs(z.var() - 1.0) < 5 * se * math.sqrt(2)
    assert u.min() >= 0.0 and u.max() < 1.0


def test_shard_of_worlds_binding():
    import manyworlds
    assert manyworlds.shard_of_worlds(100, 0, 3) == (0, 32)
    assert manyworlds.shard_of_worlds(100, 2, 3) == (64, 36)
    assert manyworlds.shard_of_worlds(5, 1, 2) == (2, 3)  # fewer blocks than ranks
    with pytest.raises(ValueError, match="every rank needs at least one world"):
        manyworlds.shard_of_worlds(2, 0, 3)


def make_short(mode, steps=3, env_id="cartpole-balance"):
    return envs.make(env_id, num_envs=N, max_episode_steps=steps, autoreset_mode=mode)


def test_next_step_autoreset():
    actions = random_actions(make_short("NextStep"), 0, 5)
    env = make_short(envs.AutoresetMode.NEXT_STEP)
    env.reset(seed=3)
    for t in range(2):
        obs, reward, terminated, truncated, info = env.step(actions[t])
        assert not (terminated | truncated).any()
    obs3, reward3, terminated3, truncated3, _ = env.step(actions[2])
    assert truncated3.all() and not terminated3.any()
    assert (reward3 > 0).all()
    # The step after: reset observations, reward 0, not done, action ignored.
    obs4, reward4, terminated4, truncated4, info4 = env.step(np.full((N, 1), 1.0, np.float32))
    assert not (terminated4 | truncated4).any()
    np.testing.assert_array_equal(reward4, 0.0)
    assert "final_obs" not in info4
    # The same draws reset a DISABLED twin by hand: the same observations.
    twin = make_short(envs.AutoresetMode.DISABLED)
    twin.reset(seed=3)
    for t in range(3):
        twin_obs = twin.step(actions[t])[0]
    same_bits(twin_obs, obs3)
    reset_obs, _ = twin.reset(options={"reset_mask": np.ones(N, np.bool_)})
    same_bits(obs4, reset_obs)
    # A new episode runs again for max_episode_steps steps.
    for t in range(2):
        assert not env.step(actions[t])[3].any()
    assert env.step(actions[2])[3].all()


def test_next_step_resets_only_the_done_worlds():
    env = envs.make("cartpole-balance", num_envs=N)
    env.reset(seed=0)
    actions = np.zeros((N, 1), np.float32)
    env.step(actions)
    bad = actions.copy()
    bad[5] = np.nan  # world 5 becomes unhealthy: its episode ends
    obs, reward, terminated, truncated, info = env.step(bad)
    assert terminated[5] and terminated.sum() == 1 and not truncated.any()
    assert info["unhealthy"][5] and info["_unhealthy"].sum() == 1
    np.testing.assert_array_equal(obs[5], 0.0)
    assert reward[5] == 0.0
    before = obs.copy()
    obs, reward, terminated, truncated, info = env.step(actions)
    assert not terminated.any() and reward[5] == 0.0
    assert "unhealthy" not in info  # world 5 was reset, not flagged again
    assert np.isfinite(obs).all() and env.batch.unhealthy_world_count == 0
    assert abs(obs[5, 0]) <= 0.1 and obs[5, 1] > math.cos(0.035)  # a balance start
    assert not np.array_equal(obs[4], before[4])  # the others went on
    assert (reward[np.arange(N) != 5] > 0).all()
    # A world that breaks on a step on which others are reset: zeros, not NaN.
    bad = actions.copy()
    bad[6] = np.nan
    env.step(bad)
    env.step(bad)
    obs, reward, terminated, truncated, info = env.step(actions)
    assert not terminated[6]  # reset on this step
    bad[5] = np.nan
    env.step(bad)  # world 5 and 6 break
    bad[:] = 0.0
    bad[7] = np.nan
    obs, reward, terminated, truncated, info = env.step(bad)  # 5, 6 reset; 7 breaks
    np.testing.assert_array_equal(terminated, np.arange(N) == 7)
    np.testing.assert_array_equal(obs[7], 0.0)
    assert np.isfinite(obs).all()


def test_same_step_autoreset():
    actions = random_actions(make_short("NextStep"), 1, 4)
    reference = make_short("NextStep")
    reference.reset(seed=8)
    expected = [reference.step(a) for a in actions]
    env = make_short(envs.AutoresetMode.SAME_STEP)
    assert env.metadata["autoreset_mode"] == envs.AutoresetMode.SAME_STEP
    env.reset(seed=8)
    for t in range(2):
        obs, reward, terminated, truncated, info = env.step(actions[t])
        same_bits(obs, expected[t][0])
        assert "final_obs" not in info
    obs, reward, terminated, truncated, info = env.step(actions[2])
    assert truncated.all()
    same_bits(reward, expected[2][1])
    same_bits(info["final_obs"], expected[2][0])  # the last observation of the episode
    assert info["_final_obs"].dtype == np.bool_ and info["_final_obs"].all()
    assert info["final_info"] == {} and info["_final_info"].all()
    same_bits(obs, expected[3][0])  # already the next episode's first observation
    obs, reward, terminated, truncated, info = env.step(actions[3])
    assert not (terminated | truncated).any() and (reward > 0).all()


def test_same_step_final_obs_only_for_the_done_worlds():
    env = envs.make("cartpole-balance", num_envs=N, autoreset_mode="SameStep")
    env.reset(seed=0)
    actions = np.zeros((N, 1), np.float32)
    actions[3] = np.nan  # (an infinite action is clipped into [-1, 1], NaN stays NaN)
    obs, reward, terminated, truncated, info = env.step(actions)
    mask = np.arange(N) == 3
    np.testing.assert_array_equal(info["_final_obs"], mask)
    np.testing.assert_array_equal(info["final_obs"][~mask], 0.0)
    np.testing.assert_array_equal(terminated, mask)
    assert np.isfinite(obs).all()


def test_disabled_autoreset_with_reset_mask():
    env = make_short(envs.AutoresetMode.DISABLED, steps=2)
    assert env.metadata["autoreset_mode"].value == "Disabled"
    obs, _ = env.reset(seed=4)
    actions = np.zeros((N, 1), np.float32)
    env.step(actions)
    obs, reward, terminated, truncated, info = env.step(actions)
    assert truncated.all()
    assert "final_obs" not in info
    with pytest.raises(AssertionError, match="DISABLED"):
        env.step(actions)
    half = np.arange(N) < N // 2
    after, _ = env.reset(options={"reset_mask": half})
    same_bits(after[~half], obs[~half])  # not reset: their last observation
    assert not np.array_equal(after[half], obs[half])
    with pytest.raises(AssertionError):
        env.step(actions)  # the other half is still done
    env.reset(options={"reset_mask": ~half})
    obs, reward, terminated, truncated, info = env.step(actions)
    assert not (terminated | truncated).any()
    for bad in (half.astype(np.uint8), np.zeros(N, np.bool_), np.ones(N + 1, np.bool_)):
        with pytest.raises(ValueError, match="reset_mask"):
            env.reset(options={"reset_mask": bad})


def test_protocol_misuse():
    env = envs.make("reacher-2link", num_envs=N)
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros((N, 2), np.float32))
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions: expected shape \(16, 2\), got \(16, 1\)"):
        env.step(np.zeros((N, 1), np.float32))
    with pytest.raises(ValueError, match="options: unknown key"):
        env.reset(options={"speed": 2})


# ---- rewards, against a transcription of dm_control/utils/rewards.py and
# dm_control/suite/cartpole.py written here independently of the package.

def dm_tolerance(x, bounds=(0.0, 0.0), margin=0.0, sigmoid="gaussian", value_at_margin=0.1):
    x = np.asarray(x, np.float64)
    lower, upper = bounds
    in_bounds = np.logical_and(lower <= x, x <= upper)
    if margin == 0:
        return np.where(in_bounds, 1.0, 0.0)
    d = np.where(x < lower, lower - x, x - upper) / margin
    if sigmoid == "gaussian":
        scale = np.sqrt(-2 * np.log(value_at_margin))
        value = np.exp(-0.5 * (d * scale) ** 2)
    else:  # quadratic
        scale = np.sqrt(1 - value_at_margin)
        scaled = d * scale
        value = np.where(abs(scaled) < 1, 1 - scaled ** 2, 0.0)
    return np.where(in_bounds, 1.0, value)


def dm_cartpole_reward(cart_position, pole_cos, angular_vel, control):
    upright = (pole_cos + 1) / 2
    centered = (1 + dm_tolerance(cart_position, margin=2)) / 2
    small_control = (4 + dm_tolerance(control, margin=1, value_at_margin=0,
                                      sigmoid="quadratic")) / 5
    small_velocity = (1 + dm_tolerance(angular_vel, margin=5)) / 2
    return upright * small_control * small_velocity * centered


def test_tolerance_shapes():
    assert envs.tolerance(0.0, margin=2.0) == 1.0
    np.testing.assert_allclose(envs.tolerance(2.0, margin=2.0), 0.1)
    np.testing.assert_allclose(envs.tolerance(-1.0, margin=1.0, value_at_margin=0.0,
                                              sigmoid="quadratic"), 0.0)
    np.testing.assert_allclose(envs.tolerance(0.5, margin=1.0, value_at_margin=0.0,
                                              sigmoid="quadratic"), 0.75)
    np.testing.assert_array_equal(envs.tolerance([0.1, 0.3], bounds=(0, 0.2)), [1.0, 0.0])
    x = np.linspace(-4, 4, 101)
    np.testing.assert_allclose(envs.tolerance(x, bounds=(-1, 0.5), margin=1.5),
                               dm_tolerance(x, bounds=(-1, 0.5), margin=1.5))


def set_cartpole(env, x, angle, vx, omega):
    """Every world of a cartpole env to the given (arrays of) coordinates."""
    n = env.num_envs
    x, angle, vx, omega = (np.broadcast_to(np.asarray(v, np.float64), (n,)) for v in
                           (x, angle, vx, omega))
    zero = np.zeros(n)
    state = env.batch.get_state()
    state[:, 1] = planar_states(x, zero, zero, vx, zero, zero)
    state[:, 2] = planar_states(x + 0.5 * np.sin(angle), 0.5 * np.cos(angle), angle,
                                vx + 0.5 * np.cos(angle) * omega,
                                -0.5 * np.sin(angle) * omega, omega)
    env.batch.set_state(state)  # keeps per-world parameters (reset_to would not)
    env._read_state()


def test_cartpole_balance_reward_upright_and_hanging():
    env = envs.make("cartpole-balance", num_envs=N)
    env.reset(seed=0)
    set_cartpole(env, 0.0, 0.0, 0.0, 0.0)  # upright, centred, at rest
    obs, reward, *_ = env.step(np.zeros((N, 1), np.float32))
    np.testing.assert_allclose(reward, 1.0, atol=1e-6)
    np.testing.assert_allclose(obs[:, 1], 1.0, atol=1e-6)
    set_cartpole(env, 0.0, math.pi, 0.0, 0.0)  # hanging down
    obs, reward, *_ = env.step(np.zeros((N, 1), np.float32))
    np.testing.assert_allclose(reward, 0.0, atol=1e-6)
    np.testing.assert_allclose(obs[:, 1], -1.0, atol=1e-6)


def test_cartpole_reward_matches_dm_control_formula():
    env = envs.make("cartpole-swingup", num_envs=N)
    env.reset(seed=2)
    rng = np.random.default_rng(0)
    set_cartpole(env, rng.uniform(-1.5, 1.5, N), rng.uniform(-math.pi, math.pi, N),
                 rng.uniform(-2, 2, N), rng.uniform(-8, 8, N))
    for a in random_actions(env, 4, 20):
        obs, reward, *_ = env.step(a * 1.5)  # also beyond [-1, 1]: clipped like ctrlrange
        expected = dm_cartpole_reward(obs[:, 0].astype(np.float64),
                                      obs[:, 1].astype(np.float64),
                                      obs[:, 4].astype(np.float64), np.clip(a[:, 0] * 1.5, -1, 1))
        # (The env takes the cosine of the float32 angle in float64; obs hold float32 cosines.)
        np.testing.assert_allclose(reward, expected, rtol=1e-4, atol=1e-7)
        assert np.all(np.abs(obs[:, 0]) <= 1.8 + 1e-3)  # the rail's limits


def test_cartpole_balance_is_balanced_by_a_pd_controller():
    """A physical sanity check: a hand-tuned PD law on (x, angle, rates) keeps
    every pole up for the whole 1000-step episode (return ~1000, the
    maximum), far above random actions."""
    env = envs.make("cartpole-balance", num_envs=N)
    obs, _ = env.reset(seed=0)
    returns = np.zeros(N)
    for _ in range(1000):
        angle = np.arctan2(obs[:, 2], obs[:, 1])
        u = 1.0 * obs[:, 0] + 1.5 * obs[:, 3] + 8.0 * angle + 1.5 * obs[:, 4]
        obs, reward, terminated, truncated, _ = env.step(u[:, None].astype(np.float32))
        returns += reward
    assert truncated.all()
    assert returns.min() > 990
    env.reset(seed=0)
    env.action_space.seed(0)
    random_returns = sum(env.step(env.action_space.sample())[1] for _ in range(1000))
    assert random_returns.mean() < 600


def test_cartpole_starts():
    balance = envs.make("cartpole-balance", num_envs=256)
    obs, _ = balance.reset(seed=1)
    assert np.all(np.abs(obs[:, 0]) <= 0.1)
    assert np.all(np.abs(np.arctan2(obs[:, 2], obs[:, 1])) <= 0.034 + 1e-6)
    swingup = envs.make("cartpole-swingup", num_envs=256)
    obs, _ = swingup.reset(seed=1)
    assert np.all(obs[:, 1] < -0.99)  # hanging
    assert np.all(np.abs(obs[:, 0]) < 0.06)


def test_pendulum_acrobot_reacher_rewards():
    pendulum = envs.make("pendulum-swingup", num_envs=N)
    pendulum.reset(seed=0)
    angles = np.linspace(-0.3, 0.3, N)  # sparse: 1 within 8 degrees of upright, else 0
    zero = np.zeros(N)
    state = pendulum.batch.get_state()
    state[:, 1] = planar_states(0.5 * np.sin(angles), 0.5 * np.cos(angles), angles, zero, zero,
                                zero)
    pendulum.batch.set_state(state)
    _, reward, *_ = pendulum.step(np.zeros((N, 1), np.float32))
    cos = np.cos(pendulum._joints[:, 0].astype(np.float64))
    np.testing.assert_array_equal(reward, (cos >= math.cos(math.radians(8))).astype(float))
    assert 0 < reward.sum() < N

    acrobot = envs.make("acrobot-swingup", num_envs=N)
    acrobot.reset(seed=0)
    state = acrobot.batch.get_state()
    acrobot.batch.reset(None)  # the scene's pose: both links straight up
    _, reward, *_ = acrobot.step(np.zeros((N, 1), np.float32))
    np.testing.assert_allclose(acrobot.tip_to_target(), 0.0, atol=1e-4)
    np.testing.assert_allclose(reward, 1.0)
    acrobot.batch.reset_to(None, state)
    obs, reward, *_ = acrobot.step(np.zeros((N, 1), np.float32))
    np.testing.assert_allclose(
        reward, dm_tolerance(acrobot.tip_to_target(), bounds=(0, 0.2), margin=1))
    # dm_control's order: sines (xz) of both links, then cosines (zz).
    th1, th12 = np.arctan2(obs[:, 0], obs[:, 2]), np.arctan2(obs[:, 1], obs[:, 3])
    tip = np.stack([np.sin(th1) + np.sin(th12), 2 + np.cos(th1) + np.cos(th12)], 1)
    np.testing.assert_allclose(np.hypot(tip[:, 0], tip[:, 1] - 4), acrobot.tip_to_target(),
                               atol=1e-5)

    reacher = envs.make("reacher-2link", num_envs=N)
    obs, _ = reacher.reset(seed=0)
    assert np.all(np.hypot(obs[:, 4], obs[:, 5]) < 0.2)
    a = random_actions(reacher, 0, 1)[0]
    obs, reward, *_ = reacher.step(a)
    expected = -np.hypot(obs[:, 8], obs[:, 9]) - 0.1 * np.sum(a.astype(np.float64) ** 2, 1)
    np.testing.assert_allclose(reward, expected, rtol=1e-5, atol=1e-6)


def test_ragdoll_pose_tracks_its_targets():
    env = envs.make("ragdoll-pose", num_envs=N)
    obs, _ = env.reset(seed=0)
    target = obs[:, -4:]
    low, high = env.limits[:, 0], env.limits[:, 1]
    assert np.all((target >= low) & (target <= high))
    # The action that commands exactly the target pose.
    actions = (2 * (target - low) / (high - low) - 1).astype(np.float32)
    rewards = [env.step(actions)[1] for _ in range(120)]
    assert np.all(rewards[-1] > 0.95) and np.all(rewards[-1] > rewards[0] - 1e-9)


def test_randomisation():
    env = envs.make("pendulum-swingup", num_envs=N, gravity_scale=(0.0, 0.0))
    obs, _ = env.reset(seed=0)
    for _ in range(10):
        after = env.step(np.zeros((N, 1), np.float32))[0]
    np.testing.assert_allclose(after, obs, atol=1e-5)  # no gravity: it stays where it started
    env = envs.make("cartpole-balance", num_envs=N, mass_scale=(0.5, 2.0), damping=(0.1, 0.2))
    env.reset(seed=0)
    scale, damping = env.world_parameters["mass_scale"], env.world_parameters["damping"]
    assert scale.shape == (N, 2) and np.all((scale >= 0.5) & (scale <= 2.0))
    assert np.all((damping >= 0.1) & (damping <= 0.2))
    assert len(np.unique(scale)) == scale.size
    # A reset option overrides make()'s range for that reset.
    env.reset(options={"mass_scale": (1.0, 1.0)})
    np.testing.assert_array_equal(env.world_parameters["mass_scale"], 1.0)
    # Without gravity, a heavier pendulum turns slower under the same torque:
    # angular velocity after one step ~ 1 / mass scale.
    env = envs.make("pendulum-swingup", num_envs=N, mass_scale=(0.5, 2.0),
                    gravity_scale=(0.0, 0.0))
    env.reset(seed=1)
    obs = env.step(np.ones((N, 1), np.float32))[0]
    scale = env.world_parameters["mass_scale"][:, 0]
    np.testing.assert_allclose(obs[:, 2] * scale, obs[0, 2] * scale[0], rtol=1e-3)
    assert len(np.unique(obs[:, 2])) == N


def test_fallback_spaces():
    box = envs.Box(-1.0, 2.0, (3,), np.float32)
    box.seed(0)
    sample = box.sample()
    assert sample.shape == (3,) and sample.dtype == np.float32 and sample in box
    assert np.array([3.0, 0, 0], np.float32) not in box
    assert np.zeros(2, np.float32) not in box
    again = envs.Box(-1.0, 2.0, (3,), np.float32)
    again.seed(0)
    same_bits(again.sample(), sample)
    unbounded = envs.Box(-np.inf, np.inf, (4,))
    assert np.isfinite(unbounded.sample()).all()
    d = envs.Discrete(3)
    d.seed(0)
    assert all(d.sample() in d for _ in range(20))
    assert d.n == 3 and 3 not in d and -1 not in d and 2 in d
    from manyworlds.envs._compat import batch_space
    batched = batch_space(d, 4)
    assert isinstance(batched, envs.MultiDiscrete) and batched.shape == (4,)
    assert batched.sample() in batched
    assert batch_space(box, 5).shape == (5, 3)
    modes = {m.name: m.value for m in envs.AutoresetMode}
    assert modes == {"NEXT_STEP": "NextStep", "SAME_STEP": "SameStep", "DISABLED": "Disabled"}
    assert envs.HAVE_GYMNASIUM is False  # what these tests cover: the fallback path


# ---- the gymnasium path, wiring only: gymnasium cannot be installed here, so
# a stub package with its module layout (gymnasium.spaces, gymnasium.vector
# with VectorEnv and AutoresetMode, gymnasium.vector.utils.batch_space)
# checks that manyworlds.envs picks it up. It does not check Gymnasium's own
# behaviour.

STUB = {
    "gymnasium/__init__.py": "from . import spaces, vector\n",
    # Self-contained: manyworlds.envs._compat is still being imported when
    # it imports gymnasium.
    "gymnasium/spaces.py": (
        "import numpy as np\n"
        "class Box:\n"
        "    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):\n"
        "        self.shape = tuple(shape)\n"
        "        self.dtype = np.dtype(dtype)\n"
        "        self.low = np.broadcast_to(np.asarray(low, dtype), self.shape).copy()\n"
        "        self.high = np.broadcast_to(np.asarray(high, dtype), self.shape).copy()\n"
        "class Discrete:\n"
        "    def __init__(self, n, seed=None, start=0):\n"
        "        self.n, self.start = n, start\n"),
    "gymnasium/vector/__init__.py": (
        "import enum\n"
        "class AutoresetMode(enum.Enum):\n"
        "    NEXT_STEP = 'NextStep'\n    SAME_STEP = 'SameStep'\n    DISABLED = 'Disabled'\n"
        "class VectorEnv:\n"
        "    metadata = {}\n    closed = False\n    _np_random = None\n"
        "    @property\n"
        "    def np_random(self):\n"
        "        return self._np_random\n"
        "    def close(self):\n        self.closed = True\n"),
    "gymnasium/vector/utils.py": (
        "from ..spaces import Box\n"
        "def batch_space(space, n):\n"
        "    return Box(space.low, space.high, (n, *space.shape), space.dtype)\n"),
}

STUB_CHECK = """
import numpy as np, gymnasium, manyworlds.envs as envs
assert envs.HAVE_GYMNASIUM
env = envs.make("cartpole-swingup", num_envs=4, autoreset_mode="SameStep", max_episode_steps=2)
assert isinstance(env, gymnasium.vector.VectorEnv)
assert envs.AutoresetMode is gymnasium.vector.AutoresetMode
assert env.metadata["autoreset_mode"] is gymnasium.vector.AutoresetMode.SAME_STEP
assert type(env.single_observation_space) is gymnasium.spaces.Box
assert type(env.action_space) is gymnasium.spaces.Box and env.action_space.shape == (4, 1)
obs, info = env.reset(seed=0)
env.step(np.zeros((4, 1), np.float32))
obs, reward, terminated, truncated, info = env.step(np.zeros((4, 1), np.float32))
assert truncated.all() and info["_final_obs"].all()
env.close()
print("stub ok")
"""


def test_gymnasium_path_wiring_with_a_stub(tmp_path):
    import os
    import subprocess
    import sys
    for name, text in STUB.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(tmp_path)] + sys.path)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    result = subprocess.run([sys.executable, "-c", STUB_CHECK], env=env, capture_output=True,
                            text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert "stub ok" in result.stdout


def test_hopper_forward_rewards_speed_and_ends_when_fallen():
    """Gymnasium's Hopper-v5 reward from the torso's state (read here from the
    batch, not from the environment's observation): x velocity + 1 - 1e-3
    |u|^2; an episode ends once the torso is below 0.7 m or tilted past
    0.2 rad. Held at u = 0 (straight legs) it stands for the whole rollout."""
    env = envs.make("hopper-forward", num_envs=N)
    env.reset(seed=4)
    still = np.zeros((N, 3), np.float32)
    for _ in range(100):
        obs, reward, terminated, _, _ = env.step(still)
        assert not terminated.any()
    torso = env.batch.get_state()[:, 1]
    np.testing.assert_allclose(reward, torso[:, 7] + 1.0, rtol=1e-6, atol=1e-6)
    assert np.all(obs[:, 0] > 1.15)  # the torso's centre stays up (1.21-1.25 m)
    actions = np.full((N, 3), -1.0, np.float32)  # every hinge to its lower limit
    ended = np.zeros(N, np.bool_)
    for _ in range(200):
        obs, reward, terminated, _, _ = env.step(actions)
        torso = env.batch.get_state()[:, 1]
        # Where not just reset, the reward is computed from the step's state.
        live = ~terminated & ~ended
        np.testing.assert_allclose(reward[live], torso[live, 7] + 1.0 - 3e-3, rtol=1e-5,
                                   atol=1e-5)
        angle = 2 * np.arctan2(torso[:, 5], torso[:, 6])
        fallen = (torso[:, 1] <= 0.7) | (np.abs(angle) >= 0.2)
        np.testing.assert_array_equal(terminated & ~ended, fallen & ~ended)
        ended |= terminated
    assert ended.all(), "a hopper folded to its limits falls"


def test_quadruped_forward_observes_the_ground_forces():
    """Ant-v5's observation ends with the contact force on every body from the
    ground (get_contacts of the ground's 9 slots); standing still, those
    carry the whole weight; the reward is x velocity + 1 - 0.5 |u|^2 - 5e-4
    |clip(f, -1, 1)|^2."""
    env = envs.make("quadruped-forward", num_envs=N)
    env.reset(seed=6)
    still = np.zeros((N, 8), np.float32)
    for _ in range(40):  # 2 s
        obs, reward, terminated, _, _ = env.step(still)
        assert not terminated.any()
    forces = obs[:, 27:].reshape(N, 9, 3)
    contacts = env.batch.get_contacts()
    ground = [s for s in range(env.batch.num_contact_slots) if env.batch.contact_slot(s)[0] == 0]
    assert len(ground) == 9
    np.testing.assert_array_equal(forces, contacts[:, ground, 2:5])
    weight = 9.81 * sum(b.mass for b in env.scene.bodies[1:])
    # At rest the ground carries the weight (the last substep's impulses; the
    # motors hold the legs, so 1 % for what is still settling).
    np.testing.assert_allclose(forces[:, :, 1].sum(axis=1), weight, rtol=1e-2)
    clipped = np.clip(forces.astype(np.float64), -1, 1)
    vx = env.batch.get_state()[:, 1, 7]
    np.testing.assert_allclose(reward, vx + 1.0 - 5e-4 * np.sum(clipped ** 2, axis=(1, 2)),
                               rtol=1e-6, atol=1e-6)
