"""Force-indentation curves and the stiffness per tube, for campaigns whose raw lines take k from
force curves ([force_curves], src/forcecurves/README.md): one row per such line. Left, a few
curves (ok ones first, each from another tube where the line has enough): the recorded force
against stage position as faint points, the baseline (Eq. (C1)) dashed across the approach, the
contact point (C3/C4) as a black ring, the fit window (C6) as a bar along the bottom over the
stage positions where the window line meets the window's edges, and the window line (slope k_m,
on top of the baseline) in the curve's colour. Right, every tube's k (Eq. (C10)) with its 95 %
interval, k +- 1.96 u, and the k of its ok curves as dots."""
import math

import numpy as np
import matplotlib

from .errors import FigureSkipped
from .style import axis_label, new_figure, styled

CURVES_PER_LINE = 3
CURVE_COLORS = matplotlib.colormaps["Dark2"].colors
Z_95 = 1.959963984540054  # the standard normal's 97.5 % quantile


def chosen_curves(curves, count=CURVES_PER_LINE):
    """Up to `count` curves with points: ok ones of distinct tubes first (file order), then other
    ok ones, then the rest."""
    with_points = [curve for curve in curves if curve.z_um.size]
    ok = [curve for curve in with_points if curve.status == "ok"]
    seen, distinct = set(), []
    for curve in ok:
        if curve.tube not in seen:
            seen.add(curve.tube)
            distinct.append(curve)
    rest = [curve for curve in ok if curve not in distinct] + [c for c in with_points if c.status != "ok"]
    return (distinct + rest)[:count]


def _draw_curves(ax, line_name, curves):
    shown = chosen_curves(curves)
    for index, curve in enumerate(shown):
        shade = CURVE_COLORS[index % len(CURVE_COLORS)]
        gid = f"{line_name}/{curve.name}"
        ax.plot(curve.z_um, curve.F_uN, ".", markersize=2.6, color=shade, alpha=0.4, markeredgewidth=0,
                gid=f"{gid}/data", label=f"{curve.name} (tube {curve.tube}, {curve.status})")
        ends = np.array([curve.z_um.min(), curve.z_um.max()])
        ax.plot(ends, curve.baseline_uN(ends), "--", color=shade, linewidth=0.9, gid=f"{gid}/baseline")
        if curve.status != "ok":
            continue
        contact = curve.numbers["contact_z_um"]
        ax.plot([contact], [curve.baseline_uN(contact)], "o", markersize=6, markerfacecolor="none",
                markeredgecolor="black", markeredgewidth=1.1, gid=f"{gid}/contact")
        low, high = curve.window_z_um()
        # A bar per curve along the bottom (full-height shading of several curves would blend).
        ax.axvspan(low, high, ymin=0.03 + 0.045 * index, ymax=0.06 + 0.045 * index, color=shade, alpha=0.8,
                   linewidth=0, gid=f"{gid}/window")
        z = np.array([low, high])
        ax.plot(z, curve.baseline_uN(z) + curve.numbers["fit_intercept_uN"] + curve.numbers["k_m_N_per_m"] * z, "-",
                color=shade, linewidth=2.2, gid=f"{gid}/fit")
    ok = sum(curve.status == "ok" for curve in curves)
    ax.set_xlabel(axis_label("z", "um"))
    ax.set_ylabel(axis_label("F", "uN"))
    ax.set_title(f"{line_name}: {len(shown)} of {len(curves)} curves ({ok} ok)")
    ax.legend(loc="upper left", frameon=False, fontsize=6.5, markerscale=3)
    ax.grid(alpha=0.3)


def _draw_tubes(ax, line_name, curves, tubes):
    fitted = [tube for tube in tubes if tube.ok > 0 and math.isfinite(tube.k_N_per_m)]
    position = np.arange(len(fitted))
    k = np.array([tube.k_N_per_m for tube in fitted])
    u = np.array([tube.u_N_per_m for tube in fitted])
    drawn = ax.errorbar(position, k, yerr=Z_95 * u, fmt="o", markersize=3, color="black", elinewidth=1.0, capsize=2,
                        label="tube k, 95 % interval (k ± 1.96 u)")
    drawn.lines[0].set_gid(f"{line_name}/tubes")  # (a gid given to errorbar would go to the caps too)
    drawn.lines[2][0].set_gid(f"{line_name}/tubes/interval")
    by_tube = {tube.name: i for i, tube in enumerate(fitted)}
    dots = [(by_tube[c.tube], c.numbers["k_N_per_m"]) for c in curves if c.status == "ok" and c.tube in by_tube]
    if dots:
        x, y = zip(*dots)
        ax.plot(x, y, ".", markersize=3, color="tab:blue", alpha=0.6, gid=f"{line_name}/curve_k",
                label="k of each ok curve")
    ax.set_xticks(position, [tube.name for tube in fitted], rotation=90, fontsize=5)
    ax.set_xlabel("tube")
    ax.set_ylabel(axis_label("k", "N/m"))
    ax.set_title(f"{line_name}: k of {len(fitted)} of {len(tubes)} tubes")
    ax.legend(loc="upper left", frameon=False, fontsize=6.5)
    ax.grid(alpha=0.3, axis="y")


@styled
def force_curves_figure(results):
    lines = [line for line in results.lines if line.force_curves]
    if not lines:
        raise FigureSkipped("force curves: results.h5 has no /lines/<line>/force_curves group "
                            "(campaigns whose raw lines take k from [force_curves] have one)")
    figure = new_figure(10.0, 3.0 * len(lines) + 0.4)
    axes = figure.subplots(len(lines), 2, squeeze=False, width_ratios=(1.0, 1.3))
    for (left, right), line in zip(axes, lines):
        curves, tubes = line.force_curves
        _draw_curves(left, line.name, curves)
        _draw_tubes(right, line.name, curves, tubes)
    figure.suptitle(f"{results.campaign_name}: force curves (points), baseline (dashed), contact (ring), "
                    "fit window (bar) and window line; stiffness per tube", fontsize=9)
    return figure
