"""Recorder and load_recording (docs/recording.md): the file numpy.load reads
directly holds what get_state and get_joint_coordinates said, frame by frame,
and the bodies' collision shapes; a file without the shapes (older) still
loads; errors leave no file behind."""

import math
import os

import numpy as np
import pytest

import manyworlds as mw


def record_ragdoll(path, worlds=(2, 0), steps=10):
    batch = mw.Batch(mw.make_scene("ragdoll"), 4)
    settings = mw.StepSettings()
    states, coordinates = [], []
    with mw.Recorder(batch, path, worlds, scene="ragdoll") as recorder:
        for step in range(steps + 1):
            if step:
                batch.step(settings)
            recorder.capture(batch, time=step * settings.delta_time, step=step)
            states.append(batch.get_state())
            coordinates.append(batch.get_joint_coordinates())
        assert not os.path.exists(path)  # only when the block ends
    return batch, np.array(states), np.array(coordinates)


def test_numpy_reads_the_frames_bit_for_bit(tmp_path):
    path = tmp_path / "ragdoll.npz"
    batch, states, coordinates = record_ragdoll(path)
    with np.load(path, allow_pickle=False) as data:
        assert data["format_version"].tolist() == [1]
        assert str(data["scene"]) == "ragdoll"
        assert data["world"].tolist() == [2, 0]
        assert data["step"].tolist() == list(range(11))
        worlds = [2, 0]
        # Bits, not values: view the floats as integers.
        assert np.array_equal(data["position"].view(np.uint32),
                              states[:, worlds, :, 0:3].view(np.uint32))
        assert np.array_equal(data["rotation"].view(np.uint32),
                              states[:, worlds, :, 3:7].view(np.uint32))
        assert np.array_equal(data["joint_coordinates"].view(np.uint32),
                              coordinates[:, worlds, :].view(np.uint32))
        assert data["health"].shape == (11, 2) and not data["health"].any()
        assert data["body_name"].tolist()[:3] == ["pelvis", "chest", "head"]
        assert data["constraint_type"][0] == "swing_twist"
        assert data["joint_coordinate_name"].shape == (batch.joint_coordinates_per_world,)
        # The ragdoll's bodies have no collision shape.
        assert data["body_shape_type"].tolist() == [0] * 11


def test_load_recording_checks_and_names_arrays(tmp_path):
    path = tmp_path / "ragdoll.npz"
    record_ragdoll(path, worlds=[1])
    recording = mw.load_recording(path)
    assert recording.scene == "ragdoll"
    assert (recording.num_frames, recording.num_worlds, recording.num_bodies) == (11, 1, 11)
    assert recording.position.shape == (11, 1, 11, 3)
    assert recording["rotation"].shape == (11, 1, 11, 4)

    # A file that numpy.savez writes with one array of a wrong shape.
    arrays = dict(recording.arrays)
    arrays["health"] = np.zeros((3, 1), np.uint8)
    bad = tmp_path / "bad.npz"
    np.savez(bad, **arrays)
    with pytest.raises(ValueError, match="health"):
        mw.load_recording(bad)
    arrays = dict(recording.arrays, format_version=np.array([2], np.int32))
    np.savez(bad, **arrays)
    with pytest.raises(ValueError, match="format_version"):
        mw.load_recording(bad)


def test_what_numpy_savez_writes_loads_too(tmp_path):
    # The format is numpy's own: a recording re-saved by numpy.savez loads the same.
    path = tmp_path / "ragdoll.npz"
    record_ragdoll(path)
    with np.load(path) as data:
        np.savez(tmp_path / "copy.npz", **{name: data[name] for name in data.files})
    again = mw.load_recording(tmp_path / "copy.npz")
    assert np.array_equal(again.position, mw.load_recording(path).position)


