"""Batch from Python: stepping, state arrays, actions, resets, snapshots,
health and reports, compared bit for bit where the C++ library promises bits."""

import pickle
import threading

import numpy as np
import pytest

import manyworlds as mw
from conftest import (WORLDS, assert_same_bits, bits, motor_hinge_scene, random_cart_forces)

CART, POLE = mw.reference_scene.CART, mw.reference_scene.POLE
RAIL, POLE_HINGE = mw.reference_scene.RAIL, mw.reference_scene.POLE_HINGE


def step_with_forces(batch, forces_per_step, settings=None):
    for forces in forces_per_step:
        batch.set_body_forces(CART, forces)
        batch.step(settings if settings is not None else mw.StepSettings())


def test_properties(cartpole):
    assert (cartpole.num_worlds, cartpole.num_bodies, cartpole.num_constraints) == (WORLDS, 3, 2)
    assert cartpole.simd_target == mw.dispatched_target()
    assert cartpole.simd_lanes >= 1 and cartpole.bytes_per_world > 0 and cartpole.threads >= 1
    assert cartpole.scene.bodies == mw.make_scene("cartpole").bodies
    assert "pole hinge" in cartpole.plan()
    assert repr(cartpole).startswith(f"Batch({WORLDS} worlds, 3 bodies, 2 constraints")
    assert mw.Batch(mw.make_scene("cartpole"), 16, threads=1).threads == 1
    assert mw.Batch(mw.make_scene("cartpole"), 16, mw.BatchOptions(threads=1)).threads == 1


def test_state_arrays(cartpole):
    state = cartpole.get_state()
    assert state.shape == (WORLDS, 3, 13) and state.dtype == np.float32
    scene = mw.make_scene("cartpole")
    for body_index, body in enumerate(scene.bodies):
        np.testing.assert_allclose(state[:, body_index, 0:3], np.tile(body.position, (WORLDS, 1)))
        np.testing.assert_allclose(state[:, body_index, 3:7], np.tile(body.rotation, (WORLDS, 1)))
    cartpole.step()
    out = np.full((WORLDS, 3, 13), np.nan, np.float32)
    assert cartpole.get_state(out=out) is out
    assert_same_bits(out, cartpole.get_state())
    for field in mw.StateField.__members__.values():
        offset, size = mw.state_field_offset(field), mw.state_field_size(field)
        values = cartpole.get_field(field)
        assert values.shape == (WORLDS, 3, size)
        assert_same_bits(values, out[:, :, offset:offset + size])


def test_set_state_round_trip_changes_no_bit(cartpole):
    rng = np.random.default_rng(0)
    step_with_forces(cartpole, [random_cart_forces(rng, WORLDS) for _ in range(5)])
    before = cartpole.get_state()
    cartpole.set_state(before)
    assert_same_bits(cartpole.get_state(), before)
    # With a mask only the masked worlds take the new state.
    moved = before.copy()
    moved[:, :, 7:10] += 1.0
    moved[:, 0, 7:10] = 0.0  # the static world body stays at rest anyway
    mask = np.zeros(WORLDS, bool)
    mask[[2, 17]] = True
    cartpole.set_state(moved, mask)
    after = cartpole.get_state()
    assert_same_bits(after[mask], moved[mask])
    assert_same_bits(after[~mask], before[~mask])
    velocities = cartpole.get_field(mw.StateField.LINEAR_VELOCITY)
    velocities[:, 1, 0] = 2.5
    cartpole.set_field(mw.StateField.LINEAR_VELOCITY, velocities)
    assert np.all(cartpole.get_state()[:, 1, 7] == np.float32(2.5))


def test_same_actions_give_the_same_bits():
    rng = np.random.default_rng(2)
    forces = [random_cart_forces(rng, WORLDS) for _ in range(100)]
    scene = mw.make_scene("cartpole")
    batches = [mw.Batch(scene, WORLDS), mw.Batch(scene, WORLDS, threads=1),
               mw.Batch(scene, WORLDS, threads=2, blocks_per_task=1)]
    for batch in batches:
        step_with_forces(batch, forces)
    for batch in batches[1:]:
        assert_same_bits(batch.get_state(), batches[0].get_state())


