"""A campaign's results.h5 (layout: campaigns/README.md, section "results.h5") read into plain
objects: per line the columns with their quantity, unit and role, the sample statuses, the stored
analysis, the data-uncertainty intervals of its medians and the tubes behind its fitted laws and, when
present, the relaxation curves and the force curves. Which samples count follows growthuq's summaries: those holding a value
of the quantity (every sample for an input; for an output, those whose model computed it, whatever flag
a later model gave the sample, and v = 0 of no_growth); the correlogram, like the engine's analysis,
uses status ok only."""
import configparser
from dataclasses import dataclass, field
from pathlib import Path

import h5py
import numpy as np

from .errors import PlotInputError
from .h5text import as_text, text_attribute, text_list
from .letters import read_letters
from .force_curves_data import read_force_curves
from .relaxation_data import read_relaxation

COLUMN_ATTRIBUTES = ("quantity", "unit", "role")


@dataclass
class Column:
    name: str        # dataset name, e.g. p_MPa
    quantity: str    # p
    unit: str        # MPa
    role: str        # input or output
    values: np.ndarray


@dataclass
class Analysis:
    explained_variance_ratio: np.ndarray   # per component, descending
    variables: list                        # rows of the loadings: inputs, then outputs
    samples_used: int
    notes: list


@dataclass
class Line:
    name: str
    columns: list                          # Column, inputs then outputs
    status: np.ndarray                     # status name per sample
    analysis: Analysis = None
    relaxation: list = None                # RelaxationCurve, or None without curves
    data_intervals: dict = field(default_factory=dict)  # quantity: (data_ci_low, data_ci_high)
    tubes: tuple = None                    # (fewest, most) tubes or curves a law of the line was
                                           # fitted to (raw-data lines); None for line files
    tube_values: dict = field(default_factory=dict)  # variable: the values its law was fitted to, one
                                           # per tube (/lines/<line>/fit_data; raw-data lines only)
    force_curves: tuple = None             # ([ForceCurve], [Tube]) of force_curves_data.py, or None

    def column(self, quantity):
        return next((column for column in self.columns if column.quantity == quantity), None)

    def counted(self, quantity):
        """Values of `quantity` over the samples growthuq's summary counts (those holding a value:
        NaN marks a sample the quantity lacks), and how many lack it (summary.csv's n_flagged)."""
        column = self.column(quantity)
        keep = np.isfinite(column.values)
        return column.values[keep], int(keep.size - keep.sum())

    def ok_samples(self):
        return self.status == "ok"


@dataclass
class Results:
    path: Path
    campaign_name: str
    reference_line: str          # the line kappa is calibrated on; None without growth
    kappa: float                 # NaN when the campaign has no growth output
    samples_per_line: int
    lines: list = field(default_factory=list)
    letters: dict = field(default_factory=dict)  # {(line, quantity): compact letters}, letters.py
    # First-order sensitivity indices (results.h5 /sensitivity, src/sensitivity/README.md):
    # {line: [(output, input, index, ci_low, ci_high)]} in the table's order.
    sensitivity: dict = field(default_factory=dict)

    def line_names(self):
        return [line.name for line in self.lines]


def _campaign_keys(text):
    """(name, reference_line) from the campaign file text stored in the results; None when the
    text does not parse (the plots then say less, but still draw)."""
    parser = configparser.ConfigParser(interpolation=None, strict=False,
                                       comment_prefixes=("#", ";"), inline_comment_prefixes=None)
    try:
        parser.read_string(text)
    except configparser.Error:
        return None, None
    return (parser.get("campaign", "name", fallback=None),
            parser.get("growth", "reference_line", fallback=None))


def _required(node, key, where, expected):
    if key not in node:
        raise PlotInputError(f"{where}/{key}: missing (expected {expected})")
    return node[key]


def _line_order(h5):
    """Lines in campaign order: the root attribute line_order (in files written before it, the
    order of the root summary table), then any other group."""
    groups = list(h5["lines"].keys())
    if "line_order" in h5.attrs:
        order = [name for name in text_list(h5.attrs["line_order"]) if name in groups]
    else:
        order = []
        if "summary" in h5 and h5["summary"].dtype.names and "line" in h5["summary"].dtype.names:
            for name in text_list(h5["summary"]["line"]):
                if name in groups and name not in order:
                    order.append(name)
    return order + [name for name in groups if name not in order]


def _read_columns(group, where):
    columns = []
    for key, node in group.items():
        if not hasattr(node, "dtype") or node.dtype.names or len(node.shape) != 1:
            continue
        if not all(attribute in node.attrs for attribute in COLUMN_ATTRIBUTES):
            continue
        quantity, unit, role = (text_attribute(node, attribute) for attribute in COLUMN_ATTRIBUTES)
        columns.append(Column(key, quantity, unit, role, np.asarray(node[()], dtype=float)))
    if not columns:
        raise PlotInputError(f"{where}: no column datasets (expected float64 datasets such as "
                             "p_MPa with attributes quantity, unit and role)")
    return columns


def _read_analysis(group):
    if "analysis" not in group or "explained_variance_ratio" not in group["analysis"]:
        return None
    analysis = group["analysis"]
    variables = text_list(analysis["loadings"].attrs.get("rows", [])) if "loadings" in analysis else []
    return Analysis(np.asarray(analysis["explained_variance_ratio"][()], dtype=float), variables,
                    int(analysis.attrs.get("samples_used", 0)), text_list(analysis.attrs.get("notes", [])))


