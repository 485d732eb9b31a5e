"""The speed/accuracy trade measured by `growthuq tradeoff` (RESULTS_DIR/tradeoff.csv), one panel per
output: the half-width of each line's 95 % confidence interval of the median in % of its reference
median (the error one run should expect; a line per plant line) and the measured |median error|
against the largest run (open points, the reference run itself excluded), against the samples per
line on log-log axes, with the target precision drawn (growthuq tradeoff's --target, default 1 %).
A last panel: the run's wall time against the samples."""
import math

import numpy as np
from matplotlib.lines import Line2D

from .style import display_name, line_colors, long_name, new_figure, styled

FIDELITY_STYLES = ("-", "--", ":", "-.")
DEFAULT_TARGET_PCT = 1.0   # growthuq tradeoff's default --target
ERROR_FLOOR_PCT = 1e-4


def half_width_pct(row):
    """The median's 95 % CI half-width in % of the reference median (NaN without either)."""
    if not abs(row["reference_median"]) > 0:
        return math.nan  # no relative width around a zero (or missing) median
    return 100 * (row["median_ci_high"] - row["median_ci_low"]) / 2 / abs(row["reference_median"])


def reference_samples(rows):
    """{fidelity: the largest sample count}, the run the errors are measured against."""
    largest = {}
    for row in rows:
        largest[row["fidelity"]] = max(largest.get(row["fidelity"], 0), row["samples"])
    return largest


def _ordered(values):
    return list(dict.fromkeys(values))


def _positive(samples, values):
    """The points a log axis can show (an error of exactly 0, e.g. the reference line's calibrated v,
    cannot be drawn)."""
    samples, values = np.asarray(samples, dtype=float), np.asarray(values, dtype=float)
    keep = np.isfinite(values) & (values > 0)
    return samples[keep], values[keep]


def _quantity_panel(ax, rows, quantity, colors, styles, reference, target_pct):
    mine = [row for row in rows if row["quantity"] == quantity]
    for fidelity, line in _ordered((row["fidelity"], row["line"]) for row in mine):
        series = sorted((row for row in mine if row["fidelity"] == fidelity and row["line"] == line),
                        key=lambda row: row["samples"])
        color = colors.get(line, "0.3")
        samples, widths = _positive([r["samples"] for r in series], [half_width_pct(r) for r in series])
        ax.plot(samples, widths, styles[fidelity], color=color, linewidth=1.2,
                gid=f"{fidelity}/{line}/{quantity}/ci")
        compared = [r for r in series if r["samples"] < reference[fidelity]]
        samples, errors = _positive([r["samples"] for r in compared],
                                    [abs(r["median_error_pct"]) for r in compared])
        ax.plot(samples, errors, "o", mfc="none", mec=color, markersize=3.5, markeredgewidth=0.9,
                gid=f"{fidelity}/{line}/{quantity}/median")
    ax.axhline(target_pct, color="black", linestyle=(0, (4, 2)), linewidth=1.0, gid=f"{quantity}/target")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("samples per line")
    ax.set_ylabel("% of the median")
    ax.set_title(f"{quantity}: {long_name(quantity)}")
    ax.grid(alpha=0.3, which="major")
    # Errors below 1e-4 % are rounding, not sampling (the reference line's v equals its
    # measured median by the kappa calibration): keep them from stretching the axis.
    bottom, top = ax.get_ylim()
    if bottom < ERROR_FLOOR_PCT < top:
        ax.set_ylim(bottom=ERROR_FLOOR_PCT)


def _time_panel(ax, rows, styles):
    for fidelity in _ordered(row["fidelity"] for row in rows):
        by_samples = {}
        for row in rows:
            if row["fidelity"] == fidelity and math.isfinite(row["seconds"]):
                by_samples[row["samples"]] = max(by_samples.get(row["samples"], 0.0), row["seconds"])
        samples = sorted(by_samples)
        ax.plot(samples, [by_samples[s] for s in samples], styles[fidelity], marker="o", color="0.2",
                markersize=3, label=fidelity, gid=f"{fidelity}/seconds")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("samples per line")
    ax.set_ylabel("wall time (s)")
    ax.set_title("time of the run (all lines)")
    ax.grid(alpha=0.3, which="major")


def legend_handles(lines, colors, fidelities, styles, target_pct):
    """One entry per plant line (its colour), then what the marks mean."""
    handles = [Line2D([], [], color=colors[line], linewidth=1.6, label=display_name(line)) for line in lines]
    handles.append(Line2D([], [], color="0.3", linewidth=1.2, label="95 % CI half-width of the median"))
    handles.append(Line2D([], [], linestyle="none", marker="o", mfc="none", mec="0.3", markersize=4,
                          label="|median error| against the largest run"))
    handles.append(Line2D([], [], color="black", linestyle=(0, (4, 2)), linewidth=1.0,
                          label=f"target {target_pct:g} %"))
    if len(fidelities) > 1:
        handles += [Line2D([], [], color="0.3", linestyle=styles[f], label=f) for f in fidelities]
    return handles


@styled
def tradeoff_figure(rows, campaign_name, line_names=(), target_pct=DEFAULT_TARGET_PCT):
    """`rows` from tradeoff_data.read_tradeoff; `line_names` fixes the colours in campaign order
    (lines not among them follow)."""
    lines = _ordered(list(line_names) + [row["line"] for row in rows])
    lines = [line for line in lines if any(row["line"] == line for row in rows)]
    colors = line_colors(_ordered(list(line_names) + lines))
    fidelities = _ordered(row["fidelity"] for row in rows)
    styles = {f: FIDELITY_STYLES[i % len(FIDELITY_STYLES)] for i, f in enumerate(fidelities)}
    reference = reference_samples(rows)
    quantities = _ordered(row["quantity"] for row in rows)
    panels = len(quantities) + 1
    columns = min(3, panels)
    grid_rows = math.ceil(panels / columns)
    figure = new_figure(7.0, 2.3 * grid_rows + 1.0)
    # The legend in a strip of its own under the panels: constrained layout (matplotlib 3.6) makes no
    # room for a figure legend, and one hung under a panel squeezes that panel to its width.
    panel_area, legend_area = figure.subfigures(2, 1, height_ratios=(2.3 * grid_rows, 0.75))
    axes = panel_area.subplots(grid_rows, columns, squeeze=False).ravel()
    for ax, quantity in zip(axes, quantities):
        _quantity_panel(ax, rows, quantity, colors, styles, reference, target_pct)
    _time_panel(axes[len(quantities)], rows, styles)
    for ax in axes[panels:]:
        ax.remove()
    legend_area.legend(handles=legend_handles(lines, colors, fidelities, styles, target_pct), loc="center",
                       ncols=3, frameon=False, fontsize=7).set_gid("trade_legend")
    references = ", ".join(f"{samples} ({fidelity})" if len(reference) > 1 else f"{samples}"
                           for fidelity, samples in reference.items())
    figure.suptitle(f"{campaign_name}: precision of the medians against the samples per line "
                    f"(errors against the run of {references} samples)", fontsize=9)
    return figure