def test_numpy_actions_match_the_cpp_scene_actions():
    scene = mw.make_scene("cartpole")
    from_cpp, from_numpy = mw.Batch(scene, WORLDS), mw.Batch(scene, WORLDS)
    actions = mw.SceneActions("cartpole")
    worlds = np.arange(WORLDS)
    for step in range(60):
        actions.apply(from_cpp, step, 7)
        forces = np.zeros((WORLDS, 3), np.float32)
        forces[:, 0] = [mw.cartpole_force(7, w, step) for w in worlds]
        from_numpy.set_body_forces(CART, forces)
        from_cpp.step()
        from_numpy.step()
    assert_same_bits(from_cpp.get_state(), from_numpy.get_state())


def test_whole_force_array_equals_per_body_form():
    rng = np.random.default_rng(3)
    scene = mw.make_scene("cartpole")
    per_body, whole = mw.Batch(scene, WORLDS), mw.Batch(scene, WORLDS)
    for _ in range(20):
        forces, torques = random_cart_forces(rng, WORLDS), random_cart_forces(rng, WORLDS)
        per_body.set_body_forces(CART, forces)
        per_body.set_body_torques(mw.reference_scene.POLE, torques)
        all_forces = np.zeros((WORLDS, 3, 3), np.float32)
        all_torques = np.zeros((WORLDS, 3, 3), np.float32)
        all_forces[:, CART] = forces
        all_torques[:, mw.reference_scene.POLE] = torques
        whole.set_forces(all_forces)
        whole.set_torques(all_torques)
        per_body.step()
        whole.step()
    assert_same_bits(per_body.get_state(), whole.get_state())


def test_motor_targets_drive_the_hinge():
    batch = mw.Batch(motor_hinge_scene(mw.MotorState.VELOCITY), WORLDS)
    targets = np.linspace(-2, 2, WORLDS).astype(np.float32)
    for _ in range(30):
        batch.set_target_velocities(0, targets)
        batch.step(mw.StepSettings(gravity=(0, 0, 0)))
    spin = batch.get_field(mw.StateField.ANGULAR_VELOCITY)[:, 1, 2]
    np.testing.assert_allclose(spin, targets, atol=1e-3)
    for _ in range(30):
        batch.set_target_velocities(0, 0.5)  # one number for every world
        batch.step(mw.StepSettings(gravity=(0, 0, 0)))
    np.testing.assert_allclose(batch.get_field(mw.StateField.ANGULAR_VELOCITY)[:, 1, 2], 0.5,
                               atol=1e-3)

    batch = mw.Batch(motor_hinge_scene(mw.MotorState.POSITION), WORLDS)
    angles = np.linspace(-1, 1, WORLDS).astype(np.float32)
    for _ in range(300):
        batch.set_target_positions(0, angles)
        batch.step(mw.StepSettings(gravity=(0, 0, 0)))
    rotation = batch.get_field(mw.StateField.ROTATION)[:, 1]
    np.testing.assert_allclose(2 * np.arctan2(rotation[:, 2], rotation[:, 3]), angles, atol=1e-2)


def test_joint_coordinates(cartpole):
    rail, hinge = mw.reference_scene.RAIL, mw.reference_scene.POLE_HINGE
    names = cartpole.joint_coordinate_names(hinge)
    assert names[:3] == ["angle", "unwrapped_angle", "angular_velocity"]
    assert cartpole.joint_coordinate_count(hinge) == len(names)
    angles = cartpole.get_joint_coordinates(hinge)
    assert angles.shape == (WORLDS, len(names)) and angles.dtype == np.float32
    np.testing.assert_allclose(angles[:, 0], 0.1, atol=1e-6)  # the pole starts 0.1 rad off
    for _ in range(20):
        cartpole.step()
    # The hinge angle is the pole's rotation about Z (the cart does not turn).
    rotation = cartpole.get_field(mw.StateField.ROTATION)[:, mw.reference_scene.POLE]
    angle = 2 * np.arctan2(rotation[:, 2], rotation[:, 3])
    np.testing.assert_allclose(cartpole.get_joint_coordinates(hinge)[:, 0], angle, atol=1e-5)
    # Every constraint's coordinates together, in scene order; out= fills an array.
    every = np.empty((WORLDS, cartpole.joint_coordinates_per_world), np.float32)
    assert cartpole.get_joint_coordinates(out=every) is every
    parts = [cartpole.get_joint_coordinates(c) for c in (rail, hinge)]
    assert_same_bits(every, np.concatenate(parts, axis=1))


