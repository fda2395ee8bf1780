"""Bad input raises the right exception, naming the argument, and writes
nothing: every refused call leaves every byte of the batch as it was (its
snapshot bytes, state and health compare equal before and after)."""

import math

import numpy as np
import pytest

import manyworlds as mw
from conftest import WORLDS, assert_same_bits, motor_hinge_scene

CART, POLE = mw.reference_scene.CART, mw.reference_scene.POLE
POLE_HINGE = mw.reference_scene.POLE_HINGE


def assert_refused(batch, call, exception, *fragments):
    """call() raises `exception` whose message holds every fragment, and the
    batch is unchanged to the last byte."""
    before_bytes = batch.snapshot().bytes()
    before_state, before_health = batch.get_state(), batch.health
    with pytest.raises(exception) as raised:
        call()
    for fragment in fragments:
        assert fragment in str(raised.value), (fragment, str(raised.value))
    assert_same_bits(batch.get_state(), before_state)
    np.testing.assert_array_equal(batch.health, before_health)
    assert batch.snapshot().bytes() == before_bytes
    return raised.value


@pytest.fixture
def stepped_cartpole(cartpole):
    # A few steps first, so that "unchanged" is not the initial state.
    forces = np.zeros((WORLDS, 3), np.float32)
    for step in range(3):
        forces[:, 0] = step
        cartpole.set_body_forces(CART, forces)
        cartpole.step()
    return cartpole


S = (WORLDS, 3, 13)  # cartpole state
# (argument name, expected shape, call with the array) for every array input.
ARRAY_ARGUMENTS = [
    ("forces", (WORLDS, 3, 3), lambda b, a: b.set_forces(a)),
    ("torques", (WORLDS, 3, 3), lambda b, a: b.set_torques(a)),
    ("forces", (WORLDS, 3), lambda b, a: b.set_body_forces(CART, a)),
    ("torques", (WORLDS, 3), lambda b, a: b.set_body_torques(CART, a)),
    ("state", S, lambda b, a: b.set_state(a)),
    ("values", (WORLDS, 3, 4), lambda b, a: b.set_field(mw.StateField.ROTATION, a)),
    ("state", S, lambda b, a: b.reset_to(None, a)),
    ("out", S, lambda b, a: b.get_state(out=a)),
    ("out", (WORLDS, 3, 3), lambda b, a: b.get_field(mw.StateField.POSITION, out=a)),
    ("out", (WORLDS, 3), lambda b, a: b.get_joint_coordinates(POLE_HINGE, out=a)),
    ("out", (WORLDS, 5), lambda b, a: b.get_joint_coordinates(out=a)),  # rail 2 + hinge 3
    ("mass", (WORLDS,), lambda b, a: b.set_mass_properties(CART, a, (0.1, 0.1, 0.1))),
    ("inertia", (WORLDS, 3), lambda b, a: b.set_mass_properties(CART, 1.0, a)),
    ("factor", (WORLDS,), lambda b, a: b.set_gravity_factor(CART, a)),
    ("angular", (WORLDS,), lambda b, a: b.set_damping(CART, 0.1, a)),
    ("max", (WORLDS,), lambda b, a: b.set_limits(0, -1.0, a)),
    ("reset_states", S,
     lambda b, a: b.step(reset_mask=np.ones(WORLDS, bool), reset_states=a)),
    ("state_out", S, lambda b, a: b.step(state_out=a)),
    ("joints_out", (WORLDS, 5), lambda b, a: b.step(joints_out=a)),
    ("body_forces[1]", (WORLDS, 3), lambda b, a: b.step(body_forces={CART: a})),
    ("body_torques[2]", (WORLDS, 3), lambda b, a: b.step(body_torques={POLE: a})),
    ("target_velocities[1]", (WORLDS,), lambda b, a: b.step(target_velocities={POLE_HINGE: a})),
]
IDS = [f"{i}-{name}" for i, (name, _, _) in enumerate(ARRAY_ARGUMENTS)]


def shape_text(shape):
    return "(" + ", ".join(map(str, shape)) + ("," if len(shape) == 1 else "") + ")"


@pytest.mark.parametrize("name,shape,call", ARRAY_ARGUMENTS, ids=IDS)
def test_float64_is_refused_not_converted(stepped_cartpole, name, shape, call):
    array = np.ones(shape, np.float64)
    assert_refused(stepped_cartpole, lambda: call(stepped_cartpole, array), TypeError,
                   f"{name}: expected float32, got float64 (use arr.astype(np.float32))")


