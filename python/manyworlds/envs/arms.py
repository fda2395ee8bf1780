"""A planar reacher (Gymnasium's Reacher-v5 task) and the ragdoll holding a
target pose with its motors."""

import numpy as np

from .. import _core
from .control import _actions, _body, _box, _hinge, _static
from .vector import ManyWorldsVectorEnv, planar_states, rotate


class ReacherEnv(ManyWorldsVectorEnv):
    """reacher-2link: Gymnasium Reacher-v5's task on a 2-link planar arm.

    Links 0.1 m and 0.11 m (uniform rods of 0.5 kg each), lying on a table
    (gravity factor 0), shoulder at the origin; action u in [-1, 1]^2 are
    torques 0.2 u N m at the shoulder and the elbow (joint damping 0.02 N m
    s, explicit). Step 0.02 s in two substeps of 0.01 s (Reacher's
    frame_skip 2), 50 steps. Per episode: joint angles uniform in
    [-0.1, 0.1], rates in [-0.005, 0.005], a target uniform in the disc of
    radius 0.2 m (Reacher's rejection sampling). Observation (Reacher-v5's
    10): [cos q1, cos q2, sin q1, sin q2, target x, target y, q1 dot, q2 dot,
    fingertip - target x, y]; reward -|fingertip - target| - 0.1 |u|^2
    (Reacher-v5's reward_dist_weight 1, reward_control_weight 0.1).
    Angle 0 points the link along +Y; angles turn about -Z.
    """

    env_id = "reacher-2link"
    UPPER, LOWER = 1, 2
    LINK1, LINK2 = 0.1, 0.11
    MASS = 0.5
    GEAR = 0.2
    DAMPING = 0.02
    CONTROL_WEIGHT = 0.1
    TARGET_RADIUS = 0.2
    default_max_episode_steps = 50

    def __init__(self, num_envs, **options):
        self.step_settings = _core.StepSettings(delta_time=0.02, substeps=2)
        super().__init__(num_envs, **options)
        self._upper_torque = np.zeros((self.num_envs, 3), np.float32)
        self._lower_torque = np.zeros((self.num_envs, 3), np.float32)
        self.target = np.zeros((self.num_envs, 2), np.float32)

    def _make_scene(self):
        scene = _core.Scene()
        scene.add_body(_static())
        for name, length, base in (("arm", self.LINK1, 0.0),
                                   ("hand", self.LINK2, self.LINK1)):
            across = self.MASS * length ** 2 / 12.0
            scene.add_body(_body(name, self.MASS, (across, 0.01 * across, across),
                                 (0.0, base + 0.5 * length, 0.0), gravity_factor=0.0))
        scene.add_constraint(_hinge("joint0", 0, 1, (0.0, 0.0, 0.0)))
        scene.add_constraint(_hinge("joint1", 1, 2, (0.0, self.LINK1, 0.0)))
        return scene

    def _observation_space(self):
        return _box(10)

    def _action_space(self):
        return _actions(2)

    def _reset_states(self, idx, rng):
        n = len(idx)
        q = rng.uniform(-0.1, 0.1, (n, 2))
        qd = rng.uniform(-0.005, 0.005, (n, 2))
        th1, th12 = q[:, 0], q[:, 0] + q[:, 1]
        w1, w12 = qd[:, 0], qd[:, 0] + qd[:, 1]
        ux, uy = rotate(th1, 0.0, 0.5 * self.LINK1)
        ex, ey = rotate(th1, 0.0, self.LINK1)
        lx, ly = rotate(th12, 0.0, 0.5 * self.LINK2)
        # Velocities of the centres of mass: d/dt rotate(th, 0, r) = w * (r cos, -r sin).
        states = np.empty((n, 3, 13), np.float32)
        states[:, 0] = self._initial_state[0]
        states[:, self.UPPER] = planar_states(ux, uy, th1, w1 * uy, -w1 * ux, w1)
        states[:, self.LOWER] = planar_states(ex + lx, ey + ly, th12, w1 * ey + w12 * ly,
                                              -w1 * ex - w12 * lx, w12)
        return states

    def _on_reset(self, idx, rng):
        # Reacher's goal: uniform in [-0.2, 0.2]^2 until inside the disc,
        # done for all at once (the rejected worlds redraw from their own
        # streams: rng.rows).
        goal = rng.uniform(-self.TARGET_RADIUS, self.TARGET_RADIUS, (len(idx), 2))
        outside = np.hypot(goal[:, 0], goal[:, 1]) >= self.TARGET_RADIUS
        while outside.any():
            goal[outside] = rng.rows(outside).uniform(-self.TARGET_RADIUS, self.TARGET_RADIUS,
                                                      (int(outside.sum()), 2))
            outside = np.hypot(goal[:, 0], goal[:, 1]) >= self.TARGET_RADIUS
        self.target[idx] = goal

    def _actions(self, actions):
        q = self._joints
        shoulder = self.GEAR * actions[:, 0] - self.DAMPING * q[:, 2]
        elbow = self.GEAR * actions[:, 1] - self.DAMPING * q[:, 5]
        # One [W, 3] write per link (the whole-batch set_torques form checks
        # every body of every world and costs more).
        self._upper_torque[:, 2] = -(shoulder - elbow)  # about the hinges' -Z axis
        self._lower_torque[:, 2] = -elbow
        return {"body_torques": {self.UPPER: self._upper_torque, self.LOWER: self._lower_torque}}

    def fingertip(self):
        """[W, 2] fingertip position (m) from the joint angles."""
        q = self._joints.astype(np.float64)
        th1, th12 = q[:, 0], q[:, 0] + q[:, 3]
        ex, ey = rotate(th1, 0.0, self.LINK1)
        hx, hy = rotate(th12, 0.0, self.LINK2)
        return np.stack([ex + hx, ey + hy], axis=1)

    def _observe(self):
        q = self._joints
        obs = np.empty((self.num_envs, 10), np.float32)
        obs[:, 0], obs[:, 1] = np.cos(q[:, 0]), np.cos(q[:, 3])
        obs[:, 2], obs[:, 3] = np.sin(q[:, 0]), np.sin(q[:, 3])
        obs[:, 4:6] = self.target
        obs[:, 6], obs[:, 7] = q[:, 2], q[:, 5]
        obs[:, 8:10] = self.fingertip() - self.target
        return obs

    def _reward(self, actions):
        d = self.fingertip() - self.target
        return (-np.hypot(d[:, 0], d[:, 1])
                - self.CONTROL_WEIGHT * np.sum(np.square(actions, dtype=np.float64), axis=1))


