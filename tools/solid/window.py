"""k over the instrument's force window, read as the shell model reads it (src/fe/force_window.cpp,
src/fe/README.md eq. 11): the curve, linear between its points, from its first passage through
`low` to its first passage through `high`, sampled at 101 equally spaced depths, and the slope of
their least-squares line."""
import numpy as np


def _passage(d, f, level):
    """Depth of the first passage of the piecewise-linear curve through `level`."""
    i = int(np.argmax(f >= level))
    if i == 0:
        return d[0]
    return d[i - 1] + (d[i] - d[i - 1]) * (level - f[i - 1]) / (f[i] - f[i - 1])


def fit_force_window(depth, force, low, high):
    depth, force = np.asarray(depth, float), np.asarray(force, float)
    if len(depth) < 2 or force.max() < high:
        return {"status": "window_not_reached", "max_force": float(force.max())}
    bottom, top = _passage(depth, force, low), _passage(depth, force, high)
    end = int(np.argmax(force >= high)) + 1  # the curve up to its first passage through `high`
    x = np.linspace(bottom, top, 101)
    y = np.interp(x, depth[:end], force[:end])
    y[0], y[-1] = max(y[0], low), high
    slope, intercept = np.polyfit(x, y, 1)
    return {"status": "ok", "slope": float(slope), "intercept": float(intercept),
            "low_depth": float(bottom), "top_depth": float(top)}