def test_motor_forces_saturate_at_their_limit():
    batch = mw.Batch(motor_hinge_scene(mw.MotorState.VELOCITY), WORLDS)
    assert batch.motor_force_count(0) == 1
    targets = np.where(np.arange(WORLDS) % 2 == 0, 50.0, -50.0).astype(np.float32)
    batch.set_target_velocities(0, targets)  # far beyond what 5 N m reach in a step
    batch.step(mw.StepSettings(gravity=(0, 0, 0)))
    torques = batch.get_motor_forces(0)
    assert torques.shape == (WORLDS, 1)
    np.testing.assert_allclose(torques[:, 0], np.sign(targets) * 5.0, rtol=1e-5)


def test_reset_changes_only_masked_worlds(cartpole):
    initial = cartpole.get_state()
    rng = np.random.default_rng(4)
    step_with_forces(cartpole, [random_cart_forces(rng, WORLDS) for _ in range(30)])
    stepped = cartpole.get_state()
    mask = np.zeros(WORLDS, np.uint8)
    mask[[0, 15, 16, 63]] = 1
    cartpole.reset(mask)
    after = cartpole.get_state()
    selected = mask.astype(bool)
    assert_same_bits(after[selected], initial[selected])
    assert_same_bits(after[~selected], stepped[~selected])
    cartpole.reset()  # every world
    assert_same_bits(cartpole.get_state(), initial)

    target = stepped.copy()
    cartpole.reset_to(mask, target)
    after = cartpole.get_state()
    assert_same_bits(after[selected], target[selected])
    assert_same_bits(after[~selected], initial[~selected])


def test_a_world_given_anothers_state_and_solver_state_continues_as_it(cartpole):
    rng = np.random.default_rng(3)
    step_with_forces(cartpole, [random_cart_forces(rng, WORLDS) for _ in range(10)])
    assert cartpole.solver_state_size == 16  # slider 7, hinge 9 (docs/stepping.md)
    source, copy = 1, WORLDS - 1
    impulses = cartpole.get_solver_state(source)
    assert impulses.shape == (16,) and impulses.dtype == np.float32
    assert not np.array_equal(impulses, cartpole.get_solver_state(copy))
    state = cartpole.get_state()
    state[copy] = state[source]
    cartpole.set_state(state)
    cartpole.set_solver_state(copy, impulses)
    forces = [random_cart_forces(rng, WORLDS) for _ in range(10)]
    for step_forces in forces:
        step_forces[copy] = step_forces[source]
    step_with_forces(cartpole, forces)
    after = cartpole.get_state()
    assert_same_bits(after[copy], after[source])
    out = np.zeros(16, np.float32)
    assert cartpole.get_solver_state(copy, out=out) is out
    assert_same_bits(out, cartpole.get_solver_state(source))
    bad = impulses.copy()
    bad[8] = np.nan  # the pole hinge's point impulse
    with pytest.raises(ValueError, match="pole hinge.*point impulse"):
        cartpole.set_solver_state(copy, bad)
    with pytest.raises(ValueError):
        cartpole.set_solver_state(copy, impulses[:15])
    with pytest.raises((IndexError, ValueError)):
        cartpole.get_solver_state(WORLDS)


