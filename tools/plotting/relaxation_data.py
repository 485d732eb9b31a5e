"""Reading the relaxation curves and fits that campaigns built from raw curves store per line in
results.h5: /lines/<line>/relaxation/ holds a per-curve fit table (a compound dataset, or one 1-D
dataset per column: curve, status, tau_fast_s, tau_slow_s, einf_frac, Er0_MPa, ...) and the
points in long format in relaxation/points/ (curve_index, the fit-table row of each point; t_s;
F_uN, the measured force; F_fit_uN, the fitted force, NaN where the fit does not apply)."""
from dataclasses import dataclass, field

import numpy as np

from .errors import PlotInputError
from .h5text import as_text, text_list

POINT_COLUMNS = ("curve_index", "t_s", "F_uN", "F_fit_uN")


@dataclass
class RelaxationCurve:
    name: str
    status: str
    t_s: np.ndarray
    F_uN: np.ndarray
    F_fit_uN: np.ndarray
    fit: dict = field(default_factory=dict)  # numeric columns of the fit table, e.g. tau_slow_s


def _status_texts(values, names):
    """Status cells as names: strings as they are, integer codes through the `names` attribute."""
    if values.dtype.kind in "SOU":
        return text_list(values)
    if names is None:
        return [str(int(code)) for code in values]
    names = text_list(names)
    return [names[int(code)] if 0 <= int(code) < len(names) else str(int(code)) for code in values]


def _fit_table(group, where):
    """The fit table as {column: array}, in file order, and the `names` of a coded status."""
    compound = [key for key in group if hasattr(group[key], "dtype") and group[key].dtype.names]
    if compound:
        key = "fits" if "fits" in compound else compound[0]
        if len(compound) > 1 and key != "fits":
            raise PlotInputError(f"{where}: several compound datasets ({', '.join(compound)}); "
                                 "expected one fit table (named 'fits')")
        data = group[key][()]
        names = group[key].attrs.get("status_names")
        return {column: data[column] for column in data.dtype.names}, names, f"{where}/{key}"
    columns = {key: group[key][()] for key in group
               if hasattr(group[key], "shape") and len(group[key].shape) == 1}
    lengths = {key: len(values) for key, values in columns.items()}
    if not columns:
        raise PlotInputError(f"{where}: no fit table (expected a compound dataset or 1-D column "
                             "datasets such as curve, status, tau_slow_s)")
    if len(set(lengths.values())) != 1:
        raise PlotInputError(f"{where}: fit-table columns differ in length ({lengths}); expected "
                             "one row per curve in every column")
    names = group["status"].attrs.get("names") if "status" in columns else None
    return columns, names, where


def read_relaxation(group, where):
    """The curves of one line's relaxation group, in fit-table order. `where` names the group
    in messages ("results.h5:/lines/wild_type/relaxation")."""
    table, status_names, table_where = _fit_table(group, where)
    rows = len(next(iter(table.values())))
    if "points" not in group:
        raise PlotInputError(f"{where}/points: missing (expected the curves' points: "
                             f"{', '.join(POINT_COLUMNS)})")
    points = {}
    for column in POINT_COLUMNS:
        if column not in group["points"]:
            raise PlotInputError(f"{where}/points/{column}: missing (expected the datasets "
                                 f"{', '.join(POINT_COLUMNS)})")
        points[column] = group["points"][column][()]
    if len({len(values) for values in points.values()}) != 1:
        raise PlotInputError(f"{where}/points: datasets of different lengths; expected one value "
                             "per point in each")
    index = points["curve_index"].astype(np.int64)
    if index.size and (index.min() < 0 or index.max() >= rows):
        bad = int(index[(index < 0) | (index >= rows)][0])
        raise PlotInputError(f"{where}/points/curve_index: value {bad}; expected a row of the "
                             f"fit table {table_where} (0 to {rows - 1})")

    curve_names = text_list(table["curve"]) if "curve" in table else [f"curve {i}" for i in range(rows)]
    statuses = (_status_texts(np.asarray(table["status"]), status_names) if "status" in table
                else ["unknown"] * rows)
    numeric = {column: np.asarray(values, dtype=float) for column, values in table.items()
               if column not in ("curve", "status") and np.asarray(values).dtype.kind in "fiu"}
    curves = []
    for row in range(rows):
        mine = index == row
        order = np.argsort(points["t_s"][mine], kind="stable")
        curves.append(RelaxationCurve(
            name=as_text(curve_names[row]), status=statuses[row],
            t_s=np.asarray(points["t_s"][mine], dtype=float)[order],
            F_uN=np.asarray(points["F_uN"][mine], dtype=float)[order],
            F_fit_uN=np.asarray(points["F_fit_uN"][mine], dtype=float)[order],
            fit={column: float(values[row]) for column, values in numeric.items()}))
    return curves
