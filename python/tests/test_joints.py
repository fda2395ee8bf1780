"""Joint coordinates and motor forces from Python (bind_joints.cc): names,
shapes, values against the bodies' state, out= and the array checks."""

import numpy as np
import pytest

import manyworlds as mw
from conftest import WORLDS, motor_hinge_scene, random_cart_forces

CART, POLE = mw.reference_scene.CART, mw.reference_scene.POLE
RAIL, POLE_HINGE = mw.reference_scene.RAIL, mw.reference_scene.POLE_HINGE


def stepped(batch, steps=20, seed=3):
    rng = np.random.default_rng(seed)
    for _ in range(steps):
        batch.set_body_forces(CART, random_cart_forces(rng, WORLDS))
        batch.step()
    return batch


def test_names_and_counts(cartpole):
    assert cartpole.joint_coordinate_names(RAIL) == ["position", "velocity"]
    assert cartpole.joint_coordinate_names(POLE_HINGE) == [
        "angle", "unwrapped_angle", "angular_velocity"]
    assert cartpole.joint_coordinate_count(RAIL) == 2
    assert cartpole.joint_coordinate_count(POLE_HINGE) == 3
    assert cartpole.joint_coordinates_per_world == 5
    # Neither has a motor: no motor rows (a [W, 0] array).
    assert cartpole.motor_force_count(RAIL) == 0
    assert cartpole.get_motor_forces(POLE_HINGE).shape == (WORLDS, 0)


def test_cartpole_coordinates_match_the_state(cartpole):
    stepped(cartpole)
    state = cartpole.get_state()
    rail = cartpole.get_joint_coordinates(RAIL)
    hinge = cartpole.get_joint_coordinates(POLE_HINGE)
    assert rail.dtype == np.float32 and rail.shape == (WORLDS, 2)
    assert hinge.dtype == np.float32 and hinge.shape == (WORLDS, 3)
    # The rail runs through the origin along X: slider position = cart x.
    np.testing.assert_allclose(rail[:, 0], state[:, CART, 0], atol=1e-5)
    np.testing.assert_allclose(rail[:, 1], state[:, CART, 7], atol=1e-4)
    # The cart cannot rotate: hinge rate = the pole's angular velocity about Z.
    np.testing.assert_allclose(hinge[:, 2], state[:, POLE, 12], rtol=1e-4, atol=1e-4)
    # Angle from the pole's quaternion (rotation about Z from upright).
    qz, qw = state[:, POLE, 5].astype(np.float64), state[:, POLE, 6].astype(np.float64)
    angle = np.angle(np.exp(1j * 2 * np.arctan2(qz, qw)))
    np.testing.assert_allclose(hinge[:, 0], angle, atol=2e-4)
    # Less than a turn: the unwrapped angle is the angle.
    np.testing.assert_allclose(hinge[:, 1], hinge[:, 0], atol=1e-6)


def test_all_coordinates_concatenate_in_scene_order(cartpole):
    stepped(cartpole)
    every = cartpole.get_joint_coordinates()
    assert every.shape == (WORLDS, 5) and every.dtype == np.float32
    np.testing.assert_array_equal(every[:, :2], cartpole.get_joint_coordinates(RAIL))
    np.testing.assert_array_equal(every[:, 2:], cartpole.get_joint_coordinates(POLE_HINGE))


def test_out_is_filled_in_place(cartpole):
    stepped(cartpole)
    out = np.full((WORLDS, 3), np.nan, np.float32)
    result = cartpole.get_joint_coordinates(POLE_HINGE, out=out)
    assert result is out
    np.testing.assert_array_equal(out, cartpole.get_joint_coordinates(POLE_HINGE))
    every = np.empty((WORLDS, 5), np.float32)
    assert cartpole.get_joint_coordinates(out=every) is every
    motor = mw.Batch(motor_hinge_scene(), WORLDS)
    motor.step()
    forces = np.empty((WORLDS, 1), np.float32)
    assert motor.get_motor_forces(0, out=forces) is forces


def test_motor_force_of_a_saturated_velocity_motor():
    batch = mw.Batch(motor_hinge_scene(), WORLDS)
    assert np.all(batch.get_motor_forces(0) == 0)  # before the first step
    batch.set_target_velocities(0, np.full(WORLDS, 1000.0, np.float32))  # far out of reach
    batch.step()
    torque = batch.get_motor_forces(0)
    assert torque.shape == (WORLDS, 1) and torque.dtype == np.float32
    np.testing.assert_allclose(np.abs(torque), 5.0, rtol=1e-5)  # its +-5 N m limit


@pytest.mark.parametrize("scene,call,shape", [
    ("cartpole", lambda b, out: b.get_joint_coordinates(POLE_HINGE, out=out), (WORLDS, 3)),
    ("cartpole", lambda b, out: b.get_joint_coordinates(out=out), (WORLDS, 5)),
    ("motor", lambda b, out: b.get_motor_forces(0, out=out), (WORLDS, 1)),
])
def test_bad_out_is_refused_by_name(scene, call, shape):
    batch = mw.Batch(mw.make_scene("cartpole") if scene == "cartpole" else motor_hinge_scene(),
                     WORLDS)
    with pytest.raises(TypeError, match=r"out: expected float32, got float64"):
        call(batch, np.zeros(shape, np.float64))
    with pytest.raises(ValueError, match=r"out: expected shape \(64, \d\), got \(64, 7\)"):
        call(batch, np.zeros((WORLDS, 7), np.float32))
    with pytest.raises(ValueError, match="out: must be C-contiguous"):
        call(batch, np.zeros((WORLDS, 2 * shape[1]), np.float32)[:, ::2])
    read_only = np.zeros(shape, np.float32)
    read_only.flags.writeable = False
    with pytest.raises(ValueError, match="out"):
        call(batch, read_only)
    with pytest.raises(TypeError, match="out: expected a numpy array"):
        call(batch, [[0.0] * shape[1]] * WORLDS)


def test_bad_constraint_index(cartpole):
    for call in (cartpole.joint_coordinate_names, cartpole.get_joint_coordinates,
                 cartpole.get_motor_forces, cartpole.joint_coordinate_count):
        with pytest.raises(IndexError, match=r"constraint 2 out of range \[0, 2\)"):
            call(2)
        with pytest.raises(IndexError, match="constraint -1"):
            call(-1)
