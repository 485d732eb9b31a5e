"""Predicted against measured growth rate per plant line. Left: per line the measured rates beside
the predicted ones. Measured: the line's tubes as points where the line was fitted to raw data
(results.h5 fit_data/v_exp), otherwise a hatched box of draws from its v_exp law (a line file holds
no tubes); predicted: the box of its samples (q1-q3, whiskers 10-90 %). A black bar on each median
spans its 95 % data interval where the bootstrap over tubes ran. Right: each line's median
predicted rate against its median measured rate, with the data intervals as bars (10-90 % ranges
when some line has no data interval), against the 1:1 line. kappa is calibrated on the reference
line (Eq. (G5), src/growth/README.md), so that line agrees by construction; the others are
predictions."""
import math

import numpy as np

from .box_drawing import draw_box, label_below, room_for_labels
from .errors import FigureSkipped
from .quantiles import spread_of
from .style import axis_label, display_name, line_colors, new_figure, styled

PAIR_OFFSET = 0.2
TUBE_SPREAD = 0.12   # half-width of the strip the tube points are spread over
DATA_INTERVAL_STYLE = {"color": "black", "linewidth": 1.8, "capsize": 3.5, "capthick": 1.2, "zorder": 4}


def _spreads(results):
    """{line: (measured spread, predicted spread)} for the lines that have both columns."""
    pairs = {}
    for line in results.lines:
        if line.column("v") is not None and line.column("v_exp") is not None:
            pairs[line.name] = (spread_of(line.counted("v_exp")[0]), spread_of(line.counted("v")[0]))
    return pairs


def _unit(results):
    return next(line.column("v").unit for line in results.lines if line.column("v") is not None)


def strip_offsets(count):
    """Horizontal offsets of `count` tube points, evenly over [-TUBE_SPREAD, TUBE_SPREAD] in a
    fixed shuffled order (no random jitter: the figure is the same on every run)."""
    if count < 2:
        return np.zeros(count)
    even = np.linspace(-TUBE_SPREAD, TUBE_SPREAD, count)
    return even[np.argsort((np.arange(count) * 0.618034) % 1.0)]


def _data_interval(ax, position, median, interval, key):
    low, high = interval
    drawn = ax.errorbar([position], [median], yerr=[[median - low], [high - median]], fmt="none",
                        **DATA_INTERVAL_STYLE)
    drawn.lines[2][0].set_gid(f"{key}/data_interval")


def _measured(ax, position, line, spread, color):
    """The tubes as points, or the draws of a line file's law as a hatched box; the count label."""
    tubes = line.tube_values.get("v_exp")
    key = f"{line.name}/v_exp"
    if tubes is not None and tubes.size:
        ax.scatter(position + strip_offsets(tubes.size), tubes, s=9, color=color, alpha=0.8,
                   edgecolors="white", linewidths=0.3, zorder=3, gid=f"{key}/tubes")
        counted = f"{tubes.size} tubes"
    else:
        draw_box(ax, position, spread, color, key, width=0.34, hatch="////")
        counted = f"{spread.n} draws"
    if "v_exp" in line.data_intervals:
        _data_interval(ax, position, spread.median, line.data_intervals["v_exp"], key)
    return counted


def _paired_boxes(ax, results, pairs, colors):
    lines = [line for line in results.lines if line.name in pairs]
    for position, line in enumerate(lines):
        measured, predicted = pairs[line.name]
        counted = _measured(ax, position - PAIR_OFFSET, line, measured, colors[line.name]) if measured.n else ""
        if predicted.n:
            draw_box(ax, position + PAIR_OFFSET, predicted, colors[line.name], f"{line.name}/v", width=0.34)
            if "v" in line.data_intervals:
                _data_interval(ax, position + PAIR_OFFSET, predicted.median, line.data_intervals["v"],
                               f"{line.name}/v")
        label_below(ax, position, f"{counted}\n{predicted.n} samples", f"{line.name}/growth")
    room_for_labels(ax, 2)
    ax.set_xlim(-0.6, len(lines) - 0.4)
    ax.set_xticks(range(len(lines)), [display_name(line.name) for line in lines], rotation=30, ha="right",
                  rotation_mode="anchor")
    ax.set_ylabel(axis_label("v", _unit(results)))
    ax.set_title("each line: measured (left), predicted (right)", fontsize=8)
    ax.grid(axis="y", alpha=0.3)


