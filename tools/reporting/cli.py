"""tools/report RESULTS_DIR: one self-contained HTML report of a growthuq run, written to
RESULTS_DIR/report.html (or --out) through a temporary name renamed when complete; an existing
report is replaced only with --force. Bad input stops with one line naming the file and what was
expected, exit status 2."""
import argparse
import sys
from pathlib import Path

from .errors import ReportInputError
from .inputs import read_run


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="tools/report",
        description="One self-contained HTML report of a growthuq run: data intervals and summary, letters, "
                    "sensitivity, fit reports, figures, a methods paragraph from the run's provenance, "
                    "references and warnings.")
    parser.add_argument("results_dir", metavar="RESULTS_DIR", type=Path,
                        help="output directory of `growthuq run` (holds summary.csv)")
    parser.add_argument("--out", type=Path, help="the HTML file to write (default RESULTS_DIR/report.html)")
    parser.add_argument("--force", action="store_true", help="replace an existing report")
    parser.add_argument("--program", default="tools/report", help=argparse.SUPPRESS)  # growthuq report's name
    return parser.parse_args(argv)


def run(arguments, out=sys.stdout):
    run_results = read_run(arguments.results_dir)
    target = arguments.out or arguments.results_dir / "report.html"
    if target.exists() and not arguments.force:
        raise ReportInputError(f"{target}: already exists; give --force to replace it")
    from .figures import embedded_figures  # matplotlib: after the checks
    from .page import report_html
    notes = []
    figures = embedded_figures(arguments.results_dir, notes)
    from plotting.errors import PlotInputError
    from plotting.output import save_text
    try:
        save_text(report_html(run_results, figures, notes), target)
    except PlotInputError as error:
        raise ReportInputError(str(error)) from None
    print(f"wrote {target}", file=out)
    return 0


def main(argv=None):
    arguments = parse_arguments(argv)
    try:
        return run(arguments)
    except ReportInputError as error:
        print(f"{arguments.program}: error: {error}", file=sys.stderr)
        return 2
