"""First-order sensitivity indices of each line (results.h5 /sensitivity; src/sensitivity/README.md):
one panel per line, for every output a group of horizontal bars, one per input, with its 95 %
interval. S = Var(E[output | input]) / Var(output): the share of the output's variance that knowing
the input alone removes (with correlated inputs, including what it explains through its partners)."""
import math

import numpy as np

from .errors import FigureSkipped
from .style import display_name, new_figure, styled


# Page width (a journal's text width, 18 cm) and the height of one bar's slot: tick labels of
# 6.5 pt, the smallest print size the figures use, need about 0.09 in each.
PAGE_WIDTH_IN = 7.0
SLOT_IN = 0.11


def symbol(dataset, quantities):
    """The quantity a sensitivity dataset name stands for: the longest of the line's quantities
    that the name is, or begins with followed by its unit (k_N_per_m -> k, v_exp_um_per_s ->
    v_exp, and einf_pct -> einf although the line's column is einf_frac: the table names an input
    in its line file's unit); the name itself when none fits."""
    fitting = [q for q in quantities if dataset == q or dataset.startswith(q + "_")]
    return max(fitting, key=len) if fitting else dataset


def row_label(output, input_, quantities):
    """"p ← k": the output and the input whose share of its variance the bar is."""
    return f"{symbol(output, quantities)} ← {symbol(input_, quantities)}"


@styled
def sensitivity_figure(results):
    lines = [line for line in results.line_names() if results.sensitivity.get(line)]
    if not lines:
        raise FigureSkipped("sensitivity: results.h5 has no /sensitivity rows (no line with 30 samples of status ok)")
    columns = min(3, len(lines))
    rows = math.ceil(len(lines) / columns)
    # Per panel a slot per (output, input) bar and one between outputs; the tallest panel sets the height.
    slots = max(len({row[0] for row in results.sensitivity[line]}) * (len({row[1] for row in results.sensitivity[line]}) + 1)
                for line in lines)
    figure = new_figure(PAGE_WIDTH_IN, rows * (slots * SLOT_IN + 0.6) + 0.4)
    # Not sharex: a panel with no panel under it (the last row's gap) keeps its tick labels.
    axes = figure.subplots(rows, columns, squeeze=False).ravel()
    palette = [f"C{i}" for i in range(10)]
    for number, (ax, line) in enumerate(zip(axes, lines)):
        table = results.sensitivity[line]
        owner = next((candidate for candidate in results.lines if candidate.name == line), None)
        quantities = [column.quantity for column in owner.columns] if owner else []
        line_outputs = list(dict.fromkeys(row[0] for row in table))
        line_inputs = list(dict.fromkeys(row[1] for row in table))
        labels, positions = [], []
        for o, output in enumerate(line_outputs):
            for i, input_ in enumerate(line_inputs):
                _, _, index, low, high = next(r for r in table if r[0] == output and r[1] == input_)
                y = -(o * (len(line_inputs) + 1) + i)
                ax.barh(y, index, color=palette[i % len(palette)], alpha=0.8, height=0.8,
                        gid=f"{line}/{output}/{input_}")
                ax.errorbar(index, y, xerr=[[max(index - low, 0)], [max(high - index, 0)]], color="0.2",
                            capsize=1.5, linewidth=0.7)
                labels.append(row_label(output, input_, quantities))
                positions.append(y)
        ax.set_yticks(positions, labels, fontsize=6.5)
        ax.tick_params(axis="y", length=2, pad=1.5)
        ax.set_ylim(min(positions) - 0.8, 0.8)
        ax.axvline(0, color="0.5", linewidth=0.6)
        ax.set_xlim(-0.05, 1.05)
        ax.set_title(display_name(line), fontsize=8)
        ax.grid(axis="x", alpha=0.3)
        if number + columns >= len(lines):  # nothing drawn under this panel
            ax.set_xlabel("first-order index S (95 % interval)", fontsize=7)
    for ax in axes[len(lines):]:
        ax.remove()
    figure.suptitle(f"{results.campaign_name}: first-order sensitivity S = Var(E[output | input]) / Var(output)",
                    fontsize=8)
    return figure
