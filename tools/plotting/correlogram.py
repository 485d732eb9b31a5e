"""Correlogram of one plant line's inputs and outputs over its samples with status ok (the samples
of the engine's analysis): histograms on the diagonal, scatter plots below it, Spearman rank
correlation coefficients above it, shaded by sign and strength. A column constant over those
samples has no rank correlation and is left out, as in the engine's analysis.

The k x k cells are drawn in one matplotlib Axes (cell (i, j) is the square [j, j + CELL] x
[k - 1 - i, k - 1 - i + CELL]; each variable is mapped onto [0, 1] across its cells) with the
tick labels drawn along the left and bottom edges: k^2 separate Axes take about 5x as long to
build and draw, mostly in tick machinery."""
import matplotlib
import numpy as np
from matplotlib import colors as mcolors
from matplotlib.collections import LineCollection
from matplotlib.patches import Rectangle
from matplotlib.ticker import LogLocator, MaxNLocator
from scipy.stats import rankdata

from .style import LOG_QUANTITIES, axis_label, display_name, line_colors, new_figure, styled

CELL = 0.9             # cell width; the rest of each unit is the gap between cells
CELL_INCHES = 1.0      # printed size of one unit, at most (see PAGE_WIDTH_INCHES)
# A journal page's text width (18 cm): a correlogram of 10 or more variables is printed at this
# width, not scaled down from a wider figure, so that its 6.5-8 pt text stays that size on paper.
PAGE_WIDTH_INCHES = 7.0
EDGE = 0.02            # beyond the outer cells, so that their frames are not clipped
MARGIN_LEFT, MARGIN_RIGHT, MARGIN_BOTTOM, MARGIN_TOP = 0.8, 0.1, 0.8, 0.35
HISTOGRAM_BINS = 20
CORRELATION_COLORS = "RdBu_r"
# Scatter cells show at most this many samples (the first ones: a Latin hypercube assigns strata
# to sample indices by a random permutation, so any prefix is an unbiased subsample); histograms
# and coefficients use every sample. Keeps files small and drawing fast for 1e6-sample campaigns.
SCATTER_POINTS = 2000


def rank_correlation(data):
    """Spearman's coefficient of every pair of columns of `data` (samples x variables): the
    Pearson correlation of the ranks, ties ranked by their average (Spearman 1904)."""
    ranks = np.column_stack([rankdata(column) for column in data.T])
    return np.corrcoef(ranks, rowvar=False)


def correlogram_columns(line):
    """The line's columns that vary over its ok samples (inputs, then outputs) and their values
    over those samples (samples x columns)."""
    ok = line.ok_samples()
    chosen = [column for column in line.columns
              if np.all(np.isfinite(column.values[ok])) and np.ptp(column.values[ok]) > 0]
    data = np.column_stack([column.values[ok] for column in chosen]) if chosen else np.empty((0, 0))
    return chosen, data


