"""First-order sensitivity indices of each line (results.h5 /sensitivity; src/sensitivity/README.md):
one panel per line, for every output a group of horizontal bars, one per input, with its 95 %
interval. S = Var(E[output | input]) / Var(output): the share of the output's variance that knowing
the input alone removes (with correlated inputs, including what it explains through its partners)."""
import math

import numpy as np

from .errors import FigureSkipped
from .style import display_name, new_figure, styled


@styled
def sensitivity_figure(results):
    lines = [line for line in results.line_names() if results.sensitivity.get(line)]
    if not lines:
        raise FigureSkipped("sensitivity: results.h5 has no /sensitivity rows (no line with 30 samples of status ok)")
    columns = min(3, len(lines))
    rows = math.ceil(len(lines) / columns)
    first = results.sensitivity[lines[0]]
    inputs = list(dict.fromkeys(row[1] for row in first))
    outputs = list(dict.fromkeys(row[0] for row in first))
    height = 0.22 * len(inputs) * len(outputs) + 1.2
    figure = new_figure(columns * 3.6, rows * height + 0.5)
    axes = figure.subplots(rows, columns, squeeze=False, sharex=True).ravel()
    palette = [f"C{i}" for i in range(10)]
    for ax, line in zip(axes, lines):
        table = results.sensitivity[line]
        line_outputs = list(dict.fromkeys(row[0] for row in table))
        line_inputs = list(dict.fromkeys(row[1] for row in table))
        labels, positions = [], []
        for o, output in enumerate(line_outputs):
            for i, input_ in enumerate(line_inputs):
                output_, _, index, low, high = next(r for r in table if r[0] == output and r[1] == input_)
                y = -(o * (len(line_inputs) + 1) + i)
                ax.barh(y, index, color=palette[i % len(palette)], alpha=0.8, height=0.8,
                        gid=f"{line}/{output}/{input_}")
                ax.errorbar(index, y, xerr=[[max(index - low, 0)], [max(high - index, 0)]], color="0.2",
                            capsize=2, linewidth=0.8)
                labels.append(f"{output_}: {input_}")
                positions.append(y)
        ax.set_yticks(positions, labels, fontsize=6)
        ax.axvline(0, color="0.5", linewidth=0.6)
        ax.set_xlim(-0.05, 1.05)
        ax.set_title(display_name(line), fontsize=8)
        ax.grid(axis="x", alpha=0.3)
        if ax.get_subplotspec().is_last_row():
            ax.set_xlabel("first-order index S (95 % interval)")
    for ax in axes[len(lines):]:
        ax.remove()
    figure.suptitle(f"{results.campaign_name}: first-order sensitivity Var(E[output | input]) / Var(output), "
                    "rank estimator", fontsize=9)
    return figure
