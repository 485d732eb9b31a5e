"""growthuq.load: a campaign's results.h5 (written by `growthuq run` with hdf5 among its formats;
layout in campaigns/README.md, section "results.h5") as pandas frames and an xarray Dataset.

Every frame has a `line` column that is an ordered categorical in the campaign's order (the root
attribute line_order), so sorting, groupby and plots keep that order rather than the alphabet's.
Units are attributes: `frame.attrs["units"]` maps a column to its unit symbol, and each variable
of the Dataset has `units` (and `long_name`) as results.h5 stores them."""
from dataclasses import dataclass, field
from pathlib import Path

import h5py
import numpy as np
import pandas as pd
import xarray as xr

from .errors import ResultsError
from .h5text import text as _text, texts as _texts
from .line_arrays import bootstrap_replicates, principal_components, relaxation_points
from .views import long_frame, short_repr, summary_array


@dataclass(repr=False)
class Results:
    path: Path                  # the results.h5 read
    lines: list                 # line names, in campaign order
    samples: pd.DataFrame       # one row per sample: line, sample, each column (unit in its name), status
    summary: pd.DataFrame       # the rows of summary.csv (line, quantity, unit, n, ..., median_ci_high, data_ci_low, data_ci_high)
    correlations: pd.DataFrame  # line, matrix (target, achieved, input_output), row, column, spearman
    fits: pd.DataFrame          # raw-data lines: line and the fits table (chosen law per variable)
    fit_parameters: pd.DataFrame  # raw-data lines: line, variable, unit, family, chosen, parameter, value
    dataset: xr.Dataset         # the sample columns and status as (line, sample) arrays, the summary as (line, quantity, statistic)
    # The data uncertainty (campaigns/README.md, "Data uncertainty"); empty frames when the
    # campaign ran no bootstrap or compared no lines.
    data_uncertainty: pd.DataFrame = field(default_factory=pd.DataFrame)  # the rows of data_uncertainty.csv, campaign order
    comparisons: pd.DataFrame = field(default_factory=pd.DataFrame)  # the rows of comparisons.csv (line_a / line_b)
    letters: pd.DataFrame = field(default_factory=pd.DataFrame)      # the rows of letters.csv (quantity, line, letters)
    # The first-order sensitivity indices (src/sensitivity/README.md): the rows of sensitivity.csv
    # (line, output, input, method, index, ci_low, ci_high, samples_used, sections); empty when
    # no line had enough samples with status ok.
    sensitivity: pd.DataFrame = field(default_factory=pd.DataFrame)
    # Raw-data lines: every family tried per variable, and the relaxation curves' fits (one row
    # per curve, the columns of `growthuq relax`) and points (line_arrays.py).
    fit_candidates: pd.DataFrame = field(default_factory=pd.DataFrame)
    relaxation_fits: pd.DataFrame = field(default_factory=pd.DataFrame)
    relaxation_points: pd.DataFrame = field(default_factory=pd.DataFrame)
    # The bootstrap's replicate medians (line, quantity, replicate, median, unit) and the
    # principal components (line, variable, component, loading; line, component, ratio).
    replicates: pd.DataFrame = field(default_factory=pd.DataFrame)
    loadings: pd.DataFrame = field(default_factory=pd.DataFrame)
    explained_variance: pd.DataFrame = field(default_factory=pd.DataFrame)
    attrs: dict = field(default_factory=dict)  # root attributes: seed, kappa, samples_per_line, campaign_text, ...
    # How the results were made (/provenance, campaigns/README.md): version, campaign and its
    # SHA-256, seed, samples, instrument, data-interval settings, and `lines` and `models` as
    # {name: {field: value}}; {} for results of a growthuq without it.
    provenance: dict = field(default_factory=dict)
    report: str = ""            # stdout of the run, when the results come from growthuq.run

    def tables(self):
        """Every frame by name, in the order above (empty ones included)."""
        return {name: value for name, value in vars(self).items() if isinstance(value, pd.DataFrame)}

    @property
    def long(self):
        """The samples as one tidy frame: line, sample, quantity, value, unit (views.long_frame)."""
        return long_frame(self.samples, self.dataset)

    def __repr__(self):
        return short_repr(self)


def _plain(value):
    """A root attribute as a Python value (numpy scalars to int, float or str)."""
    if isinstance(value, (bytes, str)):
        return _text(value)
    if isinstance(value, np.ndarray):
        return [_plain(item) for item in value]
    return value.item() if hasattr(value, "item") else value


