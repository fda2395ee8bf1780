"""dm_control suite tasks (Tassa et al. 2018, dm_control/suite/*.py) on
manyworlds: cartpole balance and swing-up, pendulum swing-up, acrobot
swing-up. Dimensions, masses, actuator gears, initial-state distributions,
observations, rewards and time limits follow dm_control's XML and task
code; docs/envs.md lists what differs (integrator, contact-free limits,
joint damping applied as explicit torques).

Geometry: dm_control's X-Z plane is manyworlds' X-Y plane (Y up), and its
hinges about +Y are hinges about -Z here, so that joint angles have
dm_control's sign (a positive angle tips a link from +Y towards +X) and 0
is upright.
"""

import math

import numpy as np

from .. import _core
from . import _compat
from .rewards import tolerance
from .vector import ManyWorldsVectorEnv, planar_states, rotate

_MINUS_Z = (0.0, 0.0, -1.0)
_X = (1.0, 0.0, 0.0)


def _body(name, mass, inertia, position, gravity_factor=1.0):
    return _core.BodySettings(name=name, mass=mass, inertia_diagonal=inertia, position=position,
                              linear_damping=0.0, angular_damping=0.0,
                              gravity_factor=gravity_factor)


def _static(name="world"):
    return _core.BodySettings(name=name, motion_type=_core.MotionType.STATIC,
                              linear_damping=0.0, angular_damping=0.0)


def _hinge(name, body1, body2, point):
    return _core.HingeConstraintSettings(name=name, body1=body1, body2=body2, point1=point,
                                         point2=point, hinge_axis1=_MINUS_Z,
                                         hinge_axis2=_MINUS_Z, normal_axis1=_X, normal_axis2=_X)


def _box(size):
    return _compat.make_box(-np.inf, np.inf, (size,), np.float32)


def _actions(size):
    return _compat.make_box(-1.0, 1.0, (size,), np.float32)


# -------------------------------------------------------------------- cartpole


class CartpoleEnv(ManyWorldsVectorEnv):
    """dm_control cartpole (suite/cartpole.py, cartpole.xml), balance or swingup.

    Cart 1 kg on a rail (slider, limits +-1.8 m), pole 0.1 kg, 1 m, hinged at
    the cart's centre; action u in [-1, 1] is a force 10 u N on the cart
    (gear 10). Step 0.01 s (dm_control's timestep and control step; one
    substep), 1000 steps (10 s). Observation [cart x, cos, sin of the pole
    angle, cart velocity, pole angular velocity]; dm_control's dense reward
    upright * centered * small_control * small_velocity.
    """

    CART, POLE = 1, 2
    RAIL, HINGE = 0, 1
    FORCE_GEAR = 10.0
    default_max_episode_steps = 1000

    def __init__(self, num_envs, *, swing_up=False, **options):
        self.swing_up = bool(swing_up)
        self.env_id = "cartpole-swingup" if swing_up else "cartpole-balance"
        self.step_settings = _core.StepSettings(delta_time=0.01, substeps=1)
        super().__init__(num_envs, **options)
        self._forces = np.zeros((self.num_envs, 3), np.float32)

    def _make_scene(self):
        scene = _core.Scene()
        scene.add_body(_static())
        scene.add_body(_body("cart", 1.0, (0.1, 0.1, 0.1), (0.0, 0.0, 0.0)))
        # Capsule 1 m, radius 0.045, 0.1 kg: about its centre ~ m L^2 / 12.
        scene.add_body(_body("pole", 0.1, (0.0084, 0.0001, 0.0084), (0.0, 0.5, 0.0)))
        scene.add_constraint(_core.SliderConstraintSettings(
            name="slider", body1=0, body2=1, slider_axis1=_X, slider_axis2=_X,
            normal_axis1=(0, 1, 0), normal_axis2=(0, 1, 0), limits_min=-1.8, limits_max=1.8))
        scene.add_constraint(_hinge("hinge_1", 1, 2, (0.0, 0.0, 0.0)))
        return scene

    def _observation_space(self):
        return _box(5)

    def _action_space(self):
        return _actions(1)

    def _reset_states(self, idx, rng):
        n = len(idx)
        # dm_control Balance.initialize_episode, in its order of draws.
        if self.swing_up:
            x = 0.01 * rng.standard_normal(n)
            angle = math.pi + 0.01 * rng.standard_normal(n)
        else:
            x = rng.uniform(-0.1, 0.1, n)
            angle = rng.uniform(-0.034, 0.034, n)
        qvel = 0.01 * rng.standard_normal((n, 2))
        vx, omega = qvel[:, 0], qvel[:, 1]
        zero = np.zeros(n)
        px, py = rotate(angle, 0.0, 0.5)
        vpx, vpy = 0.5 * np.cos(angle) * omega, -0.5 * np.sin(angle) * omega
        states = np.empty((n, 3, 13), np.float32)
        states[:, 0] = self._initial_state[0]
        states[:, self.CART] = planar_states(x, zero, zero, vx, zero, zero)
        states[:, self.POLE] = planar_states(x + px, py, angle, vx + vpx, vpy, omega)
        return states

    def _actions(self, actions):
        self._control = actions[:, 0]
        self._forces[:, 0] = self.FORCE_GEAR * self._control
        return {"body_forces": {self.CART: self._forces}}

    # joint coordinates: [x, x_dot, angle, unwrapped angle, angular velocity]
    def _observe(self):
        q = self._joints
        obs = np.empty((self.num_envs, 5), np.float32)
        obs[:, 0] = q[:, 0]
        obs[:, 1] = np.cos(q[:, 2])
        obs[:, 2] = np.sin(q[:, 2])
        obs[:, 3] = q[:, 1]
        obs[:, 4] = q[:, 4]
        return obs

    def _reward(self, actions):
        return cartpole_reward(self._joints[:, 0], np.cos(self._joints[:, 2].astype(np.float64)),
                               self._joints[:, 4], actions[:, 0])


