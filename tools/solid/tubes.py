"""The table of tubes the solid is compared on (tubes.csv), read and checked."""
import csv
import sys

COLUMNS = ("name", "p_MPa", "E_MPa", "h0_nm", "d0_um", "rho_um", "finest_um", "k_tolerance_percent")


def load_tubes(path):
    """The table's rows, each number checked: exits with the file, line, column and value of the
    first that is not a positive number (k_tolerance_percent may be "-": the row is run and
    printed, never failed)."""
    try:
        rows = list(csv.DictReader(open(path), skipinitialspace=True))
    except OSError as error:
        sys.exit(f"tools/solid: cannot read the tubes' table {path}: {error.strerror}")
    for line, row in enumerate(rows, start=2):
        for key in COLUMNS:
            value = row.get(key)
            if key == "k_tolerance_percent" and value == "-":
                continue  # a row recorded, not checked (README.md, "Results")
            if key != "name":
                try:
                    ok = float(value) > 0
                except (TypeError, ValueError):
                    ok = False
                if not ok:
                    sys.exit(f"tools/solid: {path}, line {line}, column {key}: {value!r}: expected a positive number")
    return rows