def _in_line_order(frame, lines):
    """`line` as an ordered categorical of the campaign's order, and the rows in that order (the
    campaign runs its reference line first, so summary.csv and samples.csv begin with it)."""
    frame["line"] = pd.Categorical(frame["line"], categories=lines, ordered=True)
    return frame.sort_values("line", kind="stable").reset_index(drop=True)


def _table(dataset):
    """A compound table as a frame, text as str, units (attribute column_units) in attrs."""
    frame = pd.DataFrame(dataset[()])
    for name in frame.columns:
        if frame[name].dtype == object:
            frame[name] = _texts(frame[name])
    if "column_units" in dataset.attrs:
        frame.attrs["units"] = {name: unit for name, unit in zip(frame.columns, _texts(dataset.attrs["column_units"]))
                                if unit}
    return frame


def _line_tables(h5, lines, name):
    """The table `name` of every line that has one, with the line as first column."""
    frames = []
    for line in lines:
        group = h5["lines"][line]
        if name in group:
            frame = _table(group[name])
            frame.insert(0, "line", line)
            frames.append(frame)
    if not frames:
        return pd.DataFrame({"line": pd.Series([], dtype=object)})
    combined = pd.concat(frames, ignore_index=True)
    combined.attrs["units"] = frames[0].attrs.get("units", {})
    return _in_line_order(combined, lines)


def _root_table(h5, name, lines, line_columns):
    """The root table `name` (data_uncertainty, line_comparisons, line_letters, sensitivity) with its line
    columns as ordered categoricals of the campaign's order, rows as stored; an empty frame when
    the run wrote none."""
    if name not in h5:
        return pd.DataFrame()
    frame = _table(h5[name])
    for column in line_columns:
        frame[column] = pd.Categorical(frame[column], categories=lines, ordered=True)
    return frame


def _long_matrix(rows, line, matrix, row_names, column_names, values):
    if values.shape != (len(row_names), len(column_names)):
        return  # a line without analysis: empty matrices
    for r, row in enumerate(row_names):
        for c, column in enumerate(column_names):
            rows.append((line, matrix, row, column, float(values[r, c])))


def _correlations(h5, lines):
    rows = []
    for line in lines:
        group = h5["lines"][line]
        correlation = group["input_rank_correlation"]
        names = _texts(correlation.attrs["names"])
        for matrix in ("target", "achieved"):
            if matrix in correlation:
                _long_matrix(rows, line, matrix, names, names, correlation[matrix][()])
        spearman = group["analysis/input_output_spearman"]
        _long_matrix(rows, line, "input_output", _texts(spearman.attrs["rows"]), _texts(spearman.attrs["columns"]),
                     spearman[()])
    frame = pd.DataFrame(rows, columns=["line", "matrix", "row", "column", "spearman"])
    return _in_line_order(frame, lines)


def _line_dataset(path, line):
    """One line's columns (in samples.csv's order: the group attribute `columns`) and status on
    its `sample` dimension, as xarray opens the group."""
    with xr.open_dataset(path, group=f"lines/{line}", engine="h5netcdf", decode_timedelta=False) as group:
        dataset = group[_texts(group.attrs["columns"]) + ["status"]].load()
    names = np.array(_texts(dataset["status"].attrs["names"]), dtype=object)
    dataset["status"] = ("sample", names[dataset["status"].values.astype(np.int64)])
    return dataset


def _combined(datasets, lines):
    """The lines' datasets along a `line` dimension; a column a line lacks is NaN there. Inputs
    come before outputs, each in the order the lines (in campaign order) first give them."""
    names = []
    for dataset in datasets:
        names += [name for name in dataset.data_vars if name not in names and name != "status"]
    role_rank = {"input": 0, "output": 1}
    first = {name: next(d[name] for d in datasets if name in d) for name in names}
    names.sort(key=lambda name: role_rank.get(first[name].attrs.get("role"), 2))
    filled = []
    for dataset in datasets:
        for name in names:
            if name not in dataset:
                dataset[name] = ("sample", np.full(dataset.sizes["sample"], np.nan), first[name].attrs)
        filled.append(dataset[names + ["status"]])
    return xr.concat(filled, dim=pd.Index(lines, name="line"), join="outer")


def _samples_frame(dataset, lines):
    frame = dataset.to_dataframe().reset_index()
    frame = frame[frame["status"].notna()]  # samples a shorter line does not have
    frame["sample"] = frame["sample"].astype(np.int64)
    frame = _in_line_order(frame.reset_index(drop=True), lines)
    frame.attrs["units"] = {name: dataset[name].attrs["units"] for name in dataset.data_vars if "units" in dataset[name].attrs}
    return frame