def _order_columns(columns, analysis):
    """Inputs then outputs, in the engine's analysis order when there is one."""
    rank = {name: i for i, name in enumerate(analysis.variables)} if analysis else {}
    role_rank = {"input": 0, "output": 1}
    return sorted(columns, key=lambda column: (role_rank.get(column.role, 2),
                                               rank.get(column.name, len(rank))))


def _read_line(h5, name, path):
    where = f"{path}:/lines/{name}"
    group = h5["lines"][name]
    status_dataset = _required(group, "status", where, "uint8 status codes with attribute names")
    if "names" not in status_dataset.attrs:
        raise PlotInputError(f"{where}/status: attribute 'names' missing (expected the status "
                             "name of each code)")
    names = np.array(text_list(status_dataset.attrs["names"]), dtype=object)
    codes = status_dataset[()].astype(np.int64)
    if codes.size and (codes.min() < 0 or codes.max() >= names.size):
        raise PlotInputError(f"{where}/status: code {int(codes.max())}; expected 0 to {names.size - 1}")
    analysis = _read_analysis(group)
    columns = _order_columns(_read_columns(group, where), analysis)
    for column in columns:
        if column.values.size != codes.size:
            raise PlotInputError(f"{where}/{column.name}: {column.values.size} values; expected "
                                 f"{codes.size}, one per sample as in status")
    relaxation = (read_relaxation(group["relaxation"], f"{where}/relaxation")
                  if "relaxation" in group else None)
    force_curves = (read_force_curves(group["force_curves"], f"{where}/force_curves")
                    if "force_curves" in group else None)
    return Line(name, columns, names[codes], analysis, relaxation, _data_intervals(group),
                _tubes(group), _tube_values(group), force_curves)


def _data_intervals(group):
    """{quantity: (low, high)} of the line's summary rows with a data-uncertainty interval
    (data_ci_low/high, finite only where the bootstrap ran)."""
    if "summary" not in group or "data_ci_low" not in (group["summary"].dtype.names or ()):
        return {}
    intervals = {}
    for row in group["summary"][()]:
        low, high = float(row["data_ci_low"]), float(row["data_ci_high"])
        if np.isfinite(low) and np.isfinite(high):
            quantity = row["quantity"]
            intervals[quantity.decode() if isinstance(quantity, bytes) else quantity] = (low, high)
    return intervals


def _tubes(group):
    """The fewest and most tubes (or relaxation curves) behind the line's fitted laws: the n of
    its fits table, which only raw-data lines have."""
    if "fits" not in group or "n" not in (group["fits"].dtype.names or ()):
        return None
    counts = [int(n) for n in group["fits"]["n"]]
    return (min(counts), max(counts)) if counts else None


def _tube_values(group):
    """{variable: the measured values its law was fitted to}; empty for a line file's line (and in
    files written before fit_data was stored)."""
    if "fit_data" not in group:
        return {}
    # The arrays carry the attribute units; the group's dimension scales (tube, tube_31, ...) do not.
    return {name: np.asarray(node[()], dtype=float) for name, node in group["fit_data"].items()
            if hasattr(node, "dtype") and len(node.shape) == 1 and "units" in node.attrs}


def _read_sensitivity(h5):
    if "sensitivity" not in h5:
        return {}
    table = h5["sensitivity"][()]
    rows = {}
    for line, output, input_, index, low, high in zip(table["line"], table["output"], table["input"], table["index"],
                                                      table["ci_low"], table["ci_high"]):
        rows.setdefault(as_text(line), []).append((as_text(output), as_text(input_), float(index), float(low),
                                                   float(high)))
    return rows


def read_results(path):
    """The results of `growthuq run` at `path` (a results.h5). Raises PlotInputError naming the
    file and what was expected when it is missing, not HDF5 or not growthuq's layout."""
    path = Path(path)
    if not path.is_file():
        raise PlotInputError(f"{path}: no such file (expected the results.h5 that `growthuq run` "
                             "writes with hdf5 among its formats)")
    try:
        h5 = h5py.File(path, "r")
    except OSError as error:
        raise PlotInputError(f"{path}: not a readable HDF5 file ({error}); expected the "
                             "results.h5 of `growthuq run`") from None
    with h5:
        if "lines" not in h5 or "engine_version" not in h5.attrs:
            raise PlotInputError(f"{path}: not a growthuq results file (expected the group /lines "
                                 "and the root attribute engine_version)")
        campaign_name, reference_line = _campaign_keys(text_attribute(h5, "campaign_text", ""))
        kappa = float(h5.attrs["kappa"]) if "kappa" in h5.attrs else float("nan")
        samples = int(h5.attrs["samples_per_line"]) if "samples_per_line" in h5.attrs else 0
        results = Results(path, campaign_name or path.parent.name, reference_line, kappa, samples)
        for name in _line_order(h5):
            results.lines.append(_read_line(h5, name, path))
        results.letters = read_letters(h5, path)
        results.sensitivity = _read_sensitivity(h5)
    if not results.lines:
        raise PlotInputError(f"{path}:/lines: no line groups (expected one group per plant line)")
    return results
