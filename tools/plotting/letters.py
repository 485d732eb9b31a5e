"""The compact letters of growthuq's line comparisons (results.h5 /line_letters, campaigns/README.md
"Line comparisons"), drawn above each box as published box plots show them: lines that share a
letter are not distinguishable. The letters come from the data-uncertainty bootstrap, never
from the Monte Carlo samples drawn here; a results.h5 without the table has no letters."""
from matplotlib import transforms

from .errors import PlotInputError
from .h5text import text_list

LETTER_FIELDS = ("quantity", "line", "letters")


def read_letters(h5, path):
    """{(line, quantity): letters} from /line_letters of the open file `h5`; {} without it."""
    if "line_letters" not in h5:
        return {}
    table = h5["line_letters"]
    names = table.dtype.names or ()
    missing = [field for field in LETTER_FIELDS if field not in names]
    if missing:
        raise PlotInputError(f"{path}:/line_letters: no member {missing[0]} (expected a table with members "
                             + ", ".join(LETTER_FIELDS) + ")")
    rows = table[()]
    columns = {field: text_list(rows[field]) for field in LETTER_FIELDS}
    return {(line, quantity): letters
            for quantity, line, letters in zip(columns["quantity"], columns["line"], columns["letters"])}


def draw_letters(ax, position, letters, top, key):
    """`letters` centred at `position`, just above `top` (the box's upper whisker end), in
    points so the gap is the same on a log axis."""
    offset = transforms.offset_copy(ax.transData, fig=ax.figure, x=0, y=3, units="points")
    return ax.text(position, top, letters, transform=offset, ha="center", va="bottom",
                   fontsize=8, fontweight="bold", gid=f"{key}/letters")


def room_for_letters(ax):
    """Headroom above the highest whisker for the letters (a tenth of the axis)."""
    ax.margins(y=0.1)