def bar_kind(results, pairs):
    """"data" when every line drawn has the data intervals of both v and v_exp, else "10-90"."""
    with_both = [line for line in results.lines if line.name in pairs
                 and {"v", "v_exp"} <= set(line.data_intervals)]
    return "data" if len(with_both) == len(pairs) else "10-90"


def _bar(spread, line, quantity, kind):
    low, high = line.data_intervals[quantity] if kind == "data" else (spread.p10, spread.p90)
    return [[spread.median - low], [high - spread.median]], (low, high)


def _medians_against_one_to_one(ax, results, pairs, colors):
    unit = _unit(results)
    kind = bar_kind(results, pairs)
    ends = []
    for line in results.lines:
        if line.name not in pairs:
            continue
        measured, predicted = pairs[line.name]
        if not (measured.n and predicted.n):
            continue
        reference = line.name == results.reference_line
        xerr, x_ends = _bar(measured, line, "v_exp", kind)
        yerr, y_ends = _bar(predicted, line, "v", kind)
        label = display_name(line.name) + (" (reference)" if reference else "")
        drawn = ax.errorbar([measured.median], [predicted.median], xerr=xerr, yerr=yerr,
                            fmt="s" if reference else "o", color=colors[line.name], markersize=5,
                            mfc="white" if reference else colors[line.name], elinewidth=1.2, capsize=2.5,
                            label=label)
        drawn.lines[0].set_gid(f"{line.name}/median_point")
        horizontal, vertical = drawn.lines[2]
        horizontal.set_gid(f"{line.name}/v_exp_range")
        vertical.set_gid(f"{line.name}/v_range")
        ends += [*x_ends, *y_ends]
    if ends:
        low, high = min(ends), max(ends)
        margin = 0.06 * (high - low)
        limits = (max(0.0, low - margin), high + margin)
        ax.plot(limits, limits, "--", color="0.5", linewidth=1, label="1:1", gid="one_to_one")
        ax.set_xlim(limits)
        ax.set_ylim(limits)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(f"measured {axis_label('v_exp', unit)}")
    ax.set_ylabel(f"predicted {axis_label('v', unit)}")
    ax.set_title("medians\nbars: " + ("95 % data intervals" if kind == "data" else "10-90 % ranges"), fontsize=8)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.24), ncols=1, frameon=False, fontsize=7)


def calibration_note(results):
    if results.reference_line is None or not math.isfinite(results.kappa):
        return "kappa: not recorded in results.h5."
    return (f"kappa = {results.kappa:.4g} is calibrated on {display_name(results.reference_line)}: its "
            "median predicted rate (over growing tubes) equals its measured median by construction; "
            "the other lines are predictions.")


def growth_rate_caption(results):
    """The figure's caption (captions.md, the report): what the marks are, and the calibration."""
    return ("Measured against predicted growth rate per line. Left: the measured rates (points: the tubes "
            "of a raw-data line; hatched box: draws from a line file's v_exp law, which holds no tubes) "
            "beside the predicted v of the line's samples (box q1-q3, whiskers 10-90 %); black bars: the "
            "medians' 95 % data intervals (bootstrap over tubes) where it ran. Right: median predicted "
            "against median measured rate, with the 1:1 line. " + calibration_note(results))


@styled
def growth_rate_figure(results):
    if not any(line.column("v") is not None for line in results.lines):
        raise FigureSkipped("predicted vs measured growth rate: v is not among the campaign's outputs")
    pairs = _spreads(results)
    if not pairs:
        raise FigureSkipped("predicted vs measured growth rate: no v_exp_um_per_s in results.h5 "
                            "(add v_exp to the campaign's outputs)")
    colors = line_colors(results.line_names())
    figure = new_figure(7.0, 4.0)
    left, right = figure.subplots(1, 2, width_ratios=(2.0, 1.0))
    _paired_boxes(left, results, pairs, colors)
    _medians_against_one_to_one(right, results, pairs, colors)
    figure.suptitle(f"{results.campaign_name}: growth rate, measured and predicted", fontsize=9)
    return figure
