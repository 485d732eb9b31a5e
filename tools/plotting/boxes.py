"""Box plots per plant line of turgor p, modulus E, viscosity eta and growth rate v (one panel
per quantity the campaign computed): box q1-q3, line at the median, whiskers 10-90 %, and where
the data-uncertainty bootstrap ran a black error bar on the median spanning its 95 % data
interval (data_ci_low/high of summary.csv). Under a raw-data line's name the tubes its laws were
fitted to; samples that lack the quantity (flagged before it was computed) are left out and counted
under the box as flagged (the title states the samples per line); the box statistics are the rows
of summary.csv. Above each box, when the campaign compared its lines, their compact letters
(letters.py): lines sharing a letter are not distinguishable."""
import math

from matplotlib.lines import Line2D

from .box_drawing import draw_box, label_below, room_for_labels
from .errors import FigureSkipped
from .letters import draw_letters, room_for_letters
from .quantiles import spread_of
from .style import (LOG_QUANTITIES, axis_label, display_name, line_colors, long_name, new_figure,
                    readable_log_axis, styled)

BOX_QUANTITIES = ("p", "E", "eta", "v")


def flagged_counts(results, quantity):
    """{line: samples left out of `quantity`} for the lines that computed it."""
    return {line.name: line.counted(quantity)[1] for line in results.lines if line.column(quantity)}


DATA_INTERVAL_STYLE = {"color": "black", "linewidth": 2.2, "capsize": 5, "capthick": 1.4}
DATA_INTERVAL_LABEL = "median's 95 % data interval (bootstrap over tubes)"


def count_label(flagged):
    """Under a box, the samples it leaves out (the title states the samples per line; a box holds
    all of them but the flagged)."""
    return f"{flagged} flagged" if flagged else ""


def line_label(line):
    """A line's tick label: its name and, for a raw-data line, the tubes behind its laws (fewest-most
    over its variables)."""
    if not line.tubes:
        return display_name(line.name)
    fewest, most = line.tubes
    return f"{display_name(line.name)}\n" + (f"{fewest} tubes" if fewest == most else f"{fewest}-{most} tubes")


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
        label = count_label(flagged)
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
    ax.set_xticks(range(len(results.lines)), [line_label(line) for line in results.lines], rotation=45,
                  ha="right", rotation_mode="anchor")
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
    # A page's text width (7 in, 18 cm) for up to six lines: "1000 samples" under each box at 6.5 pt
    # needs about 0.6 in; more lines widen the figure rather than overlap their counts.
    panel_width = max(3.5, 0.62 * len(results.lines) + 0.4)
    figure = new_figure(columns * panel_width, rows * 3.0 + 0.5)
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
    figure.suptitle(f"{results.campaign_name}: {', '.join(long_name(q) for q in quantities)} per line, "
                    f"{results.samples_per_line} samples each", fontsize=9)
    return figure


def box_caption(results):
    """What the box figure shows, for a caption beside it (the report's, tools/plot's
    captions.md) rather than inside it, where it took five lines of the figure."""
    drew_intervals = any(line.data_intervals for line in results.lines)
    intervals = ("Black bar: the median's 95 % data interval (bootstrap over tubes)." if drew_intervals
                 else "No data interval (no bootstrap over tubes).")
    return (f"Box q1-q3, line at the median, whiskers 10-90 %. {intervals} Under a raw-data line's name: the "
            "tubes behind its laws (fewest-most over its variables). Under each box: the flagged samples lacking the "
            f"quantity, which are left out; the box holds the other of the {results.samples_per_line} Monte Carlo "
            "samples per line (v = 0 for no_growth counts)."
            + (" Letters: lines sharing a letter are not distinguishable (line comparisons)." if results.letters
               else ""))