@pytest.mark.parametrize("name,shape,call", ARRAY_ARGUMENTS, ids=IDS)
def test_wrong_shape_is_refused(stepped_cartpole, name, shape, call):
    array = np.ones(shape[:-1] if len(shape) > 1 else (WORLDS + 1,), np.float32)
    assert_refused(stepped_cartpole, lambda: call(stepped_cartpole, array), ValueError,
                   f"{name}: expected shape {shape_text(shape)}, got {shape_text(array.shape)}")


@pytest.mark.parametrize("name,shape,call", ARRAY_ARGUMENTS, ids=IDS)
def test_non_contiguous_is_refused(stepped_cartpole, name, shape, call):
    array = np.ones((2 * shape[0],) + shape[1:], np.float32)[::2]
    assert array.shape == shape and not array.flags.c_contiguous
    assert_refused(stepped_cartpole, lambda: call(stepped_cartpole, array), ValueError,
                   f"{name}: must be C-contiguous; use np.ascontiguousarray")


@pytest.mark.parametrize("name,shape,call", ARRAY_ARGUMENTS, ids=IDS)
def test_lists_are_refused(stepped_cartpole, name, shape, call):
    values = np.ones(shape, np.float32).tolist()
    assert_refused(stepped_cartpole, lambda: call(stepped_cartpole, values), TypeError,
                   f"{name}: expected ", "numpy array of float32", "got list",
                   "(use np.asarray(x, dtype=np.float32))")


def test_read_only_output_is_refused(stepped_cartpole):
    out = np.empty(S, np.float32)
    out.flags.writeable = False
    assert_refused(stepped_cartpole, lambda: stepped_cartpole.get_state(out=out), ValueError,
                   "out: array is read-only")


MASK_CALLS = [
    lambda b, m: b.reset(m),
    lambda b, m: b.set_state(b.get_state(), m),
    lambda b, m: b.reset_to(m, b.get_state()),
    lambda b, m: b.restore(b.snapshot(), m),
    lambda b, m: b.set_gravity_factor(CART, 0.5, mask=m),
    lambda b, m: b.step(reset_mask=m),
]


@pytest.mark.parametrize("call", MASK_CALLS)
def test_bad_masks_are_refused(stepped_cartpole, call):
    b = stepped_cartpole
    assert_refused(b, lambda: call(b, np.ones(WORLDS, np.float32)), TypeError,
                   "mask: expected bool or uint8, got float32")
    assert_refused(b, lambda: call(b, np.ones(WORLDS - 1, bool)), ValueError,
                   f"mask: expected shape ({WORLDS},), got ({WORLDS - 1},)")
    assert_refused(b, lambda: call(b, [1] * WORLDS), TypeError, "mask: expected a numpy array")


def test_actions_are_never_refused_for_nan(stepped_cartpole):
    forces = np.full((WORLDS, 3), np.nan, np.float32)
    stepped_cartpole.set_body_forces(CART, forces)  # no exception: flagged at the step
    stepped_cartpole.step()
    assert np.all(stepped_cartpole.health & mw.WorldHealthBits.NON_FINITE_INPUT)


# A bad value in world 9 only: every world before it would be valid.
def nan_in_world_9(value=1.0):
    values = np.full(WORLDS, value, np.float32)
    values[9] = np.nan
    return values


def test_per_world_parameters_refuse_nan_in_one_world_and_write_nothing(stepped_cartpole):
    b = stepped_cartpole
    inertia = np.full((WORLDS, 3), 0.1, np.float32)
    error = assert_refused(b, lambda: b.set_mass_properties(CART, nan_in_world_9(), inertia),
                           ValueError, "world 9")
    assert isinstance(error, mw.SceneError)
    inertia[9, 1] = -1.0
    assert_refused(b, lambda: b.set_mass_properties(CART, 2.0, inertia), ValueError, "world 9")
    assert_refused(b, lambda: b.set_gravity_factor(CART, nan_in_world_9()), ValueError, "world 9")
    assert_refused(b, lambda: b.set_damping(CART, nan_in_world_9(0.1), 0.1), ValueError,
                   "world 9")
    # A mask selecting only good worlds writes them (the refusal was about world 9 only).
    mask = np.ones(WORLDS, bool)
    mask[9] = False
    b.set_gravity_factor(CART, nan_in_world_9(0.5), mask=mask)


