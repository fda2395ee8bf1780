"""Locomotion: the contact scenes hopper and quadruped (docs/contacts.md,
docs/scenes.md) as Gymnasium's Hopper-v5 and Ant-v5 tasks: run forward along
+X, stay healthy, spend little control.

What differs from Gymnasium's: the bodies are the same capsules (MuJoCo's
models rebuilt Y-up, masses equal), but the actions are the position targets
of hinge motors (mapped linearly from [-1, 1] onto each hinge's limits), not
torques (u = 0 holds the rest pose, -1 and 1 the limits), and the contacts are
Jolt's hard ones. Observations are built from
the same quantities in our frame (Y up; angles about our hinge axes).
"""

import numpy as np

from .. import _core
from .vector import ManyWorldsVectorEnv
from .control import _box, _actions


def _torso_angle_about_z(quaternions):
    """Rotation angle about +Z of quaternions (x, y, z, w) that turn only
    about Z (the hopper's torso): 2 atan2(z, w), in (-pi, pi]."""
    angle = 2.0 * np.arctan2(quaternions[:, 2], quaternions[:, 3])
    return np.where(angle > np.pi, angle - 2.0 * np.pi,
                    np.where(angle <= -np.pi, angle + 2.0 * np.pi, angle))


class _LocomotionEnv(ManyWorldsVectorEnv):
    """Shared by the walkers: motor targets from the actions, the torso's
    state and the hinges' joint coordinates for observations, reward
    forward_weight * vx + healthy_reward - ctrl_cost_weight * |u|^2."""

    TORSO = 1
    needs_state = True
    scene_id = None
    forward_reward_weight = 1.0
    healthy_reward = 1.0
    ctrl_cost_weight = None
    reset_noise_scale = None

    def __init__(self, num_envs, **options):
        super().__init__(num_envs, **options)
        # Each hinge's angle and angular velocity in the joint coordinates
        # (hinge: angle, unwrapped angle, angular velocity).
        offsets = np.cumsum([0] + [self.batch.joint_coordinate_count(c)
                                   for c in range(self.batch.num_constraints)])
        self._angle_columns = np.array([offsets[c] for c in self.motors])
        self._rate_columns = self._angle_columns + 2
        self._targets = np.zeros((len(self.motors), self.num_envs), np.float32)
        self._control_cost = np.zeros(self.num_envs)

    def _make_scene(self):
        # The motors (every hinge with a position motor) and their limits,
        # which the spaces need before the batch exists.
        scene = _core.make_scene(self.scene_id)
        constraints = scene.constraints
        self.motors = [c for c in range(scene.num_constraints)
                       if isinstance(constraints[c], _core.HingeConstraintSettings)
                       and constraints[c].motor_state == _core.MotorState.POSITION]
        self.limits = np.array([[constraints[c].limits_min, constraints[c].limits_max]
                                for c in self.motors], np.float32)
        return scene

    def _action_space(self):
        return _actions(len(self.motors))

    def _reset_states(self, idx, rng):
        # Gymnasium adds noise to every joint position and velocity; here the
        # velocities of every dynamic body get it (the joints, already
        # assembled, project away what they do not allow in the first step).
        states = np.array(np.broadcast_to(self._initial_state,
                                          (len(idx), *self._initial_state.shape)))
        noise = self.reset_noise_scale * self._reset_noise(rng, (len(idx), len(self._dynamic), 6))
        states[:, self._dynamic, 7:13] += noise.astype(np.float32)
        return states

    def _actions(self, actions):
        # u = 0 holds the scene's rest pose (every hinge at 0); u in [-1, 0]
        # spans [low, 0] and [0, 1] spans [0, high] (both walkers' limits
        # contain 0; the hopper's thigh and leg bend one way only).
        low, high = self.limits[:, 0], self.limits[:, 1]
        self._targets[:] = np.where(actions >= 0.0, actions * high, -actions * low).T
        self._control_cost = self.ctrl_cost_weight * np.sum(
            np.square(actions, dtype=np.float64), axis=1)
        return {"target_positions": {c: self._targets[i] for i, c in enumerate(self.motors)}}

    def torso(self):
        """The torso's state rows [W, 13]: position, rotation (x, y, z, w),
        linear and angular velocity."""
        return self._state[:, self.TORSO]

    def forward_velocity(self):
        """The torso's velocity along +X (m/s), [W]."""
        return self.torso()[:, 7].astype(np.float64)

    def is_healthy(self):
        raise NotImplementedError

    def _terminated(self):
        return ~self.is_healthy()

    def _reward(self, actions):
        return (self.forward_reward_weight * self.forward_velocity() + self.healthy_reward
                - self._control_cost - self._contact_cost())

    def _contact_cost(self):
        return 0.0


