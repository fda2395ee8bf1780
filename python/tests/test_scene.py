"""Scenes from Python: every settings struct and field, enums, Scene, the
reference and stress scenes, limit_mass_range."""

import copy
import math

import numpy as np
import pytest

import manyworlds as mw
from conftest import WORLDS, assert_same_bits, hand_built_cartpole, random_cart_forces

CONSTRAINT_TYPES = [t for t in mw.SETTINGS_TYPES if t.__name__.endswith("ConstraintSettings")]


def other_value(value):
    """A value of the same kind as `value` but different, for round trips."""
    if isinstance(value, bool):
        return not value
    if isinstance(value, int):
        return value + 3 if value < 2**31 else 5  # NO_CONSTRAINT is SIZE_MAX
    if isinstance(value, float):
        return 0.375 if value != 0.375 else 0.625
    if isinstance(value, str):
        return value + "x"
    if hasattr(type(value), "__members__"):  # an enum
        members = [m for m in type(value).__members__.values() if m != value]
        return members[-1]
    if isinstance(value, tuple):
        return tuple(other_value(v) for v in value)
    if type(value) in mw.SETTINGS_TYPES:
        changed = copy.copy(value)
        for name in mw.fields(changed):
            setattr(changed, name, other_value(getattr(changed, name)))
        return changed
    raise AssertionError(f"no other value for {value!r}")


@pytest.mark.parametrize("settings_type", mw.SETTINGS_TYPES, ids=lambda t: t.__name__)
def test_every_field_reads_back_what_was_written(settings_type):
    settings = settings_type()
    names = mw.fields(settings)
    assert names, settings_type
    for name in names:
        value = other_value(getattr(settings, name))
        if name == "path":  # a tuple of PathPoints: write a list of new ones
            value = (mw.PathPoint(position=(1, 2, 3)), mw.PathPoint(tangent=(0, 1, 0)))
        setattr(settings, name, value)
        assert getattr(settings, name) == value, name
    # The keyword constructor sets the same fields.
    rebuilt = settings_type(**{name: getattr(settings, name) for name in names})
    assert rebuilt == settings
    assert rebuilt != settings_type()


def test_defaults_are_jolts():
    body = mw.BodySettings()
    assert body.motion_type == mw.MotionType.DYNAMIC
    assert body.mass == 1.0 and body.inertia_diagonal == (1.0, 1.0, 1.0)
    assert body.rotation == (0.0, 0.0, 0.0, 1.0)
    assert body.linear_damping == pytest.approx(0.05)
    assert body.max_linear_velocity == 500.0
    assert body.max_angular_velocity == pytest.approx(0.25 * math.pi * 60.0)
    assert body.allowed_dofs == mw.AllowedDofs.ALL
    motor = mw.MotorSettings()
    assert motor.spring.mode == mw.SpringMode.FREQUENCY_AND_DAMPING
    assert (motor.spring.frequency_or_stiffness, motor.spring.damping) == (2.0, 1.0)
    hinge = mw.HingeConstraintSettings()
    assert hinge.limits_min == pytest.approx(-math.pi) and hinge.motor_state == mw.MotorState.OFF
    step = mw.StepSettings()
    assert step.delta_time == pytest.approx(1 / 60) and step.gravity == pytest.approx((0, -9.81, 0))
    assert (step.velocity_iterations, step.position_iterations, step.substeps) == (10, 2, 1)


def test_keyword_constructors_and_vectors():
    body = mw.BodySettings(mass=2.0, position=(0, 1, 0), motion_type=mw.MotionType.KINEMATIC)
    assert body.mass == 2.0 and body.position == (0.0, 1.0, 0.0)
    body.position = np.array([1.5, 2.5, 3.5])  # any sequence, numpy too
    assert body.position == (1.5, 2.5, 3.5)
    assert isinstance(body.position, tuple)  # so that body.position[0] = x fails loudly
    with pytest.raises(TypeError):
        body.position[0] = 1.0
    assert mw.BodySettings(body) == body and mw.BodySettings(body) is not body
    assert copy.deepcopy(body) == body
    assert "mass=2.0" in repr(body) and "position=(1.5, 2.5, 3.5)" in repr(body)
    assert mw.StepSettings(delta_time=0.01, substeps=4).substeps == 4


