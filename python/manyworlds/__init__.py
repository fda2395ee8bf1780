"""manyworlds: step thousands of independent rigid-body worlds per call.

The C++ library (Jolt's constraint solver, one SIMD lane per world) as a
Python module. Build a Scene (or load one with make_scene), make a Batch of
N copies, and step them all at once; state, actions and per-world parameters
are numpy arrays indexed [world, ...]::

    import numpy as np
    import manyworlds as mw

    batch = mw.Batch(mw.make_scene("cartpole"), 4096)
    forces = np.zeros((4096, 3), np.float32)
    state = np.empty((4096, batch.num_bodies, 13), np.float32)
    for step in range(1000):
        forces[:, 0] = policy(state)              # the cart's force along X
        batch.set_body_forces(mw.reference_scene.CART, forces)
        batch.step()                              # the GIL is released meanwhile
        batch.get_state(out=state)                # no allocation
        done = np.abs(state[:, mw.reference_scene.CART, 0]) > 2.4
        batch.reset(done)

docs/python.md describes the whole API, the error semantics and threading.
"""

import enum as _enum

import numpy as _np

from . import _core
from ._core import *  # noqa: F401,F403  (the whole C++ API)
from ._core import __version__  # noqa: F401
from .recording import Recorder, Recording, load_recording  # noqa: F401  (after _core's)

# The snapshot type also under the C++ name.
BatchSnapshot = _core.Batch.Snapshot


class WorldHealthBits(_enum.IntFlag):
    """Bits of Batch.health: 0 when a world is healthy (batch.h)."""

    NON_FINITE_STATE = _core.NON_FINITE_STATE  # a NaN or infinite position, rotation or velocity
    VELOCITY_OVERFLOW = _core.VELOCITY_OVERFLOW  # |v|^2 or |w|^2 overflowed float
    POSITION_OUT_OF_RANGE = _core.POSITION_OUT_OF_RANGE  # a coordinate beyond 2^24 m
    NON_FINITE_INPUT = _core.NON_FINITE_INPUT  # a NaN/inf force, torque or target was written
    NOT_STEPPED = _core.NOT_STEPPED  # an interrupted step did not reach the world


# The settings structs: plain data with a keyword constructor. They get a
# readable repr, == by value and copy.copy / copy.deepcopy here, from their
# properties (one per C++ field, in declaration order).
SETTINGS_TYPES = (
    _core.BodySettings,
    _core.ShapeSettings,
    _core.SpringSettings,
    _core.MotorSettings,
    _core.PathPoint,
    _core.StepSettings,
    _core.BatchOptions,
    _core.PointConstraintSettings,
    _core.FixedConstraintSettings,
    _core.HingeConstraintSettings,
    _core.SliderConstraintSettings,
    _core.GearConstraintSettings,
    _core.RackAndPinionConstraintSettings,
    _core.DistanceConstraintSettings,
    _core.PulleyConstraintSettings,
    _core.ConeConstraintSettings,
    _core.SwingTwistConstraintSettings,
    _core.SixDofConstraintSettings,
    _core.PathConstraintSettings,
)


def fields(settings):
    """The field names of a settings object (or type), in declaration order."""
    cls = settings if isinstance(settings, type) else type(settings)
    return [name for name, attr in vars(cls).items() if isinstance(attr, property)]


def _format_value(value):
    # Floats are float32 in C++: print their shortest float32 form (0.05,
    # not 0.05000000074505806).
    if isinstance(value, float):
        return str(_np.float32(value))
    if isinstance(value, tuple):
        items = ", ".join(_format_value(v) for v in value)
        return "(" + items + ("," if len(value) == 1 else "") + ")"
    return repr(value)


def _settings_repr(self):
    body = ", ".join(f"{name}={_format_value(getattr(self, name))}" for name in fields(self))
    return f"{type(self).__name__}({body})"


def _settings_eq(self, other):
    if type(self) is not type(other):
        return NotImplemented
    return all(getattr(self, name) == getattr(other, name) for name in fields(self))


def _settings_copy(self, memo=None):
    return type(self)(self)


for _cls in SETTINGS_TYPES:
    _cls.__repr__ = _settings_repr
    _cls.__eq__ = _settings_eq
    _cls.__hash__ = None  # mutable
    _cls.__copy__ = _settings_copy
    _cls.__deepcopy__ = _settings_copy
del _cls