def shapes_scene():
    """A body of every ShapeType (in enum order, none last), with values in
    the fields a type does not use: those are recorded as 0."""
    scene = mw.Scene()
    scene.add_body(mw.BodySettings(
        name="ground", motion_type=mw.MotionType.STATIC, position=(0, -0.5, 0),
        shape=mw.ShapeSettings(type=mw.ShapeType.PLANE, position=(0, 0.25, 0),
                               rotation=(0.0998334, 0, 0, 0.9950042), radius=3.0)))
    scene.add_body(mw.BodySettings(
        name="ball", position=(0, 1, 0),
        shape=mw.ShapeSettings(type=mw.ShapeType.SPHERE, radius=0.25, half_height=4.0)))
    scene.add_body(mw.BodySettings(
        name="rod", position=(1, 1, 0),
        shape=mw.ShapeSettings(type=mw.ShapeType.CAPSULE, radius=0.1, half_height=0.4,
                               position=(0.1, 0.2, -0.3), rotation=(0, 0, 0.7071068, 0.7071068))))
    scene.add_body(mw.BodySettings(
        name="crate", position=(-1, 1, 0),
        shape=mw.ShapeSettings(type=mw.ShapeType.BOX, half_extents=(0.3, 0.2, 0.1),
                               rotation=(0, 0.3826834, 0, 0.9238795))))
    scene.add_body(mw.BodySettings(
        name="ghost", position=(0, 3, 0),
        shape=mw.ShapeSettings(radius=0.7, position=(1, 2, 3), rotation=(0, 1, 0, 0))))
    return scene


def test_shapes_are_recorded(tmp_path):
    scene = shapes_scene()
    batch = mw.Batch(scene, 2)
    path = tmp_path / "shapes.npz"
    with mw.Recorder(batch, path, [1], scene="shapes") as recorder:
        recorder.capture(batch, 0.0, 0)
    f32 = lambda values: np.array(values, np.float32)  # noqa: E731
    with np.load(path, allow_pickle=False) as data:
        assert data["body_shape_type"].dtype == np.uint8
        assert data["body_shape_type"].tolist() == [4, 1, 2, 3, 0]
        size = data["body_shape_size"]
        assert size.dtype == np.float32 and size.shape == (5, 5)
        # Bit for bit the settings' floats (float32 in the bindings too).
        assert np.array_equal(size.view(np.uint32), f32([
            [0, 0, 0, 0, 0], [0.25, 0, 0, 0, 0], [0.1, 0.4, 0, 0, 0], [0, 0, 0.3, 0.2, 0.1],
            [0, 0, 0, 0, 0]]).view(np.uint32))
        assert np.array_equal(data["body_shape_position"].view(np.uint32), f32([
            [0, 0.25, 0], [0, 0, 0], [0.1, 0.2, -0.3], [0, 0, 0], [0, 0, 0]]).view(np.uint32))
        # Rotations normalised as the step normalises them: in double, then
        # rounded to float32 (the settings' floats are of length 1 only to
        # float rounding).
        def normalised(q):
            q = [float(x) for x in f32(q)]
            length = math.sqrt(((q[0] * q[0] + q[1] * q[1]) + q[2] * q[2]) + q[3] * q[3])
            return [x / length for x in q]
        assert np.array_equal(data["body_shape_rotation"].view(np.uint32), f32([
            normalised(q) for q in ([0.0998334, 0, 0, 0.9950042], [0, 0, 0, 1],
                                    [0, 0, 0.7071068, 0.7071068],
                                    [0, 0.3826834, 0, 0.9238795], [0, 0, 0, 1])]).view(np.uint32))
    recording = mw.load_recording(path)
    assert recording.has_shapes
    assert recording.body_shape_type.tolist() == [4, 1, 2, 3, 0]
    assert recording["body_shape_size"].shape == (5, 5)
    for b, body in enumerate(scene.bodies):
        assert recording.body_shape_type[b] == int(body.shape.type)