def test_nested_settings_are_live_views():
    hinge = mw.HingeConstraintSettings()
    hinge.motor.max_force_limit = 5.0
    hinge.motor.spring.frequency_or_stiffness = 7.0
    assert hinge.motor.max_force_limit == 5.0 and hinge.motor.spring.frequency_or_stiffness == 7.0
    six = mw.SixDofConstraintSettings()
    six.motor[2].max_force_limit = 3.0
    six.limits_spring[1].damping = 0.5
    assert six.motor[2].max_force_limit == 3.0 and six.limits_spring[1].damping == 0.5
    six.motor_state = [mw.MotorState.VELOCITY] * 6
    assert six.motor_state == (mw.MotorState.VELOCITY,) * 6


def test_six_dof_axis_helpers():
    six = mw.SixDofConstraintSettings()
    six.make_fixed_axis(mw.SixDofAxis.TRANSLATION_Y)
    six.set_limited_axis(mw.SixDofAxis.ROTATION_X, -0.5, 0.25)
    assert six.limit_min[1] > six.limit_max[1]
    assert (six.limit_min[3], six.limit_max[3]) == (-0.5, 0.25)
    six.make_free_axis(mw.SixDofAxis.TRANSLATION_Y)
    assert six.limit_min[1] < -1e38 and six.limit_max[1] > 1e38


def test_path_points():
    path = mw.PathConstraintSettings()
    path.path = [mw.PathPoint(position=(0, 0, 0)), mw.PathPoint(position=(1, 0, 0))]
    assert len(path.path) == 2 and path.path[1].position == (1.0, 0.0, 0.0)
    assert isinstance(path.path, tuple)  # copies: assign a new sequence to change it


def test_enums():
    dofs = mw.AllowedDofs.TRANSLATION_X | mw.AllowedDofs.ROTATION_Z
    assert isinstance(dofs, mw.AllowedDofs) and int(dofs) == 33
    assert repr(dofs) == "AllowedDofs.TRANSLATION_X|ROTATION_Z"
    assert mw.AllowedDofs.PLANE_2D & mw.AllowedDofs.ROTATION_Z
    assert not (mw.AllowedDofs.PLANE_2D & mw.AllowedDofs.ROTATION_X)
    body = mw.BodySettings(allowed_dofs=dofs)
    assert body.allowed_dofs == dofs
    body.allowed_dofs = 3  # ints convert too
    assert body.allowed_dofs == mw.AllowedDofs.TRANSLATION_X | mw.AllowedDofs.TRANSLATION_Y
    for enum_type, count in [(mw.MotionType, 3), (mw.MotorState, 4), (mw.SpringMode, 3),
                             (mw.SwingType, 2), (mw.ConstraintSpace, 2), (mw.PathRotation, 6),
                             (mw.SixDofAxis, 6), (mw.UnhealthyWorlds, 2), (mw.StateField, 4)]:
        assert len(enum_type.__members__) == count, enum_type
    assert [mw.state_field_offset(f) for f in mw.StateField.__members__.values()] == [0, 3, 7, 10]
    assert [mw.state_field_size(f) for f in mw.StateField.__members__.values()] == [3, 4, 3, 3]
    assert mw.WorldHealthBits.NON_FINITE_INPUT == 8 and mw.NOT_STEPPED == 16


def test_scene_bodies_and_constraints():
    scene = mw.Scene()
    assert scene.add_body(mw.BodySettings(name="a")) == 0
    assert scene.add_body(mw.BodySettings(name="b")) == 1
    assert scene.add_constraint(mw.HingeConstraintSettings(body1=0, body2=1)) == 0
    assert scene.add_constraint(mw.PointConstraintSettings(body1=0, body2=1, name="ball")) == 1
    assert [b.name for b in scene.bodies] == ["a", "b"]
    assert [type(c) for c in scene.constraints] == [mw.HingeConstraintSettings,
                                                    mw.PointConstraintSettings]
    scene.set_body(1, mw.BodySettings(name="c", mass=3.0))
    assert scene.bodies[1].mass == 3.0 and scene.num_bodies == 2
    scene.set_constraint(0, mw.SliderConstraintSettings(body1=0, body2=1))
    assert isinstance(scene.constraints[0], mw.SliderConstraintSettings)
    assert scene.constraint_label(1) == "point constraint #1 'ball'" and scene.num_constraints == 2
    with pytest.raises(IndexError, match="body 2 out of range"):
        scene.set_body(2, mw.BodySettings())
    with pytest.raises(IndexError):
        scene.body_label(-1)
    assert repr(scene) == "Scene(2 bodies, 2 constraints)"