class HopperForwardEnv(_LocomotionEnv):
    """hopper-forward: Gymnasium's Hopper-v5 on the `hopper` contact scene.

    Action u in [-1, 1]^3: the position targets of the thigh, leg and foot
    hinge motors (at most 200 N m each): u = 0 the straight rest pose, -1 and
    1 the hinge's limits (the thigh and leg bend one way: u > 0 holds them
    straight). Step
    0.008 s (Gymnasium's 4 x 0.002 s), 1000 steps. Observation (11, as
    Hopper-v5's): torso height and angle about Z, the 3 hinge angles, torso
    velocity x, y and angular velocity about Z, the 3 hinge rates, the
    velocities clipped to [-10, 10]. Reward: torso x velocity + 1 (healthy)
    - 1e-3 |u|^2. Terminated when unhealthy: torso height <= 0.7 m, torso
    angle beyond +-0.2 rad, or any observation beyond +-100. Reset: the
    scene's pose, every body's velocity plus U(-0.005, 0.005) per component.
    """

    env_id = "hopper-forward"
    scene_id = "hopper"
    default_max_episode_steps = 1000
    ctrl_cost_weight = 1e-3
    reset_noise_scale = 5e-3

    def __init__(self, num_envs, **options):
        self.step_settings = _core.StepSettings(delta_time=0.008)
        super().__init__(num_envs, **options)

    def _reset_noise(self, rng, shape):
        return rng.uniform(-1.0, 1.0, shape)

    def _observation_space(self):
        return _box(11)

    def _observe(self):
        torso = self.torso()
        obs = np.empty((self.num_envs, 11), np.float32)
        obs[:, 0] = torso[:, 1]
        obs[:, 1] = _torso_angle_about_z(torso[:, 3:7])
        obs[:, 2:5] = self._joints[:, self._angle_columns]
        obs[:, 5] = torso[:, 7]
        obs[:, 6] = torso[:, 8]
        obs[:, 7] = torso[:, 12]
        obs[:, 8:11] = self._joints[:, self._rate_columns]
        obs[:, 5:11] = np.clip(obs[:, 5:11], -10.0, 10.0)
        return obs

    def is_healthy(self):
        """Gymnasium's Hopper: torso above 0.7 m, within 0.2 rad of upright,
        every observed quantity within +-100, [W]."""
        obs = self._observe()
        return ((obs[:, 0] > 0.7) & (np.abs(obs[:, 1]) < 0.2)
                & np.all(np.abs(obs[:, 2:]) < 100.0, axis=1))


class QuadrupedForwardEnv(_LocomotionEnv):
    """quadruped-forward: Gymnasium's Ant-v5 on the `quadruped` contact scene.

    Action u in [-1, 1]^8: the position targets of the 8 hinge motors (hip,
    knee per leg; at most 150 N m each): u = 0 the rest pose, -1 and 1 the
    hinge's limits. Step
    0.05 s in 3 substeps (Gymnasium's 5 x 0.01 s), 1000 steps. Observation
    (54): torso height, rotation (x, y, z, w), the 8 hinge angles, torso
    linear and angular velocity, the 8 hinge rates, then the contact force
    on each of the 9 bodies from the ground (N, world; Ant-v5's cfrc_ext,
    as get_contacts gives it). Reward: torso x velocity + 1 (healthy)
    - 0.5 |u|^2 - 5e-4 |clip(contact forces, -1, 1)|^2. Terminated when
    unhealthy: torso height outside [0.2, 1.0] m or a non-finite state.
    Reset: the scene's pose, every body's velocity plus 0.1 N(0, 1) per
    component.
    """

    env_id = "quadruped-forward"
    scene_id = "quadruped"
    default_max_episode_steps = 1000
    ctrl_cost_weight = 0.5
    contact_cost_weight = 5e-4
    reset_noise_scale = 0.1

    def __init__(self, num_envs, **options):
        self.step_settings = _core.StepSettings(delta_time=0.05, substeps=3)
        super().__init__(num_envs, **options)
        # The ground's slots (body 1 = the ground), one per other body.
        self._ground_slots = [s for s in range(self.batch.num_contact_slots)
                              if self.batch.contact_slot(s)[0] == 0]
        self._contacts = np.zeros((self.num_envs, self.batch.num_contact_slots, 8), np.float32)

    def _reset_noise(self, rng, shape):
        return rng.standard_normal(shape)

    def _observation_space(self):
        return _box(27 + 3 * 9)

    def _read_state(self):
        super()._read_state()
        self.batch.get_contacts(out=self._contacts)

    def _step_batch(self, actions, reset_mask, reset_states):
        super()._step_batch(actions, reset_mask, reset_states)
        # Reset worlds read zeros: no contact yet, as after a separate reset.
        self.batch.get_contacts(out=self._contacts)

    def contact_forces(self):
        """The ground's force on each body, [W, 9 slots, 3] (N, world)."""
        return self._contacts[:, self._ground_slots, 2:5]

    def _observe(self):
        torso = self.torso()
        # Height and rotation (not the position along the ground, as Ant-v5).
        return np.concatenate([
            torso[:, [1, 3, 4, 5, 6]], self._joints[:, self._angle_columns], torso[:, 7:13],
            self._joints[:, self._rate_columns],
            self.contact_forces().reshape(self.num_envs, -1)], axis=1).astype(np.float32)

    def _contact_cost(self):
        clipped = np.clip(self.contact_forces().astype(np.float64), -1.0, 1.0)
        return self.contact_cost_weight * np.sum(np.square(clipped), axis=(1, 2))

    def is_healthy(self):
        """Gymnasium's Ant: torso height in [0.2, 1.0] m and a finite state, [W]."""
        height = self.torso()[:, 1]
        return ((height >= 0.2) & (height <= 1.0)
                & np.all(np.isfinite(self._state.reshape(self.num_envs, -1)), axis=1))