def test_velocity_tolerance_stops_each_world_on_its_own():
    """A tolerance above every pass's change stops every world after one
    velocity pass: the same bits as velocity_iterations=1. A tolerance of
    1e-3 m/s runs more passes than that and stays near the default's ten:
    each of the passes it leaves out changes a cartpole's velocities by less
    than 1e-3 m/s, and they shrink about tenfold per pass, so over 20 steps of
    1/60 s the positions part by less than 20 x 1.2e-3 / 60 = 4e-4 m (measured:
    2.7e-6 m). Bad tolerances are refused naming the field, and a refused
    step changes nothing."""
    rng = np.random.default_rng(5)
    forces = [random_cart_forces(rng, WORLDS) for _ in range(20)]
    scene = mw.make_scene("cartpole")
    one, loose, default, tolerant = (mw.Batch(scene, WORLDS, threads=1) for _ in range(4))
    step_with_forces(one, forces, mw.StepSettings(velocity_iterations=1))
    step_with_forces(loose, forces, mw.StepSettings(velocity_tolerance=1e30))
    step_with_forces(default, forces, mw.StepSettings())
    step_with_forces(tolerant, forces, mw.StepSettings(velocity_tolerance=1e-3))
    assert_same_bits(loose.get_state(), one.get_state())
    assert not np.array_equal(tolerant.get_state(), one.get_state())
    positions = (slice(None), slice(None), slice(0, 3))
    assert np.max(np.abs(tolerant.get_state()[positions] - default.get_state()[positions])) < 4e-4
    before = default.get_state()
    for bad in (-1.0, np.nan, np.inf):
        with pytest.raises(mw.SceneError, match="velocity_tolerance"):
            default.step(mw.StepSettings(velocity_tolerance=bad))
    assert_same_bits(default.get_state(), before)


def test_snapshot_restore_is_exact(cartpole):
    rng = np.random.default_rng(5)
    first = [random_cart_forces(rng, WORLDS) for _ in range(10)]
    then = [random_cart_forces(rng, WORLDS) for _ in range(10)]
    step_with_forces(cartpole, first)
    snapshot = cartpole.snapshot()
    assert snapshot.num_worlds == WORLDS and not snapshot.empty
    saved = cartpole.get_state()
    step_with_forces(cartpole, then)
    continued = cartpole.get_state()

    cartpole.restore(snapshot)
    assert_same_bits(cartpole.get_state(), saved)
    step_with_forces(cartpole, then)  # warm starts come back too: the same bits
    assert_same_bits(cartpole.get_state(), continued)

    for copy in (mw.Batch.Snapshot.from_bytes(snapshot.bytes()),
                 mw.BatchSnapshot.from_bytes(bytearray(snapshot.bytes())),
                 pickle.loads(pickle.dumps(snapshot))):
        assert copy.bytes() == snapshot.bytes()
        cartpole.restore(copy)
        assert_same_bits(cartpole.get_state(), saved)

    mask = np.zeros(WORLDS, bool)
    mask[3] = True
    step_with_forces(cartpole, then)
    cartpole.restore(snapshot, mask)
    after = cartpole.get_state()
    assert_same_bits(after[3], saved[3])
    assert_same_bits(after[4], continued[4])


def test_nan_actions_flag_their_world_only(cartpole):
    clean = mw.Batch(mw.make_scene("cartpole"), WORLDS)
    forces = np.zeros((WORLDS, 3), np.float32)
    forces[9, 0] = np.nan  # actions are never refused: the world is flagged
    cartpole.set_body_forces(CART, forces)
    clean.set_body_forces(CART, np.zeros((WORLDS, 3), np.float32))
    cartpole.step()
    clean.step()
    health = cartpole.health
    assert health.dtype == np.uint8 and health.shape == (WORLDS,)
    assert health[9] & mw.WorldHealthBits.NON_FINITE_INPUT
    assert np.count_nonzero(health) == 1 and cartpole.unhealthy_world_count == 1
    others = np.arange(WORLDS) != 9
    assert_same_bits(cartpole.get_state()[others], clean.get_state()[others])
    # Step settings may reset flagged worlds.
    cartpole.set_body_forces(CART, forces)
    cartpole.step(mw.StepSettings(unhealthy_worlds=mw.UnhealthyWorlds.RESET))
    initial = mw.Batch(mw.make_scene("cartpole"), 16).get_state()
    assert_same_bits(cartpole.get_state()[9], initial[9])


