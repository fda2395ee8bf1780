"""Shared set-up of the Python tests (run by ctest, one entry per file)."""

import math
import os
import pathlib

import numpy as np
import pytest

import manyworlds as mw


def pytest_report_header(config):
    return f"manyworlds {mw.__version__} from {pathlib.Path(mw.__file__).parent}"


def pytest_sessionstart(session):
    # ctest sets this: the tests must exercise the package of this build,
    # not one installed earlier in the site directory.
    expected = os.environ.get("MANYWORLDS_TEST_PACKAGE_DIR")
    if expected:
        got = pathlib.Path(mw.__file__).resolve().parent
        assert got == pathlib.Path(expected).resolve(), f"imported {got}, expected {expected}"


WORLDS = 64  # small batches keep the tests fast; four blocks of 16 worlds


def hand_built_cartpole():
    """The reference cartpole (batch/scenes.cc) built from the Python API."""
    angle = 0.1  # rad about Z: the pole's start
    c, s = math.cos(angle), math.sin(angle)
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(name="world", motion_type=mw.MotionType.STATIC,
                                   linear_damping=0.0, angular_damping=0.0))
    scene.add_body(mw.BodySettings(name="cart", mass=1.0, inertia_diagonal=(0.1, 0.1, 0.1),
                                   linear_damping=0.0, angular_damping=0.0))
    scene.add_body(mw.BodySettings(name="pole", mass=0.1,
                                   inertia_diagonal=(0.0084, 0.0001, 0.0084),
                                   position=(-0.5 * s, 0.5 * c, 0.0),
                                   rotation=(0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)),
                                   linear_damping=0.0, angular_damping=0.0))
    scene.add_constraint(mw.SliderConstraintSettings(
        name="rail", body1=0, body2=1, slider_axis1=(1, 0, 0), slider_axis2=(1, 0, 0),
        normal_axis1=(0, 1, 0), normal_axis2=(0, 1, 0)))
    scene.add_constraint(mw.HingeConstraintSettings(
        name="pole hinge", body1=1, body2=2, hinge_axis1=(0, 0, 1), hinge_axis2=(0, 0, 1),
        normal_axis1=(1, 0, 0), normal_axis2=(c, s, 0.0)))
    return scene


def motor_hinge_scene(motor_state=mw.MotorState.VELOCITY):
    """A pendulum on a motorised hinge (the README's example)."""
    scene = mw.Scene()
    ground = scene.add_body(mw.BodySettings(motion_type=mw.MotionType.STATIC))
    pole = scene.add_body(mw.BodySettings(mass=0.1, inertia_diagonal=(0.0084, 0.0001, 0.0084),
                                          position=(0, 0.5, 0)))
    hinge = mw.HingeConstraintSettings(body1=ground, body2=pole, hinge_axis1=(0, 0, 1),
                                       hinge_axis2=(0, 0, 1), normal_axis1=(1, 0, 0),
                                       normal_axis2=(1, 0, 0), motor_state=motor_state)
    hinge.motor.min_force_limit = -5
    hinge.motor.max_force_limit = 5
    scene.add_constraint(hinge)
    return scene


def bits(array):
    """The bytes of a float array as integers, for exact comparisons (NaN too)."""
    return np.ascontiguousarray(array).view(np.uint32)


def assert_same_bits(a, b):
    np.testing.assert_array_equal(bits(a), bits(b))


def random_cart_forces(rng, worlds):
    forces = np.zeros((worlds, 3), np.float32)
    forces[:, 0] = rng.uniform(-10, 10, worlds).astype(np.float32)
    return forces


@pytest.fixture
def cartpole():
    return mw.Batch(mw.make_scene("cartpole"), WORLDS)
