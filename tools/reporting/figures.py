"""The figures of tools/plot (tools/plotting/), drawn from results.h5 and embedded in the report
as base64 PNG, each with its caption (plotting/captions.py) under it in the page rather than
inside the figure."""
import base64
import io

PNG_DPI = 110  # a page's width at about 1000 px; the PNGs of tools/plot (150 dpi) stay for print


def png_base64(figure):
    import matplotlib
    from plotting.style import RC
    buffer = io.BytesIO()
    with matplotlib.rc_context(RC):
        figure.savefig(buffer, format="png", dpi=PNG_DPI, metadata={"Software": "growthuq report"})
    return base64.b64encode(buffer.getvalue()).decode("ascii")


def embedded_figures(results_dir, notes):
    """[(stem, caption, base64 PNG)] of tools/plot's default figures; without results.h5 none, and
    a note says why."""
    h5_path = results_dir / "results.h5"
    if not h5_path.is_file():
        notes.append("no figures: the run wrote no results.h5 (formats = csv); rerun with formats = csv, hdf5")
        return []
    from plotting.captions import caption
    from plotting.cli import FIGURES, ON_REQUEST, build_figures
    from plotting.errors import PlotInputError
    from plotting.results import read_results
    from .errors import ReportInputError
    try:
        results = read_results(h5_path)
        made = build_figures(results, results_dir, [f for f in FIGURES if f not in ON_REQUEST], notes)
    except PlotInputError as error:
        raise ReportInputError(str(error)) from None
    return [(stem, caption(stem, results), png_base64(figure)) for stem, figure in made]