def cartpole_reward(cart_x, pole_cos, pole_angular_velocity, control):
    """dm_control cartpole Balance._get_reward(sparse=False), over arrays."""
    upright = (pole_cos + 1.0) / 2.0
    centered = (1.0 + tolerance(cart_x, margin=2.0)) / 2.0
    small_control = (4.0 + tolerance(control, margin=1.0, value_at_margin=0.0,
                                     sigmoid="quadratic")) / 5.0
    small_velocity = (1.0 + tolerance(pole_angular_velocity, margin=5.0)) / 2.0
    return upright * small_control * small_velocity * centered


# -------------------------------------------------------------------- pendulum


class PendulumSwingupEnv(ManyWorldsVectorEnv):
    """dm_control pendulum swingup (suite/pendulum.py, pendulum.xml).

    A 1 kg ball (radius 0.05 m) on a massless 0.5 m pole from a fixed pivot;
    action u in [-1, 1] is a torque u N m (gear 1); joint damping 0.1 N m s
    (applied as a torque from the rate at the start of each step). Step 0.02
    s, 1000 steps (20 s). Starts at rest at an angle uniform in [-pi, pi).
    Observation [cos, sin, angular velocity]; reward 1 when the pole is
    within 8 degrees of upright, else 0 (dm_control's sparse reward).
    """

    env_id = "pendulum-swingup"
    POLE, HINGE = 1, 0
    DAMPING = 0.1
    LENGTH = 0.5
    COSINE_BOUND = math.cos(math.radians(8.0))
    default_max_episode_steps = 1000

    def __init__(self, num_envs, **options):
        self.step_settings = _core.StepSettings(delta_time=0.02, substeps=1)
        super().__init__(num_envs, **options)
        self._torque = np.zeros((self.num_envs, 3), np.float32)

    def _make_scene(self):
        scene = _core.Scene()
        scene.add_body(_static())
        inertia = 0.4 * 1.0 * 0.05 ** 2  # solid sphere
        scene.add_body(_body("pole", 1.0, (inertia, inertia, inertia), (0.0, self.LENGTH, 0.0)))
        scene.add_constraint(_hinge("hinge", 0, 1, (0.0, 0.0, 0.0)))
        return scene

    def _observation_space(self):
        return _box(3)

    def _action_space(self):
        return _actions(1)

    def _reset_states(self, idx, rng):
        n = len(idx)
        angle = rng.uniform(-math.pi, math.pi, n)
        zero = np.zeros(n)
        px, py = rotate(angle, 0.0, self.LENGTH)
        states = np.empty((n, 2, 13), np.float32)
        states[:, 0] = self._initial_state[0]
        states[:, self.POLE] = planar_states(px, py, angle, zero, zero, zero)
        return states

    def _actions(self, actions):
        torque = actions[:, 0] - self.DAMPING * self._joints[:, 2]
        self._torque[:, 2] = -torque  # about the hinge's -Z axis
        return {"body_torques": {self.POLE: self._torque}}

    def _observe(self):
        q = self._joints
        obs = np.empty((self.num_envs, 3), np.float32)
        obs[:, 0] = np.cos(q[:, 0])
        obs[:, 1] = np.sin(q[:, 0])
        obs[:, 2] = q[:, 2]
        return obs

    def _reward(self, actions):
        return tolerance(np.cos(self._joints[:, 0].astype(np.float64)),
                         bounds=(self.COSINE_BOUND, 1.0))


# -------------------------------------------------------------------- acrobot


