"""Explained variance of the principal components of each line's standardized inputs and outputs
(the engine's correlation-matrix PCA, results.h5 analysis/explained_variance_ratio): one panel per
line, a bar per component and the cumulative share as a line."""
import math

import numpy as np

from .errors import FigureSkipped
from .style import display_name, line_colors, new_figure, styled


@styled
def pca_figure(results):
    analysed = [line for line in results.lines
                if line.analysis is not None and line.analysis.explained_variance_ratio.size]
    if not analysed:
        raise FigureSkipped("PCA: no line has analysis/explained_variance_ratio in results.h5")
    colors = line_colors(results.line_names())
    columns = min(3, len(analysed))
    rows = math.ceil(len(analysed) / columns)
    components = max(line.analysis.explained_variance_ratio.size for line in analysed)
    width = max(3.0, 0.28 * components + 1.2)
    figure = new_figure(columns * width, rows * 2.9 + 0.5)
    axes = figure.subplots(rows, columns, squeeze=False, sharey=True).ravel()
    for ax, line in zip(axes, analysed):
        percent = 100 * line.analysis.explained_variance_ratio
        positions = np.arange(1, percent.size + 1)
        bars = ax.bar(positions, percent, color=colors[line.name], alpha=0.8, width=0.7)
        for position, bar in zip(positions, bars):
            bar.set_gid(f"{line.name}/PC{position}")
        ax.plot(positions, np.cumsum(percent), "o-", color="0.25", markersize=2.5, linewidth=1,
                label="cumulative", gid=f"{line.name}/cumulative")
        ax.set_xticks(positions, [f"PC{p}" for p in positions], rotation=90, fontsize=7)
        ax.set_ylim(0, 105)
        ax.set_title(f"{display_name(line.name)} (n = {line.analysis.samples_used})")
        if ax.get_subplotspec().is_first_col():
            ax.set_ylabel("explained variance (%)")
        ax.grid(axis="y", alpha=0.3)
        if line.analysis.notes:
            ax.text(0.98, 0.5, "\n".join(line.analysis.notes), transform=ax.transAxes, ha="right",
                    va="center", fontsize=6, wrap=True)
    axes[0].legend(loc="center right", frameon=False)
    for ax in axes[len(analysed):]:
        ax.remove()
    figure.suptitle(f"{results.campaign_name}: principal components of the standardized inputs "
                    "and outputs (samples with status ok)", fontsize=9)
    return figure
