"""Recordings: chosen worlds of a Batch, frame by frame, in an NPZ file.

The format (docs/recording.md) is plain numpy: ``numpy.load(path)`` reads it
without manyworlds. ``Recorder`` writes it (the C++ writer, streaming to
disk); ``load_recording`` reads and checks it::

    with mw.Recorder(batch, "run.npz", worlds=[0, 1, 7], scene="ragdoll") as rec:
        rec.capture(batch, time=0.0, step=0)          # frame 0: before any step
        for step in range(1, 601):
            batch.step(settings)
            rec.capture(batch, time=step * settings.delta_time, step=step)
    recording = mw.load_recording("run.npz")
    recording.position.shape                         # (601, 3, bodies, 3)
    recording.body_shape_type                        # per body: 0 none, 1 sphere, ... 4 plane

Files written before the bodies' collision shapes were recorded (same
format version 1, no ``body_shape_*`` arrays) load too: their bodies have
no shape (``recording.has_shapes`` is False).
"""

import os as _os

import numpy as _np

from . import _core

FORMAT_VERSION = 1

# Every array of format 1: dtype kind and size ("U" any width) and shape,
# in the letters T (frames), W (worlds), B (bodies), C (constraints),
# J (joint coordinates).
_ARRAYS = {
    "format_version": ("<i4", (1,)),
    "scene": ("U", ()),
    "time": ("<f8", ("T",)),
    "step": ("<i8", ("T",)),
    "world": ("<i8", ("W",)),
    "body_name": ("U", ("B",)),
    "body_motion_type": ("|u1", ("B",)),
    "body_mass": ("<f4", ("B",)),
    "body_inertia_diagonal": ("<f4", ("B", 3)),
    "body_inertia_rotation": ("<f4", ("B", 4)),
    "position": ("<f4", ("T", "W", "B", 3)),
    "rotation": ("<f4", ("T", "W", "B", 4)),
    "constraint_name": ("U", ("C",)),
    "constraint_type": ("U", ("C",)),
    "constraint_body": ("<i4", ("C", 2)),
    "constraint_anchor": ("<f4", ("C", 2, 3)),
    "joint_coordinate_name": ("U", ("J",)),
    "joint_coordinate_constraint": ("<i4", ("J",)),
    "joint_coordinates": ("<f4", ("T", "W", "J")),
    "health": ("|u1", ("T", "W")),
}
# Arrays of format 1 that older files lack: the bodies' collision shapes
# (ShapeType, then radius, half_height, half_extents; the shape's place in the
# body frame). All or none of them; without them every body has no shape, the
# values below.
_SHAPE_ARRAYS = {
    "body_shape_type": ("|u1", ("B",)),
    "body_shape_size": ("<f4", ("B", 5)),
    "body_shape_position": ("<f4", ("B", 3)),
    "body_shape_rotation": ("<f4", ("B", 4)),
}
_ARRAYS.update(_SHAPE_ARRAYS)
_SHAPE_DEFAULTS = {
    "body_shape_type": lambda bodies: _np.zeros(bodies, _np.uint8),
    "body_shape_size": lambda bodies: _np.zeros((bodies, 5), _np.float32),
    "body_shape_position": lambda bodies: _np.zeros((bodies, 3), _np.float32),
    "body_shape_rotation": lambda bodies: _np.tile(_np.array([0, 0, 0, 1], _np.float32),
                                                   (bodies, 1)),
}
# Which array fixes each letter.
_SIZES_FROM = {"T": "time", "W": "world", "B": "body_name", "C": "constraint_name",
               "J": "joint_coordinate_name"}


class Recorder(_core.Recorder):
    """Records `worlds` of `batch` to `path`, one frame per capture().

    As a context manager the file is written when the block ends, and
    removed (never left half-written) when it raises. An existing file
    raises FileExistsError unless overwrite=True.
    """

    def __init__(self, batch, path, worlds=(0,), *, scene="", overwrite=False):
        path = _os.fspath(path)
        if not overwrite and _os.path.lexists(path):
            raise FileExistsError(f"{path!r} exists (pass overwrite=True to replace it)")
        super().__init__(batch, path, [int(w) for w in worlds], scene=str(scene),
                         overwrite=overwrite)

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, traceback):
        if self.closed:
            return False
        if exc_type is None:
            self.close()
        else:
            self.discard()
        return False


class Recording:
    """A loaded recording: every array of the file as an attribute
    (``recording.position``), ``scene`` as a str, and the sizes.

    ``arrays`` holds the file's arrays as they are; the ``body_shape_*``
    attributes (and ``recording["body_shape_type"]``) exist for a file
    without them too, every body without a shape; ``has_shapes`` says
    whether the file held them."""

    def __init__(self, arrays):
        self.arrays = arrays
        for name, value in arrays.items():
            setattr(self, name, value)
        self.scene = str(arrays["scene"][()])
        self.has_shapes = all(name in arrays for name in _SHAPE_ARRAYS)
        if not self.has_shapes:
            for name, default in _SHAPE_DEFAULTS.items():
                setattr(self, name, default(len(arrays["body_name"])))

    num_frames = property(lambda self: len(self.time))
    num_worlds = property(lambda self: len(self.world))
    num_bodies = property(lambda self: len(self.body_name))

    def __getitem__(self, name):
        if name in _SHAPE_ARRAYS and name not in self.arrays:
            return getattr(self, name)
        return self.arrays[name]

    def __repr__(self):
        return (f"Recording(scene={self.scene!r}, frames={self.num_frames}, "
                f"worlds={self.world.tolist()}, bodies={self.num_bodies})")


def _check_array(name, value, sizes):
    dtype, shape = _ARRAYS[name]
    if dtype == "U":
        if value.dtype.kind != "U":
            raise ValueError(f"{name}: expected a unicode array, got dtype {value.dtype}")
    elif value.dtype != _np.dtype(dtype):
        raise ValueError(f"{name}: expected dtype {dtype}, got {value.dtype}")
    expected = tuple(sizes.get(d, d) for d in shape)
    if value.shape != expected:
        raise ValueError(f"{name}: expected shape {expected}, got {value.shape}")


def load_recording(path):
    """Reads a recording (numpy.load) and checks its version, dtypes and
    shapes; raises ValueError naming the first array that is wrong."""
    with _np.load(_os.fspath(path), allow_pickle=False) as npz:
        arrays = {name: npz[name] for name in npz.files}
    missing = [name for name in _ARRAYS if name not in arrays and name not in _SHAPE_ARRAYS]
    shapes = [name for name in _SHAPE_ARRAYS if name in arrays]
    if shapes:  # a file with shapes has all their arrays
        missing += [name for name in _SHAPE_ARRAYS if name not in arrays]
    if missing:
        raise ValueError(f"{_os.fspath(path)!r} is not a manyworlds recording: missing {missing}")
    version = arrays["format_version"]
    if version.shape != (1,) or int(version[0]) != FORMAT_VERSION:
        raise ValueError(f"format_version {version.tolist()} is not {FORMAT_VERSION}")
    sizes = {letter: len(arrays[name]) for letter, name in _SIZES_FROM.items()}
    for name, value in arrays.items():
        if name in _ARRAYS:
            _check_array(name, value, sizes)
    return Recording(arrays)