def load(results):
    """The results of a campaign: `results` is its output directory or its results.h5. Raises
    ResultsError naming the file when it is missing, not HDF5, or not growthuq's layout."""
    path = Path(results)
    if path.is_dir():
        path = path / "results.h5"
    if not path.is_file():
        raise ResultsError(f"{path}: no such file (expected the results.h5 that `growthuq run` writes with hdf5 "
                           "among its formats)")
    try:
        h5 = h5py.File(path, "r")
    except OSError as error:
        raise ResultsError(f"{path}: not a readable HDF5 file ({error}); expected the results.h5 of "
                           "`growthuq run`") from None
    try:
        return _load_open(path, h5)
    except ResultsError:
        raise
    except (AttributeError, KeyError, OSError, RuntimeError, ValueError, TypeError, IndexError) as error:
        # h5py's own errors from deep inside (a damaged block, an object of another kind) say
        # neither the file nor that it is the file that is wrong.
        raise ResultsError(f"{path}: cannot be read as growthuq's results ({type(error).__name__}: {error}); "
                           "expected an intact results.h5 of `growthuq run`: rerun the campaign") from None


def _provenance(h5):
    if "provenance" not in h5:
        return {}
    group = h5["provenance"]
    found = {name: _plain(value) for name, value in group.attrs.items()}
    for part in ("lines", "models"):
        if part in group:
            found[part] = {name: {key: _plain(value) for key, value in member.attrs.items()}
                           for name, member in group[part].items()}
    return found


def _require(path, h5, name, what):
    """ResultsError naming the file and the missing object `name` (`what` it is)."""
    if name not in h5:
        raise ResultsError(f"{path}: no /{name} ({what}); expected the layout `growthuq run` writes: rerun the "
                           "campaign")


def _load_open(path, h5):
    """load() of the opened file `h5`; h5py's errors are turned into ResultsError by load()."""
    with h5:
        if "lines" not in h5 or "engine_version" not in h5.attrs:
            raise ResultsError(f"{path}: not a growthuq results file (expected the group /lines and the root "
                               "attribute engine_version)")
        if "line_order" not in h5.attrs:
            raise ResultsError(f"{path}: written by an older growthuq (no root attribute line_order, no dimension "
                               "scales); expected a results.h5 of this version: rerun the campaign")
        lines = _texts(h5.attrs["line_order"])
        _require(path, h5, "summary", "the summary table")
        for line in lines:
            _require(path, h5, f"lines/{line}", f"the group of the line '{line}' that line_order lists")
            for part in ("status", "input_rank_correlation", "analysis/input_output_spearman"):
                _require(path, h5, f"lines/{line}/{part}", f"part of the line '{line}'")
        attrs = {name: _plain(value) for name, value in h5.attrs.items()}
        summary = _in_line_order(_table(h5["summary"]), lines)
        correlations = _correlations(h5, lines)
        fits = _line_tables(h5, lines, "fits")
        fit_parameters = _line_tables(h5, lines, "fit_parameters")
        data_uncertainty = _root_table(h5, "data_uncertainty", lines, ["line"])
        if not data_uncertainty.empty:  # in the campaign's order, as summary
            data_uncertainty = _in_line_order(data_uncertainty, lines)
        comparisons = _root_table(h5, "line_comparisons", lines, ["line_a", "line_b"])
        letters = _root_table(h5, "line_letters", lines, ["line"])
        sensitivity = _root_table(h5, "sensitivity", lines, ["line"])
        provenance = _provenance(h5)
        arrays = {"fit_candidates": _line_tables(h5, lines, "fit_candidates"),
                  "relaxation_fits": _line_tables(h5, lines, "relaxation/fits"),
                  "relaxation_points": relaxation_points(h5, lines),
                  "replicates": bootstrap_replicates(h5, lines)}
        arrays["loadings"], arrays["explained_variance"] = principal_components(h5, lines)
    for name in ("relaxation_points", "replicates", "loadings", "explained_variance"):
        if len(arrays[name]):
            arrays[name] = _in_line_order(arrays[name], lines)
    dataset = _combined([_line_dataset(path, line) for line in lines], lines)
    dataset.attrs = {name: value for name, value in attrs.items() if not isinstance(value, list)}
    samples = _samples_frame(dataset, lines)
    dataset["summary"] = summary_array(summary, lines)
    return Results(path, lines, samples, summary, correlations, fits, fit_parameters,
                   dataset, data_uncertainty=data_uncertainty, comparisons=comparisons, letters=letters,
                   sensitivity=sensitivity, attrs=attrs, provenance=provenance, **arrays)
