"""Predicted against measured growth rate per plant line. Left: paired boxes (measured v_exp
hatched, predicted v filled; box q1-q3, whiskers 10-90 %). Right: each line's median predicted
rate against its median measured rate, with 10-90 % bars both ways, against the 1:1 line. kappa
is calibrated on the reference line (Eq. (G5), src/growth/README.md), so that line agrees by
construction; the others are predictions."""
import math
import textwrap

from .box_drawing import draw_box, label_below, room_for_labels
from .errors import FigureSkipped
from .quantiles import spread_of
from .style import axis_label, line_colors, new_figure, styled

PAIR_OFFSET = 0.2


def _spreads(results):
    """{line: (measured spread, predicted spread)} for the lines that have both columns."""
    pairs = {}
    for line in results.lines:
        if line.column("v") is not None and line.column("v_exp") is not None:
            pairs[line.name] = (spread_of(line.counted("v_exp")[0]), spread_of(line.counted("v")[0]))
    return pairs


def _unit(results):
    return next(line.column("v").unit for line in results.lines if line.column("v") is not None)


def _paired_boxes(ax, results, pairs, colors):
    names = list(pairs)
    for position, name in enumerate(names):
        measured, predicted = pairs[name]
        for offset, spread, kind, hatch in ((-PAIR_OFFSET, measured, "v_exp", "////"),
                                            (PAIR_OFFSET, predicted, "v", None)):
            if spread.n:
                draw_box(ax, position + offset, spread, colors[name], f"{name}/{kind}", width=0.34,
                         hatch=hatch)
        # The measured box is the line's fitted v_exp law sampled, not its tubes: say draws.
        label_below(ax, position, f"{measured.n} draws\n{predicted.n} samples", f"{name}/growth")
    room_for_labels(ax, 2)
    ax.set_xlim(-0.6, len(names) - 0.4)
    ax.set_xticks(range(len(names)), names, rotation=30, ha="right", rotation_mode="anchor")
    ax.set_ylabel(axis_label("v", _unit(results)))
    ax.set_title("measured (hatched: draws from the fitted v_exp law) and predicted (filled)")
    ax.grid(axis="y", alpha=0.3)


def _medians_against_one_to_one(ax, results, pairs, colors):
    unit = _unit(results)
    ends = []
    for name, (measured, predicted) in pairs.items():
        if not (measured.n and predicted.n):
            continue
        reference = name == results.reference_line
        drawn = ax.errorbar([measured.median], [predicted.median],
                            xerr=[[measured.median - measured.p10], [measured.p90 - measured.median]],
                            yerr=[[predicted.median - predicted.p10], [predicted.p90 - predicted.median]],
                            fmt="s" if reference else "o", color=colors[name], markersize=6,
                            mfc="white" if reference else colors[name], elinewidth=1.2, capsize=2.5,
                            label=f"{name} (reference)" if reference else name)
        drawn.lines[0].set_gid(f"{name}/median_point")
        horizontal, vertical = drawn.lines[2]
        horizontal.set_gid(f"{name}/v_exp_range")
        vertical.set_gid(f"{name}/v_range")
        ends += [measured.p10, measured.p90, predicted.p10, predicted.p90]
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
    ax.set_title("medians, bars 10-90 %")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)


def calibration_note(results):
    if results.reference_line is None or not math.isfinite(results.kappa):
        return "kappa: not recorded in results.h5"
    return (f"kappa = {results.kappa:.4g} is calibrated on {results.reference_line}: its median "
            "predicted rate (over growing tubes) equals its measured median by construction; "
            "the other lines are predictions.")


@styled
def growth_rate_figure(results):
    if not any(line.column("v") is not None for line in results.lines):
        raise FigureSkipped("predicted vs measured growth rate: v is not among the campaign's outputs")
    pairs = _spreads(results)
    if not pairs:
        raise FigureSkipped("predicted vs measured growth rate: no v_exp_um_per_s in results.h5 "
                            "(add v_exp to the campaign's outputs)")
    colors = line_colors(results.line_names())
    figure = new_figure(max(9.0, 1.1 * len(pairs) + 6.0), 4.4)
    left, right = figure.subplots(1, 2, width_ratios=(1.3, 1.0))
    _paired_boxes(left, results, pairs, colors)
    _medians_against_one_to_one(right, results, pairs, colors)
    figure.suptitle(f"{results.campaign_name}: growth rate, predicted vs measured\n"
                    + textwrap.fill(calibration_note(results), 110), fontsize=9)
    return figure
