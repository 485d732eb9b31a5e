"""Box plots per plant line of turgor p, modulus E, viscosity eta and growth rate v (one panel
per quantity the campaign computed): box q1-q3, line at the median, whiskers 10-90 %, and where
the data-uncertainty bootstrap ran a black error bar on the median spanning its 95 % data
interval (data_ci_low/high of summary.csv). Under each box what it counts: the samples, and for
a raw-data line the tubes its laws were fitted to. Samples that lack the quantity (flagged before
it was computed) are left out and counted under the box; the box statistics are the rows of
summary.csv. Above each box, when the campaign compared its lines, their compact letters
(letters.py): lines sharing a letter are not distinguishable."""
import math

from matplotlib.lines import Line2D

from .box_drawing import draw_box, label_below, room_for_labels
from .errors import FigureSkipped
from .letters import draw_letters, room_for_letters
from .quantiles import spread_of
from .style import (LOG_QUANTITIES, axis_label, line_colors, long_name, new_figure,
                    readable_log_axis, styled)

BOX_QUANTITIES = ("p", "E", "eta", "v")


def flagged_counts(results, quantity):
    """{line: samples left out of `quantity`} for the lines that computed it."""
    return {line.name: line.counted(quantity)[1] for line in results.lines if line.column(quantity)}


DATA_INTERVAL_STYLE = {"color": "black", "linewidth": 2.2, "capsize": 5, "capthick": 1.4}
DATA_INTERVAL_LABEL = "median's 95 % data interval (bootstrap over tubes)"


def count_label(spread_n, flagged, tubes):
    """What a box counts: "997 samples", the tubes behind a raw-data line's laws, the flagged."""
    label = f"{spread_n} samples"
    if tubes:
        fewest, most = tubes
        label += f"\n{fewest} tubes" if fewest == most else f"\n{fewest}-{most} tubes"
    return label + (f"\n{flagged} flagged" if flagged else "")


def _draw_data_interval(ax, position, median, interval, key):
    """A black error bar on the median spanning the data interval [low, high]."""
    low, high = interval
    drawn = ax.errorbar([position], [median], yerr=[[median - low], [high - median]], fmt="none",
                        zorder=4, **DATA_INTERVAL_STYLE)
    drawn.lines[2][0].set_gid(f"{key}/data_interval")
    return drawn


def _draw_quantity(ax, results, quantity, colors):
    lows, unit, text_lines, intervals, lettered = [], "", 1, 0, False
    for position, line in enumerate(results.lines):
        column = line.column(quantity)
        if column is None:
            label_below(ax, position, "not computed", f"{line.name}/{quantity}")
            continue
        unit = column.unit
        values, flagged = line.counted(quantity)
        spread = spread_of(values)
        if spread.n:
            draw_box(ax, position, spread, colors[line.name], f"{line.name}/{quantity}")
            lows.append(spread.p10)
            if quantity in line.data_intervals:
                interval = line.data_intervals[quantity]
                _draw_data_interval(ax, position, spread.median, interval, f"{line.name}/{quantity}")
                lows.append(interval[0])
                intervals += 1
            letters = results.letters.get((line.name, quantity))
            if letters:
                draw_letters(ax, position, letters, spread.p90, f"{line.name}/{quantity}")
                lettered = True
        label = count_label(spread.n, flagged, line.tubes)
        label_below(ax, position, label, f"{line.name}/{quantity}")
        text_lines = max(text_lines, label.count("\n") + 1)
    log = quantity in LOG_QUANTITIES and lows and min(lows) > 0
    if log:
        ax.set_yscale("log")
        readable_log_axis(ax.yaxis)
    room_for_labels(ax, text_lines)
    if lettered:
        room_for_letters(ax)
    ax.set_xlim(-0.6, len(results.lines) - 0.4)
    ax.set_xticks(range(len(results.lines)), results.line_names(), rotation=30, ha="right",
                  rotation_mode="anchor")
    ax.set_ylabel(axis_label(quantity, unit))
    # Log panels sit beside linear ones: the title says which.
    ax.set_title(long_name(quantity) + (" (log scale)" if log else ""))
    ax.grid(axis="y", which="major", alpha=0.3)
    return intervals


@styled
def box_figure(results):
    """One panel per quantity of p, E, eta, v that the campaign computed, one box per line."""
    quantities = [q for q in BOX_QUANTITIES if any(line.column(q) for line in results.lines)]
    if not quantities:
        raise FigureSkipped("box plots: none of p, E, eta, v among the campaign's outputs")
    columns = 2 if len(quantities) > 1 else 1
    rows = math.ceil(len(quantities) / columns)
    panel_width = max(3.2, 0.8 * len(results.lines) + 1.2)  # room for "1000 samples" under each box
    figure = new_figure(columns * panel_width, rows * 3.3 + 0.6)
    axes = figure.subplots(rows, columns, squeeze=False).ravel()
    colors = line_colors(results.line_names())
    drew_intervals = False
    for ax, quantity in zip(axes, quantities):
        if _draw_quantity(ax, results, quantity, colors) and not drew_intervals:
            # Above the panel's title, where it covers no box (the layout makes room for it).
            ax.legend(handles=[Line2D([], [], color="black", linewidth=2.2, label=DATA_INTERVAL_LABEL)],
                      loc="lower left", bbox_to_anchor=(0.0, 1.1), fontsize=7,
                      frameon=False).set_gid("data_interval_legend")
            drew_intervals = True
    for ax in axes[len(quantities):]:
        ax.remove()
    figure.suptitle(f"{results.campaign_name}: {', '.join(long_name(q) for q in quantities)} per line", fontsize=9)
    return figure


def box_caption(results):
    """What the box figure shows, for a caption beside it (the report's, tools/plot's
    captions.md) rather than inside it, where it took five lines of the figure."""
    drew_intervals = any(line.data_intervals for line in results.lines)
    intervals = ("Black bar: the median's 95 % data interval (bootstrap over tubes)." if drew_intervals
                 else "No data interval (no bootstrap over tubes).")
    return (f"Box q1-q3, line at the median, whiskers 10-90 %. {intervals} Under each box: the Monte Carlo samples "
            "holding a value (v = 0 for no_growth counts), the tubes behind a raw-data line's laws, and the "
            "flagged samples lacking the quantity, which are left out."
            + (" Letters: lines sharing a letter are not distinguishable (line comparisons)." if results.letters
               else ""))
