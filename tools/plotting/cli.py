"""tools/plot RESULTS_DIR: every figure of a campaign in one command. Reads RESULTS_DIR/results.h5
(and RESULTS_DIR/tradeoff.csv when `growthuq tradeoff` wrote one), writes one file per figure and
format into RESULTS_DIR/plots (or --out), prints what it wrote and why a figure was skipped. Bad
input stops with one line naming the file and what was expected, exit status 2."""
import argparse
import math
import re
import sys
from pathlib import Path

from .errors import FigureSkipped, PlotInputError
from .results import read_results

FORMATS = ("png", "pdf")
FIGURES = ("boxes", "growth_rate", "correlogram", "sensitivity", "pca", "relaxation", "force_curves", "tradeoff")
# Not drawn unless --figures names them: the PCA's scree plot says nothing of which input drives
# an output, which the sensitivity figure shows; it stays available by name.
ON_REQUEST = ("pca",)


def _file_stem(text):
    return re.sub(r"[^\w.-]", "_", text)


def _builders(results, results_dir, notes, target_pct):
    """{family: a function returning [(file stem, Figure)]}. The figure modules (matplotlib and
    scipy, about 1 s to import) are imported here, once the results have been read, so that a
    wrong path or file is reported at once."""
    from .boxes import box_figure
    from .correlogram import correlogram_columns, correlogram_figure
    from .force_curves import force_curves_figure
    from .growth_rate import growth_rate_figure
    from .pca import pca_figure
    from .relaxation import relaxation_figure
    from .sensitivity import sensitivity_figure
    from .tradeoff import tradeoff_figure
    from .tradeoff_data import read_tradeoff

    def correlograms():
        made = []
        for line in results.lines:
            chosen, data = correlogram_columns(line)
            if len(chosen) < 2 or data.shape[0] < 3:
                notes.append(f"skipped correlogram of {line.name}: {data.shape[0]} samples with "
                             f"status ok and {len(chosen)} varying columns (need 3 and 2)")
                continue
            made.append((f"correlogram_{_file_stem(line.name)}", correlogram_figure(results, line)))
        return made

    def trade():
        path = results_dir / "tradeoff.csv"
        if not path.is_file():
            raise FigureSkipped(f"trade plot: no {path} (written by `growthuq tradeoff`)")
        return [("tradeoff", tradeoff_figure(read_tradeoff(path), results.campaign_name,
                                             results.line_names(), target_pct))]

    return {
        "boxes": lambda: [("boxes", box_figure(results))],
        "growth_rate": lambda: [("growth_rate", growth_rate_figure(results))],
        "correlogram": correlograms,
        "sensitivity": lambda: [("sensitivity", sensitivity_figure(results))],
        "pca": lambda: [("pca", pca_figure(results))],
        "relaxation": lambda: [("relaxation", relaxation_figure(results))],
        "force_curves": lambda: [("force_curves", force_curves_figure(results))],
        "tradeoff": trade,
    }


def build_figures(results, results_dir, wanted, notes, target_pct=1.0):
    """[(file stem, Figure)] of the `wanted` figure families, in FIGURES order; a family whose
    data is missing adds a note to `notes` instead. `target_pct`: the precision the trade plot draws."""
    builders = _builders(results, results_dir, notes, target_pct)
    made = []
    for family in FIGURES:
        if family not in wanted:
            continue
        try:
            made += builders[family]()
        except FigureSkipped as skipped:
            notes.append(f"skipped {skipped}")
    return made


def flag_notes(results):
    """What the figures leave out of flagged samples (the same rule as summary.csv): a box only
    the samples lacking its quantity, the correlogram and the PCA every flagged sample."""
    flagged = {line.name: int((line.status != "ok").sum()) for line in results.lines}
    if not any(flagged.values()):
        return []
    counts = ", ".join(f"{name} {count}" for name, count in flagged.items() if count)
    return [f"flagged samples (status not ok): {counts} (of {results.samples_per_line} per line); a box "
            f"leaves out only those lacking its quantity (n_flagged of summary.csv: p and E computed "
            f"before a later flag, and v = 0 of no_growth, count), the correlogram and PCA all of them"]


def _list_option(text, allowed):
    chosen = [item.strip() for item in text.split(",") if item.strip()]
    unknown = [item for item in chosen if item not in allowed]
    if unknown or not chosen:
        raise argparse.ArgumentTypeError(f"'{text}': expected a comma-separated list of "
                                         f"{', '.join(allowed)}")
    return chosen


def _percent(text):
    try:
        value = float(text.rstrip("%"))
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"'{text}': expected a percentage > 0, e.g. 1 or 0.5%")
    return value


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="tools/plot",
        description="Figures of a growthuq campaign: box plots per line, predicted vs measured "
                    "growth rate, correlograms, first-order sensitivity, PCA, relaxation fits, force "
                    "curves and stiffness per tube, the speed/accuracy trade.")
    parser.add_argument("results_dir", metavar="RESULTS_DIR", type=Path,
                        help="output directory of `growthuq run` (holds results.h5)")
    parser.add_argument("--out", type=Path, help="where the plots go (default RESULTS_DIR/plots)")
    parser.add_argument("--formats", default="png,pdf", help="png, pdf or both (default png,pdf)",
                        type=lambda text: _list_option(text, FORMATS))
    default_figures = ",".join(f for f in FIGURES if f not in ON_REQUEST)
    parser.add_argument("--figures", default=default_figures,
                        help=f"which figures (default {default_figures}; also {','.join(ON_REQUEST)})",
                        type=lambda text: _list_option(text, FIGURES))
    parser.add_argument("--target", type=_percent, default=1.0, metavar="PCT",
                        help="the precision the trade plot draws, in %% of the median (default 1, as "
                             "growthuq tradeoff's --target)")
    parser.add_argument("--force", action="store_true", help="replace existing plots")
    return parser.parse_args(argv)


def run(arguments, out=sys.stdout):
    results_dir = arguments.results_dir
    if not results_dir.is_dir():
        raise PlotInputError(f"{results_dir}: no such directory (expected the output directory of "
                             "`growthuq run`)")
    results = read_results(results_dir / "results.h5")
    from .output import refuse_overwrite, save_figure, save_text, target_paths  # matplotlib: after the checks
    out_dir = arguments.out or results_dir / "plots"
    notes = []
    made = build_figures(results, results_dir, arguments.figures, notes, arguments.target)
    paths = target_paths(out_dir, [stem for stem, _ in made], arguments.formats)
    captions_path = out_dir / "captions.md"
    if not arguments.force:
        refuse_overwrite(paths + ([captions_path] if made else []))
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise PlotInputError(f"{out_dir}: cannot create the directory ({error.strerror})") from None
    for stem, figure in made:
        for extension in arguments.formats:
            path = out_dir / f"{stem}.{extension}"
            save_figure(figure, path)
            print(f"wrote {path}", file=out)
    if made:
        from .captions import captions_markdown
        save_text(captions_markdown([stem for stem, _ in made], results), captions_path)
        print(f"wrote {captions_path}", file=out)
    for note in flag_notes(results) + notes:
        print(f"note: {note}", file=out)
    return 0


def main(argv=None):
    arguments = parse_arguments(argv)
    try:
        return run(arguments)
    except PlotInputError as error:
        print(f"tools/plot: error: {error}", file=sys.stderr)
        return 2
