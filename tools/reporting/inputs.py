"""What a report reads from a results directory: summary.csv (required: `growthuq run` moves it
in last, so it marks a complete set), the optional tables (data_uncertainty.csv, letters.csv,
comparisons.csv, sensitivity.csv), provenance.json and, in results.h5, the raw-data lines' fit
tables. Every table keeps its file's columns; a missing column names the file and the column."""
import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

from .errors import ReportInputError

SUMMARY_COLUMNS = ("line", "quantity", "unit", "n", "n_flagged", "median", "q1", "q3", "iqr", "p10", "p90",
                   "median_ci_low", "median_ci_high", "data_ci_low", "data_ci_high")
OPTIONAL_TABLES = {
    "letters": ("letters.csv", ("quantity", "line", "letters")),
    "comparisons": ("comparisons.csv", ("quantity", "unit", "line_a", "line_b", "ratio", "adjusted_ci_low",
                                        "adjusted_ci_high", "adjusted_level", "differs")),
    "sensitivity": ("sensitivity.csv", ("line", "output", "input", "method", "index", "ci_low", "ci_high")),
}


@dataclass
class RunResults:
    directory: Path
    summary: list                      # rows of summary.csv as dicts (text values)
    letters: list = None               # rows of the optional tables; None when the file is absent
    comparisons: list = None
    sensitivity: list = None
    provenance: dict = None            # provenance.json; None for a run of an older growthuq
    fits: dict = field(default_factory=dict)  # line: rows of results.h5 lines/<line>/fits
    written: str = ""                  # when summary.csv was written (UTC), for the methods


def number(text):
    """A CSV cell as a float; an empty cell (undefined) is NaN."""
    return float(text) if text not in ("", None) else math.nan


def read_table(path, required):
    try:
        with open(path, newline="", encoding="utf-8") as file:
            reader = csv.DictReader(file)
            missing = [name for name in required if name not in (reader.fieldnames or [])]
            if missing:
                raise ReportInputError(f"{path}: no column '{missing[0]}' (expected the columns growthuq run "
                                       f"writes: {', '.join(required)})")
            return list(reader)
    except OSError as error:
        raise ReportInputError(f"{path}: cannot read ({error.strerror})") from None
    except UnicodeDecodeError:
        raise ReportInputError(f"{path}: not UTF-8 text (expected a CSV written by growthuq run)") from None


def read_provenance(path):
    if not path.is_file():
        return None
    try:
        provenance = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ReportInputError(f"{path}: not readable as JSON ({error}); expected the provenance.json "
                               "growthuq run writes") from None
    if not isinstance(provenance, dict) or "growthuq_version" not in provenance:
        raise ReportInputError(f"{path}: no key 'growthuq_version' (expected the provenance.json growthuq run "
                               "writes)")
    return provenance


def read_fits(h5_path):
    """{line: [row dict]} of the raw-data lines' fit tables; {} without results.h5."""
    if not h5_path.is_file():
        return {}
    import h5py  # only when there is an HDF5 file to read
    fits = {}
    try:
        with h5py.File(h5_path, "r") as file:
            for name, group in file.get("lines", {}).items():
                if "fits" not in group:
                    continue
                table = group["fits"][:]
                rows = []
                for record in table:
                    rows.append({column: (value.decode() if isinstance(value, bytes) else value)
                                 for column, value in zip(table.dtype.names, record)})
                fits[name] = rows
    except OSError as error:
        raise ReportInputError(f"{h5_path}: not readable as HDF5 ({error})") from None
    return fits


def check_results_directory(directory):
    if not directory.exists():
        raise ReportInputError(f"{directory}: no such directory (expected the output directory of growthuq run)")
    if not directory.is_dir():
        raise ReportInputError(f"{directory}: is not a directory (expected the output directory of growthuq run)")
    if not (directory / "summary.csv").is_file():
        raise ReportInputError(f"{directory}: is not a results directory: it has no summary.csv (growthuq run "
                               "writes one when its results are complete)")


def read_run(directory):
    directory = Path(directory)
    check_results_directory(directory)
    summary_path = directory / "summary.csv"
    results = RunResults(directory=directory, summary=read_table(summary_path, SUMMARY_COLUMNS))
    for key, (name, required) in OPTIONAL_TABLES.items():
        if (directory / name).is_file():
            setattr(results, key, read_table(directory / name, required))
    results.provenance = read_provenance(directory / "provenance.json")
    results.fits = read_fits(directory / "results.h5")
    import datetime
    written = datetime.datetime.fromtimestamp(summary_path.stat().st_mtime, datetime.timezone.utc)
    results.written = written.strftime("%Y-%m-%d %H:%M UTC")
    return results