class CellScale:
    """One variable mapped onto [0, 1] across a cell, linearly or in log10 (quantities in
    LOG_QUANTITIES), with 5 % of free space at either end."""

    def __init__(self, column, values):
        self.log = column.quantity in LOG_QUANTITIES and values.min() > 0
        # The unit under the symbol: one line of "v_exp (µm/s)" is wider than a cell printed at page width.
        self.label = axis_label(column.quantity, column.unit).replace(" (", "\n(")
        transformed = self._transform(values)
        pad = 0.05 * (transformed.max() - transformed.min())
        self.low, self.high = transformed.min() - pad, transformed.max() + pad

    def _transform(self, values):
        values = np.asarray(values, dtype=float)
        return np.log10(values) if self.log else values

    def to_unit(self, values):
        return (self._transform(values) - self.low) / (self.high - self.low)

    def ticks(self):
        """Round values inside the cell to label: powers of ten (or 1-2-5 steps) on a log scale
        spanning enough decades for two of them, otherwise evenly spaced round numbers."""
        candidates = []
        if self.log:
            for subs in ((1.0,), (1.0, 2.0, 5.0)):
                candidates = LogLocator(base=10, subs=subs).tick_values(10 ** self.low, 10 ** self.high)
                if np.count_nonzero(self._inside(candidates)) >= 2:
                    break
            else:
                candidates = MaxNLocator(3).tick_values(10 ** self.low, 10 ** self.high)
        else:
            candidates = MaxNLocator(3).tick_values(self.low, self.high)
        candidates = np.asarray(candidates, dtype=float)
        return candidates[self._inside(candidates)]

    def _inside(self, values):
        values = np.asarray(values, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            unit = self.to_unit(np.where(values > 0, values, np.nan) if self.log else values)
        return np.isfinite(unit) & (unit >= -1e-9) & (unit <= 1 + 1e-9)


def _shade(value):
    red_blue = matplotlib.colormaps[CORRELATION_COLORS](mcolors.Normalize(-1, 1)(value))
    return (*red_blue[:3], 0.25 + 0.5 * abs(value))


def _edge_ticks(ax, scales, k):
    """Tick marks and labels along the bottom (columns) and left (rows 1..k-1; row 0's diagonal
    cell is a histogram, its height a count) edges, and each variable's label with its unit."""
    marks = []
    for j, scale in enumerate(scales):
        for value in scale.ticks():
            x = j + CELL * scale.to_unit(value)
            marks.append([(x, 0), (x, -0.04)])
            ax.annotate(f"{value:g}", (x, 0), xytext=(0, -5), textcoords="offset points", ha="right",
                        va="top", rotation=45, rotation_mode="anchor", fontsize=6.5, gid=f"xtick/{j}")
        ax.annotate(scale.label, (j + CELL / 2, 0), xytext=(0, -26), textcoords="offset points",
                    ha="center", va="top", fontsize=7, gid=f"xlabel/{j}")
    for i, scale in enumerate(scales):
        y0 = k - 1 - i
        if i > 0:
            for value in scale.ticks():
                y = y0 + CELL * scale.to_unit(value)
                marks.append([(0, y), (-0.04, y)])
                ax.annotate(f"{value:g}", (0, y), xytext=(-5, 0), textcoords="offset points",
                            ha="right", va="center", fontsize=6.5, gid=f"ytick/{i}")
        # Beside the widest tick labels ("0.12" at 6.5 pt), its bottom (after the rotation) towards them.
        ax.annotate(scale.label, (0, y0 + CELL / 2), xytext=(-24, 0), textcoords="offset points",
                    ha="center", va="bottom", rotation=90, rotation_mode="anchor", fontsize=7,
                    gid=f"ylabel/{i}")
    ax.add_collection(LineCollection(marks, colors="0.2", linewidths=0.6))


@styled
def correlogram_figure(results, line):
    chosen, data = correlogram_columns(line)
    k = len(chosen)
    color = line_colors(results.line_names())[line.name]
    scales = [CellScale(column, data[:, i]) for i, column in enumerate(chosen)]
    unit = np.column_stack([scale.to_unit(data[:, i]) for i, scale in enumerate(scales)])
    rho = rank_correlation(data) if k > 1 else np.ones((k, k))
    # Fixed margins in inches around square cells of CELL_INCHES: room for the tick labels and
    # variable names at the left and bottom, for the title at the top.
    units = k - 1 + CELL + 2 * EDGE
    side = units * min(CELL_INCHES, (PAGE_WIDTH_INCHES - MARGIN_LEFT - MARGIN_RIGHT) / units)
    width, height = side + MARGIN_LEFT + MARGIN_RIGHT, side + MARGIN_BOTTOM + MARGIN_TOP
    figure = new_figure(width, height, layout=None)
    ax = figure.add_axes([MARGIN_LEFT / width, MARGIN_BOTTOM / height, side / width, side / height])
    ax.set_axis_off()
    ax.set_xlim(-EDGE, k - 1 + CELL + EDGE)
    ax.set_ylim(-EDGE, k - 1 + CELL + EDGE)
    for i in range(k):
        for j in range(k):
            key = f"{chosen[i].name}/{chosen[j].name}"
            x0, y0 = j, k - 1 - i
            background = _shade(rho[i, j]) if i < j else "none"
            ax.add_patch(Rectangle((x0, y0), CELL, CELL, facecolor=background, edgecolor="0.55",
                                   linewidth=0.6, gid=f"cell/{key}"))
            if i == j:
                counts, edges = np.histogram(unit[:, i], bins=np.linspace(0, 1, HISTOGRAM_BINS + 1))
                ax.stairs(y0 + 0.92 * CELL * counts / counts.max(), x0 + CELL * edges, baseline=y0,
                          fill=True, color=color, alpha=0.75, linewidth=0, gid=f"histogram/{key}")
            elif i > j:
                ax.scatter(x0 + CELL * unit[:SCATTER_POINTS, j], y0 + CELL * unit[:SCATTER_POINTS, i],
                           s=2.0, color=color, alpha=0.5, linewidths=0, gid=f"scatter/{key}")
            else:
                value = round(float(rho[i, j]), 2) + 0.0  # + 0.0: no "-0.00"
                ax.text(x0 + CELL / 2, y0 + CELL / 2, f"{value:.2f}", ha="center", va="center",
                        fontsize=8 if k <= 8 else 7.5, fontweight="bold" if abs(value) >= 0.5 else "normal",
                        gid=f"spearman/{key}")
    _edge_ticks(ax, scales, k)
    # What the cells are is the caption's (captions.py); the title names the line and the count.
    figure.suptitle(f"{display_name(line.name)}: {data.shape[0]} samples with status ok", fontsize=9,
                    y=1 - 0.12 / height, va="top")
    return figure