class AcrobotSwingupEnv(ManyWorldsVectorEnv):
    """dm_control acrobot swingup (suite/acrobot.py, acrobot.xml).

    Two 1 kg, 1 m links (capsules of radius 0.05 m, as cylinders' inertia)
    from a fixed shoulder 2 m up; action u in [-1, 1] is an elbow torque 2 u
    N m (gear 2); joint damping 0.05 N m s at both joints (explicit torques).
    Step 0.01 s, 1000 steps (10 s). Starts at rest with both angles uniform
    in [-pi, pi). Observation [sin th1, sin th12, cos th1, cos th12, th1 dot,
    th2 dot] (dm_control's orientations(): xz then zz of both links, then
    qvel); reward
    tolerance(|tip - target|, bounds=(0, 0.2), margin=1) with the target
    4 m up (dm_control's dense swingup).
    """

    env_id = "acrobot-swingup"
    UPPER, LOWER = 1, 2
    SHOULDER, ELBOW = 0, 1
    DAMPING = 0.05
    GEAR = 2.0
    PIVOT_HEIGHT = 2.0
    TARGET_HEIGHT = 4.0
    TARGET_RADIUS = 0.2
    default_max_episode_steps = 1000

    def __init__(self, num_envs, **options):
        self.step_settings = _core.StepSettings(delta_time=0.01, substeps=1)
        super().__init__(num_envs, **options)
        self._upper_torque = np.zeros((self.num_envs, 3), np.float32)
        self._lower_torque = np.zeros((self.num_envs, 3), np.float32)

    def _make_scene(self):
        scene = _core.Scene()
        scene.add_body(_static())
        across = (3 * 0.05 ** 2 + 1.0) / 12.0
        inertia = (across, 0.5 * 0.05 ** 2, across)
        h = self.PIVOT_HEIGHT
        scene.add_body(_body("upper_arm", 1.0, inertia, (0.0, h + 0.5, 0.0)))
        scene.add_body(_body("lower_arm", 1.0, inertia, (0.0, h + 1.5, 0.0)))
        scene.add_constraint(_hinge("shoulder", 0, 1, (0.0, h, 0.0)))
        scene.add_constraint(_hinge("elbow", 1, 2, (0.0, h + 1.0, 0.0)))
        return scene

    def _observation_space(self):
        return _box(6)

    def _action_space(self):
        return _actions(1)

    def _reset_states(self, idx, rng):
        n = len(idx)
        angles = rng.uniform(-math.pi, math.pi, (n, 2))
        th1, th12 = angles[:, 0], angles[:, 0] + angles[:, 1]
        zero = np.zeros(n)
        ux, uy = rotate(th1, 0.0, 0.5)
        ex, ey = rotate(th1, 0.0, 1.0)
        lx, ly = rotate(th12, 0.0, 0.5)
        h = self.PIVOT_HEIGHT
        states = np.empty((n, 3, 13), np.float32)
        states[:, 0] = self._initial_state[0]
        states[:, self.UPPER] = planar_states(ux, h + uy, th1, zero, zero, zero)
        states[:, self.LOWER] = planar_states(ex + lx, h + ey + ly, th12, zero, zero, zero)
        return states

    # joint coordinates: shoulder [angle, unwrapped, rate], elbow [angle, unwrapped, rate]
    def _actions(self, actions):
        q = self._joints
        shoulder = -self.DAMPING * q[:, 2]
        elbow = self.GEAR * actions[:, 0] - self.DAMPING * q[:, 5]
        # One [W, 3] write per link (the whole-batch set_torques form checks
        # every body of every world and costs more).
        self._upper_torque[:, 2] = -(shoulder - elbow)  # about the hinges' -Z axis
        self._lower_torque[:, 2] = -elbow
        return {"body_torques": {self.UPPER: self._upper_torque, self.LOWER: self._lower_torque}}

    def _observe(self):
        q = self._joints
        th1, th12 = q[:, 0], q[:, 0] + q[:, 3]
        obs = np.empty((self.num_envs, 6), np.float32)
        # dm_control's orientations(): horizontal (xmat xz = sin) of both
        # links, then vertical (zz = cos).
        obs[:, 0], obs[:, 1] = np.sin(th1), np.sin(th12)
        obs[:, 2], obs[:, 3] = np.cos(th1), np.cos(th12)
        obs[:, 4], obs[:, 5] = q[:, 2], q[:, 5]
        return obs

    def tip_to_target(self):
        """|tip - target| (m) of every world, from the joint angles."""
        q = self._joints.astype(np.float64)
        th1, th12 = q[:, 0], q[:, 0] + q[:, 3]
        tip_x = np.sin(th1) + np.sin(th12)
        tip_y = self.PIVOT_HEIGHT + np.cos(th1) + np.cos(th12)
        return np.hypot(tip_x, tip_y - self.TARGET_HEIGHT)

    def _reward(self, actions):
        return tolerance(self.tip_to_target(), bounds=(0.0, self.TARGET_RADIUS), margin=1.0)