def test_constraint_parameters_refuse_by_name():
    batch = mw.Batch(motor_hinge_scene(mw.MotorState.POSITION), WORLDS)
    batch.step()
    assert_refused(batch, lambda: batch.set_motor_limits(0, 1.0, nan_in_world_9(2.0)),
                   ValueError, "world 9")
    assert_refused(batch, lambda: batch.set_motor_spring(0, nan_in_world_9(2.0), 1.0),
                   ValueError, "world 9")
    assert_refused(batch, lambda: batch.set_max_friction(0, -1.0), ValueError, "friction")
    assert_refused(batch, lambda: batch.set_limits(0, -0.5, 0.5), ValueError, "limits")
    assert_refused(batch, lambda: batch.set_ratio(0, 2.0), ValueError, "ratio")
    gears = mw.Batch(mw.make_scene("geartrain"), WORLDS)
    assert_refused(gears, lambda: gears.set_ratio(mw.reference_scene.GEAR, nan_in_world_9(2.0)),
                   ValueError, "world 9")
    gears.set_ratio(mw.reference_scene.GEAR, 2.0)


def test_indices_out_of_range(stepped_cartpole):
    b = stepped_cartpole
    forces = np.zeros((WORLDS, 3), np.float32)
    assert_refused(b, lambda: b.set_body_forces(3, forces), IndexError, "body 3 out of range")
    assert_refused(b, lambda: b.set_body_forces(-1, forces), IndexError, "body -1")
    assert_refused(b, lambda: b.set_target_velocities(2, 0.0), IndexError, "constraint 2")
    assert_refused(b, lambda: b.set_gravity_factor(7, 1.0), IndexError, "body 7")
    with pytest.raises(IndexError, match="world 64"):
        b.max_constraint_error(WORLDS)


def test_targets_on_a_constraint_without_a_motor(stepped_cartpole):
    b = stepped_cartpole
    assert_refused(b, lambda: b.set_target_velocities(POLE_HINGE, np.zeros(WORLDS, np.float32)),
                   ValueError, "pole hinge")
    assert_refused(b, lambda: b.set_target_orientations(POLE_HINGE,
                                                        np.zeros((WORLDS, 4), np.float32)),
                   ValueError)


def test_zero_target_orientation_in_one_world_writes_nothing():
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(motion_type=mw.MotionType.STATIC))
    scene.add_body(mw.BodySettings(position=(1, 0, 0)))
    joint = mw.SwingTwistConstraintSettings(
        body1=0, body2=1, normal_half_cone_angle=1.0, plane_half_cone_angle=1.0,
        twist_min_angle=-1.0, twist_max_angle=1.0, swing_motor_state=mw.MotorState.POSITION,
        twist_motor_state=mw.MotorState.POSITION)
    scene.add_constraint(joint)
    batch = mw.Batch(scene, WORLDS)
    targets = np.tile(np.float32([0, 0, math.sin(0.2), math.cos(0.2)]), (WORLDS, 1))
    batch.set_target_orientations(0, targets)
    targets[9] = 0.0
    assert_refused(batch, lambda: batch.set_target_orientations(0, targets), ValueError,
                   "in world 9: target orientation is a zero quaternion")


def test_bad_scenes_and_settings():
    scene = mw.make_scene("cartpole")
    scene.set_body(2, mw.BodySettings(scene.bodies[2], mass=float("nan")))
    with pytest.raises(mw.SceneError, match="pole.*mass"):
        mw.Batch(scene, 16)
    assert issubclass(mw.SceneError, ValueError)
    with pytest.raises(ValueError, match="world"):
        mw.Batch(mw.make_scene("cartpole"), 0)
    with pytest.raises(ValueError, match="threads"):
        mw.Batch(mw.make_scene("cartpole"), 16, threads=-1)
    batch = mw.Batch(mw.make_scene("cartpole"), 16)
    assert_refused(batch, lambda: batch.step(mw.StepSettings(delta_time=0.0)), ValueError,
                   "delta_time")
    assert_refused(batch, lambda: batch.step(mw.StepSettings(substeps=5000)), ValueError,
                   "substeps")
    rotations = batch.get_field(mw.StateField.ROTATION)
    rotations[3, 1] = 0.0
    assert_refused(batch, lambda: batch.set_field(mw.StateField.ROTATION, rotations), ValueError,
                   "world 3")