def test_per_world_parameters_change_only_their_worlds():
    scene = mw.make_scene("cartpole")
    batch, clean = mw.Batch(scene, WORLDS), mw.Batch(scene, WORLDS)
    pole = mw.reference_scene.POLE
    weightless = np.zeros(WORLDS, bool)
    weightless[[1, 20, 40]] = True
    batch.set_gravity_factor(pole, 0.0, mask=weightless)
    masses = np.full(WORLDS, scene.bodies[pole].mass, np.float32)
    masses[5] = 0.3  # every other world gets the scene's own mass: the same bits
    batch.set_mass_properties(pole, masses, scene.bodies[pole].inertia_diagonal)
    batch.set_damping(CART, 0.5, 0.5, mask=np.zeros(WORLDS, bool))  # no world selected
    for _ in range(30):
        batch.step()
        clean.step()
    changed = weightless.copy()
    changed[5] = True
    state, clean_state = batch.get_state(), clean.get_state()
    assert_same_bits(state[~changed], clean_state[~changed])
    for world in np.flatnonzero(changed):
        assert not np.array_equal(bits(state[world]), bits(clean_state[world])), world
    # A reset puts the scene's parameters back.
    batch.reset()
    clean.reset()
    for _ in range(30):
        batch.step()
        clean.step()
    assert_same_bits(batch.get_state(), clean.get_state())


def test_constraint_errors(cartpole):
    cartpole.step()
    errors = cartpole.max_constraint_errors()
    assert errors.shape == (WORLDS,) and errors.dtype == np.float32
    assert errors[5] == np.float32(cartpole.max_constraint_error(5))
    linear, angular = cartpole.max_constraint_error_split(5)
    assert linear >= 0 and angular >= 0
    assert np.float32(max(linear, angular)) == errors[5]
    assert cartpole.constraint_error(5, 1) >= 0 and cartpole.constraint_velocity_error(5, 1) >= 0


@pytest.mark.parametrize("fused", [False, True])
def test_step_releases_the_gil_and_concurrent_use_raises(fused):
    """A step on one thread runs while Python goes on on another; a call on
    the same Batch from that other thread meanwhile raises RuntimeError.
    The same with the fused step's resets and outputs."""
    batch = mw.Batch(mw.make_scene("chain64"), 4096, threads=1)
    slow = mw.StepSettings(velocity_iterations=200, substeps=4)
    started, done = threading.Event(), threading.Event()
    errors = []
    out = np.empty((4096, batch.num_bodies, 13), np.float32)
    outputs = {}
    if fused:
        outputs = {"reset_mask": np.arange(4096) % 7 == 0,
                   "state_out": np.empty_like(out),
                   "joints_out": np.empty((4096, batch.joint_coordinates_per_world), np.float32)}

    def step():
        started.set()
        try:
            batch.step(slow, **outputs)
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)
        done.set()

    thread = threading.Thread(target=step)
    thread.start()
    started.wait()
    refused = None
    while not done.is_set():  # only reachable while stepping if the GIL is free
        try:
            batch.get_state(out=out)
        except RuntimeError as error:
            refused = error
            break
    thread.join()
    assert not errors, errors
    assert refused is not None, "the step ended before the other thread could run"
    assert "thread" in str(refused)
    batch.get_state(out=out)  # fine again afterwards


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("with_states", [False, True])
def test_fused_step_gives_the_bits_of_separate_calls(threads, with_states):
    """step(reset_mask=, reset_states=, state_out=, joints_out=) equals step();
    reset(mask) or reset_to(mask, states); get_state(); get_joint_coordinates()
    bit for bit, step after step (1040 worlds: enough blocks for threads)."""
    worlds = 1040
    scene = mw.make_scene("cartpole")
    separate = mw.Batch(scene, worlds, threads=threads)
    fused = mw.Batch(scene, worlds, threads=threads)
    rng = np.random.default_rng(5)
    state_out = np.empty((worlds, 3, 13), np.float32)
    joints_out = np.empty((worlds, fused.joint_coordinates_per_world), np.float32)
    for step in range(20):
        forces = random_cart_forces(rng, worlds)
        done = rng.random(worlds) < 0.1
        states = separate.get_state()
        states[:, :, 0] += np.float32(0.01)
        for batch in (separate, fused):
            batch.set_body_forces(CART, forces)
        separate.step()
        if with_states:
            separate.reset_to(done, states)
            fused.step(reset_mask=done, reset_states=states, state_out=state_out,
                       joints_out=joints_out)
        else:
            separate.reset(done)
            fused.step(reset_mask=done, state_out=state_out, joints_out=joints_out)
        assert_same_bits(state_out, separate.get_state())
        assert_same_bits(joints_out, separate.get_joint_coordinates())
        np.testing.assert_array_equal(fused.health, separate.health)
    assert fused.snapshot().bytes() == separate.snapshot().bytes()


