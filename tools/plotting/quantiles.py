"""Order statistics drawn by the plots, with the rule of growthuq's summary.csv: numpy's default
"linear" interpolation (Hyndman and Fan 1996, definition 7), so a box drawn here has exactly the
q1, median, q3, p10 and p90 that summary.csv reports for the same samples."""
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Spread:
    """Quantiles of one sample; every field is NaN when n == 0."""
    n: int
    p10: float
    q1: float
    median: float
    q3: float
    p90: float


def spread_of(values):
    values = np.asarray(values, dtype=float)
    if values.size == 0:
        nan = float("nan")
        return Spread(0, nan, nan, nan, nan, nan)
    p10, q1, median, q3, p90 = np.percentile(values, [10, 25, 50, 75, 90])
    return Spread(int(values.size), float(p10), float(q1), float(median), float(q3), float(p90))
