"""The arrays results.h5 keeps per line beside its tables (campaigns/README.md, section
"results.h5"), as long frames with a `line` column: the relaxation curves' points, the bootstrap's
replicate medians and the principal components. Each reader takes the open file and the lines in
the campaign's order, and returns an empty frame of its columns when no line has the array."""
import h5py
import numpy as np
import pandas as pd

from .h5text import text as _text, texts as _texts


def _frame(rows, columns, units):
    frame = pd.DataFrame(rows, columns=columns) if rows else pd.DataFrame({c: pd.Series([], dtype=object) for c in columns})
    frame.attrs["units"] = units
    return frame


def _concat(frames, columns, units):
    if not frames:
        return _frame([], columns, units)
    frame = pd.concat(frames, ignore_index=True)[columns]
    frame.attrs["units"] = units
    return frame


def relaxation_points(h5, lines):
    """Every sample of every relaxation curve: line, curve_index (the row of the line's
    relaxation fits), curve (its name), t_s, F_uN (measured) and F_fit_uN (the fitted model at
    the sample; NaN before the force maximum for the step fit)."""
    columns = ["line", "curve_index", "curve", "t_s", "F_uN", "F_fit_uN"]
    frames = []
    for line in lines:
        group = h5["lines"][line]
        if "relaxation/points" not in group:
            continue
        points = group["relaxation/points"]
        names = np.array(_texts(group["relaxation/fits"]["curve"]), dtype=object)
        index = points["curve_index"][()].astype(np.int64)
        frames.append(pd.DataFrame({"line": line, "curve_index": index, "curve": names[index],
                                    "t_s": points["t_s"][()], "F_uN": points["F_uN"][()],
                                    "F_fit_uN": points["F_fit_uN"][()]}))
    return _concat(frames, columns, {"t_s": "s", "F_uN": "uN", "F_fit_uN": "uN"})


def bootstrap_replicates(h5, lines):
    """The data-uncertainty bootstrap's replicate medians: line, quantity, replicate (0-based
    among the replicates that succeeded; a failed replicate has no row), median, unit. Their
    2.5 and 97.5 % quantiles are the data 95 % interval of data_uncertainty.csv."""
    rows = []
    for line in lines:
        group = h5["lines"][line]
        if "data_uncertainty_replicates" not in group:
            continue
        replicates = group["data_uncertainty_replicates"]
        # The quantities in data_uncertainty's row order (HDF5 lists datasets alphabetically).
        for quantity in _texts(group["data_uncertainty"]["quantity"]):
            if quantity not in replicates or h5py.h5ds.is_scale(replicates[quantity].id):
                continue
            medians = replicates[quantity]
            unit = _text(medians.attrs["unit"])
            rows += [(line, quantity, i, float(value), unit) for i, value in enumerate(medians[()])]
    return _frame(rows, ["line", "quantity", "replicate", "median", "unit"], {})


def principal_components(h5, lines):
    """The principal components of each line's standardized inputs and outputs (the correlation
    matrix's eigenvectors, largest entry positive, as the run report prints them): `loadings`
    (line, variable, component "PC1", ..., loading) and `explained` (line, component,
    explained_variance_ratio)."""
    loadings, explained = [], []
    for line in lines:
        analysis = h5["lines"][line]["analysis"]
        if "loadings" not in analysis or analysis["loadings"].size == 0:
            continue  # a line without analysis: too few samples with status ok
        matrix = analysis["loadings"][()]
        variables = _texts(analysis["loadings"].attrs["rows"])
        components = [f"PC{c + 1}" for c in range(matrix.shape[1])]
        loadings += [(line, variable, component, float(matrix[r, c]))
                     for r, variable in enumerate(variables) for c, component in enumerate(components)]
        ratios = analysis["explained_variance_ratio"][()]
        explained += [(line, component, float(ratio)) for component, ratio in zip(components, ratios)]
    return (_frame(loadings, ["line", "variable", "component", "loading"], {"loading": "1"}),
            _frame(explained, ["line", "component", "explained_variance_ratio"], {"explained_variance_ratio": "1"}))