def test_fused_step_resets_after_the_step_for_autoreset(cartpole):
    """The worlds in reset_mask are observed at their initial state (the new
    episode's first observation), as Gymnasium's next-step autoreset wants."""
    initial = cartpole.get_state()
    for _ in range(5):
        cartpole.step()
    done = np.zeros(WORLDS, bool)
    done[[3, 40]] = True
    state_out = np.empty_like(initial)
    cartpole.step(reset_mask=done, state_out=state_out)
    assert_same_bits(state_out[done], initial[done])
    assert not np.array_equal(bits(state_out[~done]), bits(initial[~done]))


def test_fused_step_flags_a_nan_world_and_no_other():
    """A NaN action in world 9 under the fused step: world 9 is flagged, every
    other world's observation has the bits of a clean batch; resetting world 9
    in a later step clears its flag."""
    scene = mw.make_scene("cartpole")
    clean, dirty = mw.Batch(scene, WORLDS), mw.Batch(scene, WORLDS)
    rng = np.random.default_rng(2)
    obs_clean, obs_dirty = (np.empty((WORLDS, 3, 13), np.float32) for _ in range(2))
    no_reset, reset_9 = np.zeros(WORLDS, bool), np.zeros(WORLDS, bool)
    reset_9[9] = True
    others = np.arange(WORLDS) != 9
    for step in range(5):
        forces = random_cart_forces(rng, WORLDS)
        clean.set_body_forces(CART, forces)
        if step == 1:
            forces[9, 0] = np.nan
        dirty.set_body_forces(CART, forces)
        clean.step(reset_mask=no_reset, state_out=obs_clean)
        dirty.step(reset_mask=reset_9 if step == 3 else no_reset, state_out=obs_dirty)
        assert_same_bits(obs_dirty[others], obs_clean[others])
        assert not dirty.health[others].any()
        if step == 1:
            assert dirty.health[9] & mw.WorldHealthBits.NON_FINITE_INPUT
    assert dirty.health[9] == 0 and np.isfinite(obs_dirty[9]).all()


@pytest.mark.parametrize("threads", [1, 2])
def test_fused_actions_give_the_bits_of_separate_calls(threads):
    """step(body_forces=, body_torques=, target_velocities=, target_positions=)
    equals set_body_forces, set_body_torques, set_target_velocities,
    set_target_positions, then step(), bit for bit (targets beyond the limits
    clamped alike; a NaN force flags its world alike), with resets and reads
    in the same call."""
    worlds = 1040
    scene = mw.make_scene("cartpole")
    rail = scene.constraints[RAIL]
    rail.limits_min, rail.limits_max = -0.5, 0.5
    rail.motor_state = mw.MotorState.POSITION
    scene.set_constraint(RAIL, rail)
    hinge = scene.constraints[POLE_HINGE]
    hinge.motor_state = mw.MotorState.VELOCITY
    hinge.motor.min_force_limit, hinge.motor.max_force_limit = -2.0, 2.0
    scene.set_constraint(POLE_HINGE, hinge)
    separate = mw.Batch(scene, worlds, threads=threads)
    fused = mw.Batch(scene, worlds, threads=threads)
    rng = np.random.default_rng(8)
    state_out = np.empty((worlds, 3, 13), np.float32)
    for step in range(12):
        forces = random_cart_forces(rng, worlds)
        if step == 2:
            forces[17, 0] = np.nan
        torques = rng.uniform(-1, 1, (worlds, 3)).astype(np.float32)
        positions = rng.uniform(-1, 1, worlds).astype(np.float32)
        velocity = float(rng.uniform(-3, 3))  # one number for every world
        done = rng.random(worlds) < 0.05
        done[17] = False
        separate.set_body_forces(CART, forces)
        separate.set_body_torques(POLE, torques)
        separate.set_target_velocities(POLE_HINGE, velocity)
        separate.set_target_positions(RAIL, positions)
        separate.step()
        separate.reset(done)
        # numpy integer keys work as indices do
        fused.step(body_forces={CART: forces}, body_torques={np.int64(POLE): torques},
                   target_velocities={POLE_HINGE: velocity}, target_positions={RAIL: positions},
                   reset_mask=done, state_out=state_out)
        assert_same_bits(state_out, separate.get_state())
        np.testing.assert_array_equal(fused.health, separate.health)
        assert fused.snapshot().bytes() == separate.snapshot().bytes()
        if step == 2:
            assert fused.health[17] & mw.WorldHealthBits.NON_FINITE_INPUT