def test_hand_built_cartpole_is_the_reference_cartpole():
    hand, reference = hand_built_cartpole(), mw.make_scene("cartpole")
    assert hand.bodies == reference.bodies
    assert hand.constraints == reference.constraints
    # ... and so steps the same bits.
    batches = [mw.Batch(scene, WORLDS) for scene in (hand, reference)]
    rng = np.random.default_rng(1)
    for _ in range(50):
        forces = random_cart_forces(rng, WORLDS)
        for batch in batches:
            batch.set_body_forces(mw.reference_scene.CART, forces)
            batch.step()
    assert_same_bits(batches[0].get_state(), batches[1].get_state())


def test_scene_catalogue():
    reference, stress = mw.reference_scene_ids(), mw.stress_scene_ids()
    contact = mw.contact_scene_ids()
    assert reference[0] == "cartpole" and "ragdoll" in reference
    assert "spring-0.5" in stress and "mass-range-hanging" in stress
    assert "box-drop" in contact and "sphere-roll" in contact
    assert mw.all_scene_ids() == reference + [s for s in stress if s not in reference] + contact
    for scene_id in mw.all_scene_ids():
        scene = mw.make_scene(scene_id)
        assert mw.Batch(scene, 16).num_bodies == scene.num_bodies
    assert mw.scene_step_settings("dt-1e-4").delta_time == pytest.approx(1e-4)
    assert mw.scene_step_settings("cartpole") == mw.StepSettings()
    with pytest.raises(ValueError, match="valid ids"):
        mw.make_scene("no-such-scene")
    descriptions = [mw.scene_description(scene_id) for scene_id in mw.all_scene_ids()]
    assert all(d and "\n" not in d for d in descriptions)
    assert len(set(descriptions)) == len(descriptions), "two scenes described alike"
    with pytest.raises(ValueError, match="valid ids"):
        mw.scene_description("no-such-scene")


def test_scene_actions_are_the_cartpole_forces():
    actions = mw.SceneActions("cartpole")
    assert actions.forces_per_world == 1 and not actions.empty
    force = actions.force(0, world=5, step=7, seed=3)
    assert force.body == mw.reference_scene.CART
    assert force.force == (mw.cartpole_force(3, 5, 7), 0.0, 0.0)
    assert mw.SceneActions("chain16").empty


def test_limit_mass_range():
    scene = mw.make_scene("mass-range-hanging")
    light = scene.bodies[1].mass
    raised = mw.limit_mass_range(scene, 1000.0)
    assert raised and all(r.factor > 1 for r in raised)
    first = raised[0]
    assert scene.bodies[first.body].mass == pytest.approx(light * first.factor, rel=1e-6)
    # Within the range now: nothing left to raise (beyond float rounding).
    assert all(r.factor == pytest.approx(1.0, rel=1e-6) for r in mw.limit_mass_range(scene, 1000.0))
    with pytest.raises(ValueError, match="max_ratio"):
        mw.limit_mass_range(scene, 0.5)


def test_every_constraint_type_is_bound():
    assert len(CONSTRAINT_TYPES) == 12
    for constraint_type in CONSTRAINT_TYPES:
        scene = mw.Scene()
        scene.add_body(mw.BodySettings())
        assert scene.add_constraint(constraint_type(body1=0, body2=0)) == 0
        assert type(scene.constraints[0]) is constraint_type