def test_a_contact_scene_records_its_shapes(tmp_path):
    batch = mw.Batch(mw.make_scene("box-stack"), 1)
    with mw.Recorder(batch, tmp_path / "stack.npz", [0], scene="box-stack") as recorder:
        recorder.capture(batch, 0.0, 0)
    recording = mw.load_recording(tmp_path / "stack.npz")
    assert recording.body_shape_type.tolist() == [int(mw.ShapeType.PLANE)] + \
        [int(mw.ShapeType.BOX)] * 5
    assert np.allclose(recording.body_shape_size[1:, 2:], [0.4, 0.25, 0.3])


def test_a_file_without_shapes_loads(tmp_path):
    # What the writer made before shapes were recorded: the same format 1
    # without the body_shape_* arrays. Every body then has no shape.
    path = tmp_path / "ragdoll.npz"
    record_ragdoll(path)
    with np.load(path) as data:
        old = {name: data[name] for name in data.files if not name.startswith("body_shape_")}
    np.savez(tmp_path / "old.npz", **old)
    recording = mw.load_recording(tmp_path / "old.npz")
    assert not recording.has_shapes
    assert "body_shape_type" not in recording.arrays
    bodies = recording.num_bodies
    assert recording.body_shape_type.tolist() == [0] * bodies
    assert recording["body_shape_type"].dtype == np.uint8
    assert recording.body_shape_size.shape == (bodies, 5) and not recording.body_shape_size.any()
    assert recording.body_shape_position.shape == (bodies, 3)
    assert recording.body_shape_rotation.tolist() == [[0, 0, 0, 1]] * bodies
    assert np.array_equal(recording.position, mw.load_recording(path).position)

    # Some of the shape arrays but not all: refused, naming the missing ones.
    np.savez(tmp_path / "part.npz", **old, body_shape_type=np.zeros(bodies, np.uint8))
    with pytest.raises(ValueError, match="body_shape_size"):
        mw.load_recording(tmp_path / "part.npz")
    # A shape array of a wrong shape or dtype: refused like any other.
    with np.load(path) as data:
        arrays = {name: data[name] for name in data.files}
    arrays["body_shape_size"] = np.zeros((bodies, 4), np.float32)
    np.savez(tmp_path / "bad.npz", **arrays)
    with pytest.raises(ValueError, match="body_shape_size"):
        mw.load_recording(tmp_path / "bad.npz")
    arrays["body_shape_size"] = np.zeros((bodies, 5), np.float64)
    np.savez(tmp_path / "bad.npz", **arrays)
    with pytest.raises(ValueError, match="body_shape_size"):
        mw.load_recording(tmp_path / "bad.npz")


def test_an_exception_leaves_no_file(tmp_path):
    batch = mw.Batch(mw.make_scene("cartpole"), 2)
    with pytest.raises(KeyError):
        with mw.Recorder(batch, tmp_path / "never.npz", [0]) as recorder:
            recorder.capture(batch, 0.0, 0)
            raise KeyError("stop")
    assert os.listdir(tmp_path) == []


def test_refusals(tmp_path):
    batch = mw.Batch(mw.make_scene("cartpole"), 2)
    with pytest.raises(IndexError, match="world 2"):
        mw.Recorder(batch, tmp_path / "a.npz", [0, 2])
    with pytest.raises(ValueError, match="twice"):
        mw.Recorder(batch, tmp_path / "a.npz", [1, 1])
    with pytest.raises(ValueError, match="no world"):
        mw.Recorder(batch, tmp_path / "a.npz", [])
    with pytest.raises(RuntimeError, match="missing"):
        mw.Recorder(batch, tmp_path / "missing" / "a.npz", [0])
    assert os.listdir(tmp_path) == []
    (tmp_path / "a.npz").write_bytes(b"")
    with pytest.raises(FileExistsError):
        mw.Recorder(batch, tmp_path / "a.npz", [0])
    with mw.Recorder(batch, tmp_path / "a.npz", [0], overwrite=True) as recorder:
        recorder.capture(batch, 0.0, 0)
    assert mw.load_recording(tmp_path / "a.npz").num_frames == 1
    recorder = mw.Recorder(batch, tmp_path / "b.npz", [0])
    recorder.close()
    with pytest.raises(RuntimeError):
        recorder.capture(batch, 0.0, 0)
