"""The report's tables as HTML, each cell the file's value to four significant digits (a reader
wanting more digits has the CSV). Every table has an id (summary, letters, comparisons,
sensitivity, fits-<line>) and a header row, so a test or a script can find it."""
import math
from html import escape

from .inputs import number
from plotting.style import typeset_unit

MISSING = "—"


def significant(value):
    """Four significant digits; an undefined value (NaN, an empty CSV cell) as a dash."""
    value = number(value) if isinstance(value, str) else value
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return MISSING
    return f"{value:.4g}"


def is_fixed(low, high):
    """Zero width but for rounding, by the rule of the CLI's tables (data_interval_is_fixed,
    src/campaign/campaign_report.cpp): a median the bootstrap does not move, whose replicates may
    still differ in the last bits (0.027999999999999997 and 0.028000000000000008)."""
    return high - low <= 1e-12 * max(abs(low), abs(high))


def interval(low, high):
    """'low – high'; 'fixed' for a zero-width interval (a law the bootstrap held fixed: it varies
    nothing, so an interval would claim a precision the data do not give); a dash when absent."""
    low, high = number(low), number(high)
    if math.isnan(low) or math.isnan(high):
        return MISSING
    if is_fixed(low, high):
        return "fixed"
    return f"{significant(low)} – {significant(high)}"


def html_table(table_id, header, rows, caption=""):
    head = "".join(f"<th>{escape(cell)}</th>" for cell in header)
    body = "\n".join("<tr>" + "".join(f"<td>{escape(str(cell))}</td>" for cell in row) + "</tr>" for row in rows)
    caption_html = f"<caption>{escape(caption)}</caption>" if caption else ""
    return (f'<table id="{escape(table_id)}">{caption_html}<thead><tr>{head}</tr></thead>\n'
            f"<tbody>\n{body}\n</tbody></table>")


SUMMARY_HEADER = ("line", "quantity", "unit", "data 95 % interval of the median", "median",
                  "Monte Carlo 95 % CI of the median", "IQR (q1 – q3)", "10 – 90 %", "n", "flagged")


def summary_table(summary):
    rows = [(row["line"], row["quantity"], typeset_unit(row["unit"]), interval(row["data_ci_low"], row["data_ci_high"]),
             significant(row["median"]), interval(row["median_ci_low"], row["median_ci_high"]),
             interval(row["q1"], row["q3"]), interval(row["p10"], row["p90"]), row["n"], row["n_flagged"])
            for row in summary]
    return html_table("summary", SUMMARY_HEADER, rows,
                      "Per line and quantity: the data interval (what refitting the line's laws to tubes redrawn "
                      "from them moves the median by; a dash for lines given by a line file, 'fixed' for a law "
                      "held fixed), then the Monte Carlo summary of the samples.")


def letters_table(letters):
    lines = list(dict.fromkeys(row["line"] for row in letters))
    quantities = list(dict.fromkeys(row["quantity"] for row in letters))
    found = {(row["quantity"], row["line"]): row["letters"] for row in letters}
    rows = [[quantity] + [found.get((quantity, line), MISSING) for line in lines] for quantity in quantities]
    return html_table("letters", ["quantity"] + lines, rows,
                      "Lines sharing a letter do not differ (comparisons.csv, adjusted data intervals of the "
                      "ratio of medians).")


def comparisons_table(comparisons):
    rows = [(row["quantity"], row["line_a"], row["line_b"], significant(row["ratio"]),
             interval(row["adjusted_ci_low"], row["adjusted_ci_high"]), significant(row["adjusted_level"]),
             row["differs"]) for row in comparisons]
    return html_table("comparisons", ("quantity", "line a", "line b", "ratio of medians (a/b)",
                                      "adjusted interval", "level", "differs"), rows)


def sensitivity_table(sensitivity):
    rows = [(row["line"], row["output"], row["input"], row["method"], significant(row["index"]),
             interval(row["ci_low"], row["ci_high"])) for row in sensitivity]
    return html_table("sensitivity", ("line", "output", "input", "method", "index", "95 % CI"), rows,
                      "Which input drives each output (src/sensitivity/README.md).")


def fits_table(line, fits):
    def cell(row, key):
        value = row.get(key, "")
        return significant(float(value)) if isinstance(value, (int, float)) and not isinstance(value, bool) else value
    rows = [(row.get("variable", ""), typeset_unit(row.get("unit", "")), row.get("family", ""),
             row.get("parameters", ""), row.get("n", ""), cell(row, "ks"), cell(row, "ad"), row.get("source", ""))
            for row in fits]
    return html_table(f"fits-{line}", ("variable", "unit", "family", "parameters", "tubes", "KS D", "AD A²",
                                       "source"), rows, f"Laws of {line} fitted to its raw data (least AIC).")
