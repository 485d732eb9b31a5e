"""Reading the force curves that campaigns with a [force_curves] raw line store per line in
results.h5: /lines/<line>/force_curves/curves (one row per curve: curve, tube, status, the
baseline's offset and tilt, and for an ok curve the contact, the window's forces above the
baseline, the window line's slope k_m and intercept, k and its uncertainty u), .../tubes (one row
per tube: tube, k_N_per_m, u_N_per_m, ...) and the approaches in long format in .../points
(curve_index, the curves row of each point; z_um; F_uN as recorded)."""
from dataclasses import dataclass

import numpy as np

from .errors import PlotInputError
from .h5text import text_list

CURVE_COLUMNS = ("curve", "tube", "status", "baseline_offset_uN", "baseline_tilt_N_per_m", "contact_z_um",
                 "window_low_uN", "window_high_uN", "k_m_N_per_m", "fit_intercept_uN", "k_N_per_m", "u_N_per_m")
TUBE_COLUMNS = ("tube", "ok", "k_N_per_m", "u_N_per_m")
POINT_COLUMNS = ("curve_index", "z_um", "F_uN")


@dataclass
class ForceCurve:
    name: str
    tube: str
    status: str
    z_um: np.ndarray
    F_uN: np.ndarray           # as recorded
    numbers: dict              # the numeric columns of the curves table (NaN where not ok)

    def baseline_uN(self, z_um):
        """The baseline at z (Eq. (C1)); its tilt in N/m is uN per um."""
        return self.numbers["baseline_offset_uN"] + self.numbers["baseline_tilt_N_per_m"] * z_um

    def window_z_um(self):
        """The stage positions where the window line meets the window's edges."""
        k_m, intercept = self.numbers["k_m_N_per_m"], self.numbers["fit_intercept_uN"]
        return ((self.numbers["window_low_uN"] - intercept) / k_m, (self.numbers["window_high_uN"] - intercept) / k_m)


@dataclass
class Tube:
    name: str
    ok: int
    k_N_per_m: float
    u_N_per_m: float


def _table(group, key, columns, where):
    if key not in group or not group[key].dtype.names:
        raise PlotInputError(f"{where}/{key}: missing (expected a compound table with {', '.join(columns)})")
    data = group[key][()]
    missing = [column for column in columns if column not in data.dtype.names]
    if missing:
        raise PlotInputError(f"{where}/{key}: no column {', '.join(missing)} (expected {', '.join(columns)})")
    return data


def read_force_curves(group, where):
    """([ForceCurve] in table order, [Tube] in table order) of one line's force_curves group;
    `where` names the group in messages ("results.h5:/lines/wild_type/force_curves")."""
    table = _table(group, "curves", CURVE_COLUMNS, where)
    tubes = _table(group, "tubes", TUBE_COLUMNS, where)
    points = {}
    for column in POINT_COLUMNS:
        if "points" not in group or column not in group["points"]:
            raise PlotInputError(f"{where}/points/{column}: missing (expected the approaches' points: "
                                 f"{', '.join(POINT_COLUMNS)})")
        points[column] = group["points"][column][()]
    if len({len(values) for values in points.values()}) != 1:
        raise PlotInputError(f"{where}/points: datasets of different lengths; expected one value per point in each")
    index = points["curve_index"].astype(np.int64)
    if index.size and (index.min() < 0 or index.max() >= len(table)):
        bad = int(index[(index < 0) | (index >= len(table))][0])
        raise PlotInputError(f"{where}/points/curve_index: value {bad}; expected a row of {where}/curves "
                             f"(0 to {len(table) - 1})")
    numeric = [column for column in table.dtype.names if table.dtype[column].kind in "fiu"]
    names, tube_names, statuses = (text_list(table[column]) for column in ("curve", "tube", "status"))
    curves = []
    for row in range(len(table)):
        mine = index == row
        curves.append(ForceCurve(name=names[row], tube=tube_names[row], status=statuses[row],
                                 z_um=np.asarray(points["z_um"][mine], dtype=float),
                                 F_uN=np.asarray(points["F_uN"][mine], dtype=float),
                                 numbers={column: float(table[column][row]) for column in numeric}))
    tube_list = [Tube(name, int(ok), float(k), float(u)) for name, ok, k, u in
                 zip(text_list(tubes["tube"]), tubes["ok"], tubes["k_N_per_m"], tubes["u_N_per_m"])]
    return curves, tube_list
