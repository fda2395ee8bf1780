"""dm_control's reward shaping (dm_control/utils/rewards.py), vectorised.

tolerance(x, bounds, margin, sigmoid, value_at_margin) is 1 where
bounds[0] <= x <= bounds[1] and decays outside with the distance to the
nearer bound, scaled by `margin`, so that a distance of `margin` gives
`value_at_margin`. Only the sigmoids the tasks here use are transcribed:
'gaussian' (dm_control's default) and 'quadratic'.
"""

import numpy as np


def _sigmoid(x, value_at_1, sigmoid):
    if sigmoid == "gaussian":
        scale = np.sqrt(-2.0 * np.log(value_at_1))
        return np.exp(-0.5 * (x * scale) ** 2)
    if sigmoid == "quadratic":
        scale = np.sqrt(1.0 - value_at_1)
        scaled = x * scale
        return np.where(np.abs(scaled) < 1.0, 1.0 - scaled ** 2, 0.0)
    raise ValueError(f"sigmoid: 'gaussian' or 'quadratic' supported, got {sigmoid!r}")


def tolerance(x, bounds=(0.0, 0.0), margin=0.0, sigmoid="gaussian", value_at_margin=0.1):
    """dm_control.utils.rewards.tolerance over arrays (float64 result)."""
    lower, upper = bounds
    if lower > upper:
        raise ValueError("tolerance: lower bound must be <= upper bound")
    if margin < 0:
        raise ValueError("tolerance: margin must be non-negative")
    x = np.asarray(x, np.float64)
    in_bounds = (lower <= x) & (x <= upper)
    if margin == 0:
        return np.where(in_bounds, 1.0, 0.0)
    distance = np.where(x < lower, lower - x, x - upper) / margin
    return np.where(in_bounds, 1.0, _sigmoid(distance, value_at_margin, sigmoid))