def test_settings_refuse_unknown_keywords_and_bad_vectors():
    with pytest.raises(TypeError, match="unexpected keyword argument 'mas'"):
        mw.BodySettings(mas=2.0)
    with pytest.raises(TypeError, match="BodySettings.position: expected a sequence of 3"):
        mw.BodySettings(position=(1, 2))
    with pytest.raises(TypeError, match=r"HingeConstraintSettings.point1\[1\]: expected a number"):
        mw.HingeConstraintSettings(point1=(1, "a", 3))
    with pytest.raises(TypeError, match="SixDofConstraintSettings.motor: expected a sequence of 6"):
        mw.SixDofConstraintSettings(motor=[mw.MotorSettings()] * 5)
    with pytest.raises(TypeError, match="PathConstraintSettings.path: expected PathPoint"):
        mw.PathConstraintSettings(path=[(0, 0, 0)])


def test_snapshots_of_another_batch_are_refused(stepped_cartpole):
    b = stepped_cartpole
    other = mw.Batch(mw.make_scene("cartpole"), WORLDS * 2).snapshot()
    assert_refused(b, lambda: b.restore(other), ValueError, "world count")
    chain = mw.Batch(mw.make_scene("chain16"), WORLDS).snapshot()
    assert_refused(b, lambda: b.restore(chain), ValueError)
    with pytest.raises(ValueError, match="snapshot"):
        mw.BatchSnapshot.from_bytes(b"not a snapshot at all, clearly")


def test_a_refused_step_writes_no_output(stepped_cartpole):
    """One bad argument of step(): the batch and every other output array
    are left as they were."""
    b = stepped_cartpole
    state_out = np.full(S, 7.0, np.float32)
    joints_out = np.full((WORLDS, 5), 7.0, np.float32)
    zero_rotation = b.get_state()
    zero_rotation[9, CART, 3:7] = 0.0
    assert_refused(b, lambda: b.step(state_out=state_out, joints_out=np.ones((WORLDS, 4),
                                                                            np.float32)),
                   ValueError, "joints_out: expected shape (64, 5), got (64, 4)")
    assert_refused(b, lambda: b.step(reset_states=b.get_state(), state_out=state_out),
                   ValueError, "reset_states: given without a reset_mask")
    assert_refused(b, lambda: b.step(reset_mask=np.ones(WORLDS, bool), reset_states=zero_rotation,
                                     state_out=state_out, joints_out=joints_out),
                   ValueError, "'cart' in world 9: rotation is zero")
    assert_refused(b, lambda: b.step(mw.StepSettings(substeps=0), state_out=state_out,
                                     joints_out=joints_out), ValueError, "substeps")
    assert np.all(state_out == 7.0) and np.all(joints_out == 7.0)


STEP_ACTION_REFUSALS = [
    (lambda b, f: b.step(body_forces=f), TypeError,
     "body_forces: expected a dict {body: float32 array [world, 3]}, got ndarray"),
    (lambda b, f: b.step(target_positions={"rail": 0.0}), TypeError,
     "target_positions: keys are constraint indices (int), got 'rail'"),
    (lambda b, f: b.step(body_torques={7: f}), IndexError, "body 7 out of range [0, 3)"),
    (lambda b, f: b.step(body_forces={0: f}), mw.SceneError,
     "'world': a force applies to dynamic bodies only"),
    (lambda b, f: b.step(target_velocities={POLE_HINGE: 1.0}), mw.SceneError,
     "'pole hinge': a target velocity needs a motor or friction"),
    # A good action before a bad one is not written either.
    (lambda b, f: b.step(body_forces={CART: f}, body_torques={POLE: f[:-1]}), ValueError,
     f"body_torques[2]: expected shape ({WORLDS}, 3), got ({WORLDS - 1}, 3)"),
    (lambda b, f: b.step(body_forces={CART: f}, target_velocities={POLE_HINGE: 1.0},
                         state_out=np.empty(S, np.float32)), mw.SceneError, "needs a motor"),
]


@pytest.mark.parametrize("call,exception,message", STEP_ACTION_REFUSALS)
def test_step_actions_are_refused_by_name_before_anything(stepped_cartpole, call, exception,
                                                          message):
    forces = np.full((WORLDS, 3), 3.0, np.float32)
    assert_refused(stepped_cartpole, lambda: call(stepped_cartpole, forces), exception, message)
