"""Reading tradeoff.csv, the table `growthuq tradeoff` writes: one row per sample count x line x
quantity, with the error of the median and IQR against the largest run of the same fidelity
(the reference), the 95 % confidence interval of the median, and the errors against the
shell_fe run with the most samples (fe_ columns). Empty cells (e.g. no interval with 5 or fewer
samples) are NaN."""
import csv
import math

from .errors import PlotInputError

TEXT_COLUMNS = ("fidelity", "line", "quantity", "unit")
NUMBER_COLUMNS = ("samples", "seconds", "n", "median", "iqr", "median_ci_low", "median_ci_high",
                  "reference_median", "reference_iqr", "median_error_pct", "iqr_error_pct",
                  "median_error_over_ci_half_width")
# Against the finite-element reference (the shell_fe run with the most samples); empty without
# one, and absent from tables written before the fidelity axis: NaN then.
OPTIONAL_NUMBER_COLUMNS = ("fe_reference_median", "fe_reference_iqr", "fe_median_error_pct",
                           "fe_iqr_error_pct")


def _number(text, path, row, column):
    if text.strip() == "":
        return math.nan
    try:
        return float(text)
    except ValueError:
        raise PlotInputError(f"{path}:{row}: column {column}: '{text}' is not a number") from None


def read_tradeoff(path):
    """The rows of `path` as dicts (numbers as float, `samples` as int), in file order. Lines
    starting with # are comments."""
    try:
        with open(path, newline="", encoding="utf-8") as handle:
            numbered = [(number, text) for number, text in enumerate(handle, start=1)
                        if text.strip() and not text.startswith("#")]
    except OSError as error:
        raise PlotInputError(f"{path}: cannot read ({error.strerror})") from None
    if not numbered:
        raise PlotInputError(f"{path}: empty (expected a header row and one row per sample count, "
                             "line and quantity)")
    records = list(csv.reader(text for _, text in numbered))
    header = [name.strip() for name in records[0]]
    missing = [column for column in TEXT_COLUMNS + NUMBER_COLUMNS if column not in header]
    if missing:
        raise PlotInputError(f"{path}:{numbered[0][0]}: header lacks {', '.join(missing)} "
                             "(expected the columns growthuq tradeoff writes)")
    rows = []
    for (number, _), record in zip(numbered[1:], records[1:]):
        if len(record) != len(header):
            raise PlotInputError(f"{path}:{number}: {len(record)} cells; expected {len(header)} as "
                                 "in the header")
        cells = dict(zip(header, record))
        row = {column: cells[column] for column in TEXT_COLUMNS}
        for column in NUMBER_COLUMNS:
            row[column] = _number(cells[column], path, number, column)
        for column in OPTIONAL_NUMBER_COLUMNS:
            row[column] = _number(cells.get(column, ""), path, number, column)
        if not (row["samples"] >= 1 and float(row["samples"]).is_integer()):
            raise PlotInputError(f"{path}:{number}: column samples: '{cells['samples']}'; expected "
                                 "a whole number >= 1")
        row["samples"] = int(row["samples"])
        rows.append(row)
    if not rows:
        raise PlotInputError(f"{path}: no rows after the header (expected one per sample count, "
                             "line and quantity)")
    return rows