class RagdollPoseEnv(ManyWorldsVectorEnv):
    """ragdoll-pose: the reference ragdoll (make_scene("ragdoll"): 11 bodies
    floating without gravity, swing-twist waist, neck, shoulders and hips,
    position-motor hinges at the elbows and knees) holding a target pose.

    Action u in [-1, 1]^4: the motors' position targets (left elbow, left
    knee, right elbow, right knee), mapped linearly onto each hinge's limits
    (elbows [-2.5, 0], knees [0, 2.5] rad). Per episode a target pose is
    drawn uniformly within the same limits. Step 1/60 s (StepSettings'
    defaults), 200 steps. Observation: every constraint's joint coordinates
    (get_joint_coordinates(): 6 swing-twist joints x 6, 4 hinges x 3; 48)
    then the 4 target angles (52). Reward exp(-sum of the 4 squared angle
    errors (rad^2)); no termination but health.
    """

    env_id = "ragdoll-pose"
    MOTORS = (_core.reference_scene.LEFT_ELBOW, _core.reference_scene.LEFT_KNEE,
              _core.reference_scene.RIGHT_ELBOW, _core.reference_scene.RIGHT_KNEE)
    default_max_episode_steps = 200

    def __init__(self, num_envs, **options):
        self.step_settings = _core.StepSettings()
        super().__init__(num_envs, **options)
        constraints = self.scene.constraints
        self.limits = np.array([[constraints[c].limits_min, constraints[c].limits_max]
                                for c in self.MOTORS], np.float32)
        self.target_pose = np.zeros((self.num_envs, len(self.MOTORS)), np.float32)
        # Column of each motor's hinge angle in the joint-coordinate array.
        offsets = np.cumsum([0] + [self.batch.joint_coordinate_count(c)
                                   for c in range(self.batch.num_constraints)])
        self._angle_columns = np.array([offsets[c] for c in self.MOTORS])
        self._targets = np.zeros((len(self.MOTORS), self.num_envs), np.float32)

    def _make_scene(self):
        return _core.make_scene("ragdoll")

    def _observation_space(self):
        return _box(self.batch.joint_coordinates_per_world + len(self.MOTORS))

    def _action_space(self):
        return _actions(len(self.MOTORS))

    def _reset_states(self, idx, rng):
        return np.broadcast_to(self._initial_state, (len(idx), *self._initial_state.shape))

    def _on_reset(self, idx, rng):
        u = rng.uniform(0.0, 1.0, (len(idx), len(self.MOTORS)))
        self.target_pose[idx] = self.limits[:, 0] + u * (self.limits[:, 1] - self.limits[:, 0])

    def _actions(self, actions):
        low, high = self.limits[:, 0], self.limits[:, 1]
        self._targets[:] = (low + 0.5 * (actions + 1.0) * (high - low)).T
        # One [W] array per motor, never a loop over worlds.
        return {"target_positions": {c: self._targets[i] for i, c in enumerate(self.MOTORS)}}

    def _observe(self):
        return np.concatenate([self._joints, self.target_pose], axis=1)

    def pose_error(self):
        """Sum over the motors of (angle - target)^2 (rad^2), [W]."""
        angles = self._joints[:, self._angle_columns].astype(np.float64)
        return np.sum(np.square(angles - self.target_pose), axis=1)

    def _reward(self, actions):
        return np.exp(-self.pose_error())
