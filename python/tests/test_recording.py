"""Recorder and load_recording (docs/recording.md): the file numpy.load reads
directly holds what get_state and get_joint_coordinates said, frame by frame;
errors leave no file behind."""

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