def test_shapes_make_contacts():
    """A ball dropped on a ground plane rests on it; a box beside it in its own
    collision group falls through; a bad shape is refused by name."""
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(name="ground", motion_type=mw.MotionType.STATIC,
                                   shape=mw.ShapeSettings(type=mw.ShapeType.PLANE)))
    scene.add_body(mw.BodySettings(name="ball", position=(0, 1, 0), linear_damping=0,
                                   shape=mw.ShapeSettings(type=mw.ShapeType.SPHERE, radius=0.25)))
    scene.add_body(mw.BodySettings(name="ghost", position=(3, 1, 0),
                                   shape=mw.ShapeSettings(type=mw.ShapeType.BOX, collision_group=2,
                                                          collision_mask=2)))
    batch = mw.Batch(scene, WORLDS)
    assert "contacts in solve order (after the constraints): 1" in batch.plan()
    settings = mw.StepSettings(penetration_slop=0.01)
    for _ in range(120):
        batch.step(settings)
    state = batch.get_state()
    # Resting within the slop (1 cm): the speculative contact stops it near
    # the surface; the ghost fell 2 s freely (~19.6 m).
    assert np.all(np.abs(state[:, 1, 1] - 0.25) <= 0.01)
    assert np.all(state[:, 2, 1] < -15)
    # The ball's one point carries its weight (1 kg): 9.81 N up, on body 2.
    assert batch.num_contact_slots == 1 and batch.contact_slot(0) == (0, 1, 1)
    contacts = batch.get_contacts()
    assert contacts.shape == (WORLDS, 1, 8) and contacts.dtype == np.float32
    assert np.all(contacts[:, 0, 0] == 1)
    np.testing.assert_allclose(contacts[:, 0, 1], 9.81, rtol=1e-4)
    np.testing.assert_allclose(contacts[:, 0, 2:5], np.tile([0, 9.81, 0], (WORLDS, 1)), atol=1e-3)
    bad = mw.Scene(scene)
    ball = bad.bodies[1]
    ball.shape.radius = -1.0
    bad.set_body(1, ball)
    with pytest.raises(ValueError, match=r"'ball'.*shape\.radius"):
        mw.Batch(bad, 4)


def test_boxes_stack_on_each_other():
    """Two boxes stacked on the ground and a ball on top: every slot between
    them carries the weight above it (box-box 4 points, sphere-box 1)."""
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(name="ground", motion_type=mw.MotionType.STATIC,
                                   shape=mw.ShapeSettings(type=mw.ShapeType.PLANE)))
    half = (0.5, 0.25, 0.4)
    for i, name in enumerate(("lower", "upper")):
        scene.add_body(mw.BodySettings(
            name=name, mass=2.0, inertia_diagonal=(0.15, 0.27, 0.2), position=(0, 0.25 + 0.5 * i, 0),
            linear_damping=0, shape=mw.ShapeSettings(type=mw.ShapeType.BOX, half_extents=half)))
    scene.add_body(mw.BodySettings(name="ball", mass=1.0, position=(0.1, 1.2, -0.1), linear_damping=0,
                                   shape=mw.ShapeSettings(type=mw.ShapeType.SPHERE, radius=0.2)))
    batch = mw.Batch(scene, WORLDS)
    # Slots in body order: ground with each (3), lower-upper, lower-ball, upper-ball.
    assert batch.num_contact_slots == 6
    assert [batch.contact_slot(i) for i in range(6)] == [
        (0, 1, 4), (0, 2, 4), (0, 3, 1), (1, 2, 4), (1, 3, 1), (2, 3, 1)]
    for _ in range(120):
        batch.step(mw.StepSettings())
    state = batch.get_state()
    # At rest within the 2 cm slop of each contact below (speculative contacts
    # land them on the surface; the slop bounds what the solver leaves).
    np.testing.assert_allclose(state[:, 1, 1], 0.25, atol=0.02)
    np.testing.assert_allclose(state[:, 2, 1], 0.75, atol=0.04)
    np.testing.assert_allclose(state[:, 3, 1], 1.2, atol=0.06)
    contacts = batch.get_contacts()
    g = 9.81
    # Normal forces: the ground carries all 5 kg, the boxes' contact 3 kg, the
    # ball's 1 kg; within 1 % (10 velocity iterations on a resting stack).
    np.testing.assert_allclose(contacts[:, 0, 1], 5 * g, rtol=1e-2)
    np.testing.assert_allclose(contacts[:, 3, 1], 3 * g, rtol=1e-2)
    np.testing.assert_allclose(contacts[:, 5, 1], 1 * g, rtol=1e-2)
    assert np.all(contacts[:, 3, 0] == 4) and np.all(contacts[:, 5, 0] == 1)