def test_phase_profile_counts_every_phase_and_keeps_the_bits():
    """profile_phases=True times each phase of the step (phase_profile()) and
    changes no bit of the worlds; a plain batch's profile is all zero."""
    scene = mw.make_scene("cartpole")
    plain = mw.Batch(scene, WORLDS)
    profiled = mw.Batch(scene, WORLDS, profile_phases=True)
    for _ in range(4):
        plain.step()
        profiled.step()
    assert plain.snapshot().bytes() == profiled.snapshot().bytes()
    profile = profiled.phase_profile()
    assert list(profile["seconds"]) == ["forces", "setup", "warm_start", "velocity",
                                        "integration", "position", "finish"]
    assert all(seconds > 0 for seconds in profile["seconds"].values())
    assert profile["world_steps"] == 4 * WORLDS and profile["block_steps"] == 4 * WORLDS // 16
    assert plain.phase_profile()["world_steps"] == 0
    profiled.reset_phase_profile()
    assert sum(profiled.phase_profile()["seconds"].values()) == 0


def test_fused_drive_targets_give_the_bits_of_the_setters():
    """step(target_orientations=, target_angular_velocities=,
    target_translations=, target_linear_velocities=) equals the set_target_*
    calls of the same names, then step(), bit for bit."""
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(motion_type=mw.MotionType.STATIC))
    scene.add_body(mw.BodySettings(position=(1, 0, 0)))
    scene.add_body(mw.BodySettings(position=(-1, 0.5, 0)))
    scene.add_constraint(mw.SwingTwistConstraintSettings(
        body1=0, body2=1, normal_half_cone_angle=1.0, plane_half_cone_angle=1.0,
        twist_min_angle=-1.0, twist_max_angle=1.0, swing_motor_state=mw.MotorState.POSITION,
        twist_motor_state=mw.MotorState.POSITION))
    mount = mw.SixDofConstraintSettings(body1=0, body2=2)
    mount.motor_state = [mw.MotorState.VELOCITY] * 6
    scene.add_constraint(mount)
    separate, fused = mw.Batch(scene, WORLDS), mw.Batch(scene, WORLDS)
    rng = np.random.default_rng(4)
    for _ in range(6):
        q = rng.normal(size=(WORLDS, 4)).astype(np.float32)
        spin, move, speed = (rng.uniform(-1, 1, (WORLDS, 3)).astype(np.float32)
                             for _ in range(3))
        separate.set_target_orientations(0, q)
        separate.set_target_angular_velocities(0, spin)
        separate.set_target_translations(1, move)
        separate.set_target_linear_velocities(1, speed)
        separate.step()
        fused.step(target_orientations={0: q}, target_angular_velocities={0: spin},
                   target_translations={1: move}, target_linear_velocities={1: speed})
        assert fused.snapshot().bytes() == separate.snapshot().bytes()
    with pytest.raises(TypeError, match=r"target_orientations: expected a dict \{constraint: "
                                        r"float32 array \[world, 4\]\}"):
        fused.step(target_orientations=q)
    with pytest.raises(ValueError, match=r"target_translations\[1\]: expected shape"):
        fused.step(target_translations={1: q})


