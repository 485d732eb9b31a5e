"""Force-relaxation curves with their generalized Maxwell fits, for campaigns built from raw
curves: one panel per line with relaxation data, a few curves each (fitted curves first: status ok,
or extrapolated, a tau_slow beyond the hold),
measured force as points and the fitted force as a line, on a log time axis (t = 0 at the force
maximum; points at t <= 0, the ramp, cannot be shown on it). Within a panel every curve has its
own hue and marker; the legend gives each fit's fast and slow relaxation times. Under each panel
the residuals F - F_fit of the fitted curves on the same time axis: a fit that misses a phase of
the decay shows there as a run of one sign, which the force scale hides."""
import math

import numpy as np
import matplotlib

from .errors import FigureSkipped
from .style import axis_label, display_name, new_figure, styled

CURVES_PER_LINE = 4
# Statuses of curves that were fitted; an extrapolated fit has tau_slow beyond the hold.
FITTED = ("ok", "extrapolated")


def chosen_curves(curves, count=CURVES_PER_LINE):
    """Up to `count` curves with points, the fitted ones first, each group in file order."""
    with_points = [curve for curve in curves if curve.t_s.size]
    ordered = ([curve for curve in with_points if curve.status in FITTED]
               + [curve for curve in with_points if curve.status not in FITTED])
    return ordered[:count]


# Within a panel (one line) each curve has its own hue and marker: shades of one line colour
# could not be told apart where the line's colour is light.
CURVE_COLORS = matplotlib.colormaps["Dark2"].colors
CURVE_MARKERS = ("o", "s", "^", "D")


# The legend's title says which of each entry's two times is which (the entries stay short
# enough for a third of the page's width).
LEGEND_TITLE = "tau: fast, slow"
# Page width (a journal's text width, 18 cm); the smallest print size of the figures' text.
PAGE_WIDTH_IN = 7.0
SMALL_PT = 6.5


def _legend_text(curve):
    if curve.status not in FITTED:
        return f"{curve.name} ({curve.status})"
    if "tau_fast_s" in curve.fit and "tau_slow_s" in curve.fit:
        extrapolated = " (extrap.)" if curve.status == "extrapolated" else ""
        return f"{curve.name}: {curve.fit['tau_fast_s']:.2g} s, {curve.fit['tau_slow_s']:.2g} s{extrapolated}"
    return curve.name


def _draw_line(ax, residual_ax, line):
    shown = chosen_curves(line.relaxation)
    for index, curve in enumerate(shown):
        shade = CURVE_COLORS[index % len(CURVE_COLORS)]
        marker = CURVE_MARKERS[index % len(CURVE_MARKERS)]
        after_maximum = curve.t_s > 0
        ax.plot(curve.t_s[after_maximum], curve.F_uN[after_maximum], marker,
                markersize=2.4, color=shade, alpha=0.55, markeredgewidth=0, gid=f"{line.name}/{curve.name}/data")
        fitted = after_maximum & np.isfinite(curve.F_fit_uN)
        ax.plot(curve.t_s[fitted], curve.F_fit_uN[fitted], "-", color=shade, linewidth=1.4,
                gid=f"{line.name}/{curve.name}/fit", label=_legend_text(curve))
        residual_ax.plot(curve.t_s[fitted], curve.F_uN[fitted] - curve.F_fit_uN[fitted], marker, markersize=1.6,
                         color=shade, alpha=0.5, markeredgewidth=0, gid=f"{line.name}/{curve.name}/residual")
    ok = sum(curve.status in FITTED for curve in line.relaxation)
    ax.set_xscale("log")
    ax.tick_params(axis="x", labelbottom=False)
    ax.set_ylabel(axis_label("F", "uN"), fontsize=7)
    residual_ax.axhline(0, color="0.3", linewidth=0.8)
    residual_ax.set_xlabel("t (s)", fontsize=7)
    residual_ax.set_ylabel(axis_label("F - F_fit", "uN"), fontsize=7)
    residual_ax.grid(alpha=0.3, which="major")
    for axis in (ax, residual_ax):
        axis.tick_params(labelsize=SMALL_PT)
    ax.set_title(f"{display_name(line.name)}: {len(shown)} of {len(line.relaxation)} curves,\n{ok} fitted",
                 fontsize=8)
    # Lower left: the decay starts at the top left and ends at the right, so that corner is empty
    # but for the first point after the maximum (t of one sample), which the offset leaves visible.
    ax.legend(loc="lower left", bbox_to_anchor=(0.1, 0.0), frameon=False, fontsize=SMALL_PT, title=LEGEND_TITLE,
              title_fontproperties={"size": SMALL_PT}, handlelength=1.2, borderaxespad=0.2, labelspacing=0.25)
    ax.grid(alpha=0.3, which="major")


@styled
def relaxation_figure(results):
    lines = [line for line in results.lines if line.relaxation]
    if not lines:
        raise FigureSkipped("relaxation curves: results.h5 has no /lines/<line>/relaxation group "
                            "(campaigns built from raw relaxation curves have one)")
    columns = min(3, len(lines))
    rows = math.ceil(len(lines) / columns)
    figure = new_figure(PAGE_WIDTH_IN, 3.1 * rows + 0.35)
    # Per line a force panel over its residual panel, sharing the time axis.
    grid = figure.add_gridspec(2 * rows, columns, height_ratios=(3, 1.2) * rows)
    for index, line in enumerate(lines):
        row, column = divmod(index, columns)
        ax = figure.add_subplot(grid[2 * row, column])
        _draw_line(ax, figure.add_subplot(grid[2 * row + 1, column], sharex=ax), line)
    figure.suptitle(f"{results.campaign_name}: force relaxation, measured (points) and generalized Maxwell "
                    "fit (line); t = 0 at the force maximum", fontsize=8)
    return figure
