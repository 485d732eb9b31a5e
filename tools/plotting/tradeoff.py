"""The speed/accuracy trade measured by `growthuq tradeoff` (RESULTS_DIR/tradeoff.csv): per
quantity, the error of the median and of the IQR against the largest run, in %, against the
samples per line (log-log, one colour per line), beside the half-width of the median's 95 %
confidence interval in % of the reference median (the error one run should expect); and the
wall time against the samples. The reference run itself (errors 0) is not drawn."""
import math

import numpy as np
from matplotlib.lines import Line2D

from .style import axis_label, line_colors, new_figure, styled

FIDELITY_MARKERS = ("o", "s", "^", "D")
SERIES = (("median", "-", "|median error|"),
          ("iqr", "--", "|IQR error|"),
          ("ci", ":", "95 % CI half-width of the median"))


def series_value(row, series):
    """The plotted percentage of one row: |median error|, |IQR error| or the CI half-width."""
    if series == "median":
        return abs(row["median_error_pct"])
    if series == "iqr":
        return abs(row["iqr_error_pct"])
    if not abs(row["reference_median"]) > 0:
        return math.nan  # no relative width around a zero (or missing) median
    return 100 * (row["median_ci_high"] - row["median_ci_low"]) / 2 / abs(row["reference_median"])


def reference_samples(rows):
    """{fidelity: the largest sample count}, the run the errors are measured against."""
    largest = {}
    for row in rows:
        largest[row["fidelity"]] = max(largest.get(row["fidelity"], 0), row["samples"])
    return largest


ERROR_FLOOR_PCT = 1e-4


def _ordered(values):
    return list(dict.fromkeys(values))


def _quantity_panel(ax, rows, quantity, colors, markers, reference):
    mine = [row for row in rows if row["quantity"] == quantity
            and row["samples"] < reference[row["fidelity"]]]
    for (fidelity, line) in _ordered((row["fidelity"], row["line"]) for row in mine):
        series_rows = sorted((row for row in mine if row["fidelity"] == fidelity and row["line"] == line),
                             key=lambda row: row["samples"])
        samples = np.array([row["samples"] for row in series_rows], dtype=float)
        for series, style, _ in SERIES:
            values = np.array([series_value(row, series) for row in series_rows])
            drawable = np.isfinite(values) & (values > 0)  # a log axis cannot show 0
            ax.plot(samples[drawable], values[drawable], style, marker=markers[fidelity],
                    markersize=3 if series != "ci" else 0, color=colors.get(line, "0.3"),
                    linewidth=1.1, gid=f"{fidelity}/{line}/{quantity}/{series}")
    unit = next((row["unit"] for row in mine), "")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("samples per line")
    ax.set_ylabel("error (% of reference)")
    ax.set_title(axis_label(quantity, unit))
    ax.grid(alpha=0.3, which="major")
    # Errors below 1e-4 % are rounding, not sampling (the reference line's v equals its
    # measured median by the kappa calibration): keep them from stretching the axis.
    bottom, top = ax.get_ylim()
    if bottom < ERROR_FLOOR_PCT < top:
        ax.set_ylim(bottom=ERROR_FLOOR_PCT)


def _time_panel(ax, rows, markers):
    for fidelity in _ordered(row["fidelity"] for row in rows):
        by_samples = {}
        for row in rows:
            if row["fidelity"] == fidelity and math.isfinite(row["seconds"]):
                by_samples[row["samples"]] = max(by_samples.get(row["samples"], 0.0), row["seconds"])
        samples = sorted(by_samples)
        ax.plot(samples, [by_samples[s] for s in samples], "-", marker=markers[fidelity],
                color="0.2", markersize=3.5, label=fidelity, gid=f"{fidelity}/seconds")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("samples per line")
    ax.set_ylabel(axis_label("wall time", "s"))
    ax.set_title("time of the run (all lines)")
    ax.add_artist(ax.legend(title="fidelity", loc="upper left", frameon=False))
    ax.grid(alpha=0.3, which="major")


@styled
def tradeoff_figure(rows, campaign_name, line_names=()):
    """`rows` from tradeoff_data.read_tradeoff; `line_names` fixes the colours in campaign order
    (lines not among them follow)."""
    lines = _ordered(list(line_names) + [row["line"] for row in rows])
    colors = line_colors(lines)
    fidelities = _ordered(row["fidelity"] for row in rows)
    markers = {f: FIDELITY_MARKERS[i % len(FIDELITY_MARKERS)] for i, f in enumerate(fidelities)}
    reference = reference_samples(rows)
    quantities = _ordered(row["quantity"] for row in rows)
    panels = len(quantities) + 1
    columns = min(3, panels)
    grid_rows = math.ceil(panels / columns)
    figure = new_figure(3.6 * columns + 1.8, 3.0 * grid_rows + 0.6)
    axes = figure.subplots(grid_rows, columns, squeeze=False).ravel()
    for ax, quantity in zip(axes, quantities):
        _quantity_panel(ax, rows, quantity, colors, markers, reference)
    time_panel = axes[len(quantities)]
    _time_panel(time_panel, rows, markers)
    for ax in axes[panels:]:
        ax.remove()
    line_handles = [Line2D([], [], linestyle="-", color=colors[line], label=line)
                    for line in lines if any(row["line"] == line for row in rows)]
    style_handles = [Line2D([], [], linestyle=style, color="0.3", label=label)
                     for _, style, label in SERIES]
    # Beside the time panel: constrained layout (matplotlib 3.6) makes room for an axes legend
    # outside its axes, not for a figure legend.
    time_panel.legend(handles=line_handles + style_handles, loc="upper left",
                      bbox_to_anchor=(1.04, 1.0), frameon=False)
    references = ", ".join(f"{samples} ({fidelity})" if len(reference) > 1 else str(samples)
                           for fidelity, samples in reference.items())
    figure.suptitle(f"{campaign_name}: error against the reference run of {references} samples "
                    "per line, and time", fontsize=9)
    return figure