def test_exact_solve_closes_chain16_and_cartpole_joints_and_refuses_a_planar_pin():
    # The exact joint solve (docs/stepping.md): chain16's and cartpole's
    # joints within the tolerance after every step, where Gauss-Seidel leaves
    # centimetres; every constraint type steps (a cone's cone row and a
    # distance spring by Gauss-Seidel around the solve), the hopper's planar
    # torso too; a ball joint between the ground and a planar body (no
    # dynamic body with all six degrees of freedom: its out-of-plane rows
    # move nothing) is refused by name, before anything moves.
    settings = mw.StepSettings(solver=mw.JointSolver.EXACT, position_iterations=10)
    assert settings.exact_tolerance == pytest.approx(1e-5)
    for scene in ("chain16", "cartpole"):
        batch = mw.Batch(mw.make_scene(scene), 4, threads=1)
        for _ in range(60):
            batch.step(settings)
            assert batch.max_constraint_errors().max() <= settings.exact_tolerance + 2e-6
    for scene in ("singular-cone", "spring-0.5", "hopper"):
        batch = mw.Batch(mw.make_scene(scene), 4, threads=1)
        for _ in range(60):
            batch.step(settings)
        assert batch.unhealthy_world_count == 0
        assert np.isfinite(batch.get_state()).all()
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(motion_type=mw.MotionType.STATIC))
    scene.add_body(mw.BodySettings(name="planar slab", position=(1, 0, 0),
                                   allowed_dofs=mw.AllowedDofs.PLANE_2D))
    scene.add_constraint(mw.PointConstraintSettings(body1=0, body2=1, name="pin"))
    planar = mw.Batch(scene, 4, threads=1)
    before = planar.get_state()
    with pytest.raises(mw.SceneError, match="planar slab"):
        planar.step(settings)
    assert_same_bits(planar.get_state(), before)


def test_exact_curvature_velocity_is_on_by_default_and_keeps_chain16_energy():
    # The exact solve's curvature correction (docs/stepping.md): on by
    # default; chain16 released from horizontal keeps more of its energy
    # with it (docs/accuracy.md: 0.47 % of M g L lost in the first second
    # against 1.15 % without). The energy here is the chain's height and
    # speed summed over links of 1 kg (the inertia's share is small and the
    # same in both runs' scale), enough to tell the two apart.
    assert mw.StepSettings().exact_curvature_velocity

    def energy(state):
        position = state[0, 1:, 0:3]
        velocity = state[0, 1:, 7:10]
        return float(9.81 * position[:, 1].sum() + 0.5 * (velocity ** 2).sum())

    losses = {}
    for curvature in (True, False):
        settings = mw.StepSettings(solver=mw.JointSolver.EXACT, position_iterations=4,
                                   exact_curvature_velocity=curvature)
        batch = mw.Batch(mw.make_scene("chain16"), 1, threads=1)
        start = energy(batch.get_state())
        for _ in range(60):
            batch.step(settings)
        losses[curvature] = start - energy(batch.get_state())
    assert 0 < losses[True] < 0.6 * losses[False]


def test_make_chain_builds_the_chains_at_any_ratio_and_names_a_bad_argument():
    # make_chain(16, 100) is chain16-r100 body for body; a heavier chain holds
    # under the exact solve with 30 Newton steps (docs/accuracy.md, mass
    # ratios); bad arguments are refused by name.
    assert mw.make_chain(16, 100).bodies == mw.make_scene("chain16-r100").bodies
    assert mw.make_chain(64, 1).bodies == mw.make_scene("chain64").bodies
    settings = mw.StepSettings(solver=mw.JointSolver.EXACT, position_iterations=30)
    batch = mw.Batch(mw.make_chain(16, 1024), 4, threads=1)
    for _ in range(120):
        batch.step(settings)
    assert batch.max_constraint_errors().max() <= 0.01
    with pytest.raises(ValueError, match="links"):
        mw.make_chain(0, 1)
    with pytest.raises(ValueError, match="last_link_scale"):
        mw.make_chain(16, float("nan"))
