"""What every figure shares: axis labels with units, long names of the quantities, which
quantities get a log axis, one colour per plant line (the same in every figure), and the
typography of a printed figure."""
import functools
import re

import matplotlib
from matplotlib.figure import Figure
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

# Quantities that span a decade or more across lines and tubes (envelope of src/mechanics/README.md:
# eta 10-300 MPa s physiologically, E 5-200 MPa): a log axis keeps every line's box readable.
LOG_QUANTITIES = frozenset({"E", "eta"})

LONG_NAMES = {
    "p": "turgor pressure",
    "E": "wall modulus",
    "eta": "wall viscosity",
    "v": "growth rate (predicted)",
    "v_exp": "growth rate (measured)",
    "k": "apparent stiffness",
    "h": "wall thickness",
    "d": "turgid diameter",
    "d0": "plasmolysed diameter",
    "tau": "slow relaxation time",
    "einf": "equilibrium modulus fraction",
    "lambda": "stretch ratio",
    "alpha": "alpha",
    "phi": "phi",
    "hoop_stress": "hoop stress",
    "wall_stiffness": "wall stiffness",
}

RC = {
    "font.size": 9,
    "axes.titlesize": 10,
    "axes.labelsize": 9,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "legend.fontsize": 8,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "pdf.fonttype": 42,  # TrueType in the PDF: text stays editable in a figure editor
}


def typeset_unit(unit):
    """A unit as a paper prints it: growthuq's files spell micro as "u" (ASCII) and a product with
    a space; 'um/s' -> 'µm/s', 'uN' -> 'µN', 'MPa s' -> 'MPa·s'; '1' (a pure number) -> ''."""
    if unit in ("1", ""):
        return ""
    return re.sub(r"\bu(?=[mNs]\b|m/)", "µ", unit).replace(" ", "·")


def axis_label(quantity, unit):
    """`p (MPa)`, `v (µm/s)`: the quantity's symbol as growthuq names it, with its unit typeset."""
    unit = typeset_unit(unit)
    return f"{quantity} ({unit})" if unit else quantity


def display_name(line):
    """A plant line as a paper names it: the genotypes separated by spaces, as in the published
    tables ("xxt1 xxt2", "wild type"), not the campaign's identifier (xxt1_xxt2)."""
    return line.replace("_", " ")


def long_name(quantity):
    return LONG_NAMES.get(quantity, quantity)


def readable_log_axis(axis):
    """A log axis labelled at 1, 2 and 5 times each power of ten, in plain numbers: box plots of E
    and eta often span less than two decades, where the default labels only the powers of ten
    (sometimes none)."""
    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axis.set_minor_formatter(NullFormatter())


def line_colors(line_names):
    """One colour per line in campaign order, from matplotlib's qualitative tab10 cycle."""
    palette = matplotlib.colormaps["tab10"].colors
    return {name: palette[i % len(palette)] for i, name in enumerate(line_names)}


def styled(build):
    """Runs a figure builder under the shared typography: matplotlib reads rcParams when each
    artist is created, so the whole build (and the saving, see output.py) happens inside it."""
    @functools.wraps(build)
    def build_styled(*args, **kwargs):
        with matplotlib.rc_context(RC):
            return build(*args, **kwargs)
    return build_styled


def new_figure(width_in, height_in, layout="constrained"):
    """A figure without pyplot (no global figure registry, no GUI backend: saving goes through
    the Agg and PDF canvases)."""
    return Figure(figsize=(width_in, height_in), layout=layout)
