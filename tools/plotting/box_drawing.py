"""Drawing one box with whiskers from precomputed quantiles (matplotlib's bxp), so that the box is
exactly q1-q3, the line the median and the whiskers end at the 10th and 90th percentiles, as in
the published figures. (Axes.boxplot with whis=(10, 90) would instead end each whisker at the
most extreme sample inside that range.) Every part carries a gid "<key>/<part>" so that a test can
find it and read its geometry back."""
import numpy as np
from matplotlib import transforms


def draw_box(ax, position, spread, color, key, width=0.6, hatch=None):
    stats = {"med": spread.median, "q1": spread.q1, "q3": spread.q3,
             "whislo": spread.p10, "whishi": spread.p90, "fliers": np.empty(0), "label": ""}
    drawn = ax.bxp([stats], positions=[position], widths=width, patch_artist=True,
                   showfliers=False, manage_ticks=False,
                   boxprops={"facecolor": (*color[:3], 0.45), "edgecolor": color, "hatch": hatch},
                   medianprops={"color": "black", "linewidth": 1.6},
                   whiskerprops={"color": color, "linewidth": 1.2},
                   capprops={"color": color, "linewidth": 1.2})
    drawn["boxes"][0].set_gid(f"{key}/box")
    drawn["medians"][0].set_gid(f"{key}/median")
    for part, (low, high) in (("whisker", drawn["whiskers"]), ("cap", drawn["caps"])):
        low.set_gid(f"{key}/{part}_low")
        high.set_gid(f"{key}/{part}_high")
    return drawn


def label_below(ax, position, text, key):
    """`text` centred under the box at `position`, just below the axis (the x tick labels are
    pushed down to make room, see room_for_labels)."""
    along_x = transforms.blended_transform_factory(ax.transData, ax.transAxes)
    return ax.text(position, -0.02, text, transform=along_x, ha="center", va="top",
                   fontsize=6.5, color="0.25", gid=f"{key}/n")


def room_for_labels(ax, text_lines):
    """Moves the x tick labels below `text_lines` lines of label_below text."""
    ax.tick_params(axis="x", pad=4 + 8.5 * text_lines)
