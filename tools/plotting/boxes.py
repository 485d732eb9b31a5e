"""Box plots per plant line of turgor p, modulus E, viscosity eta and growth rate v (one panel
per quantity the campaign computed): box q1-q3, line at the median, whiskers 10-90 %, n under
each box. Samples with a flag are left out and counted under the box; the box statistics are
the rows of summary.csv. Above each box, when the campaign compared its lines, their compact
letters (letters.py): lines sharing a letter are not distinguishable."""
import math

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


def _draw_quantity(ax, results, quantity, colors):
    lows, unit, text_lines, lettered = [], "", 1, False
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
            letters = results.letters.get((line.name, quantity))
            if letters:
                draw_letters(ax, position, letters, spread.p90, f"{line.name}/{quantity}")
                lettered = True
        label = f"n = {spread.n}" + (f"\n{flagged} flagged" if flagged else "")
        label_below(ax, position, label, f"{line.name}/{quantity}")
        text_lines = max(text_lines, label.count("\n") + 1)
    if quantity in LOG_QUANTITIES and lows and min(lows) > 0:
        ax.set_yscale("log")
        readable_log_axis(ax.yaxis)
    room_for_labels(ax, text_lines)
    if lettered:
        room_for_letters(ax)
    ax.set_xlim(-0.6, len(results.lines) - 0.4)
    ax.set_xticks(range(len(results.lines)), results.line_names(), rotation=30, ha="right",
                  rotation_mode="anchor")
    ax.set_ylabel(axis_label(quantity, unit))
    ax.set_title(long_name(quantity))
    ax.grid(axis="y", which="major", alpha=0.3)


@styled
def box_figure(results):
    """One panel per quantity of p, E, eta, v that the campaign computed, one box per line."""
    quantities = [q for q in BOX_QUANTITIES if any(line.column(q) for line in results.lines)]
    if not quantities:
        raise FigureSkipped("box plots: none of p, E, eta, v among the campaign's outputs")
    columns = 2 if len(quantities) > 1 else 1
    rows = math.ceil(len(quantities) / columns)
    panel_width = max(3.2, 0.6 * len(results.lines) + 1.2)
    figure = new_figure(columns * panel_width, rows * 3.3 + 0.6)
    axes = figure.subplots(rows, columns, squeeze=False).ravel()
    colors = line_colors(results.line_names())
    for ax, quantity in zip(axes, quantities):
        _draw_quantity(ax, results, quantity, colors)
    for ax in axes[len(quantities):]:
        ax.remove()
    figure.suptitle(f"{results.campaign_name}: per line, box q1-q3, line median, whiskers 10-90 %"
                    "\nn: samples with status ok (for v also no_growth, v = 0); flagged samples "
                    "left out" + ("\nletters: lines sharing a letter are not distinguishable (line "
                                  "comparisons)" if results.letters else ""),
                    fontsize=9)
    return figure
