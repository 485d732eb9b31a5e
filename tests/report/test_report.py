#!/usr/bin/python3
"""growthuq report end to end (issue 30): a raw-data campaign with line comparisons run with the
CLI, its report made, and what the report states read back against independent sources: the
tables against summary.csv and letters.csv (read with the csv module), the provenance against the
campaign file (configparser, hashlib), results.h5's /provenance against provenance.json, the
embedded figures as PNG. Also the refusals: an existing report without --force, a directory that
is not a results directory, a missing one.
Usage: test_report.py --cli GROWTHUQ --source-dir SOURCE"""
import argparse
import base64
import configparser
import csv
import hashlib
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py

sys.path.insert(0, str(Path(__file__).resolve().parent))
from report_html import parse_report  # noqa: E402

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print(f"FAIL: {message}", file=sys.stderr)


def run(*words):
    return subprocess.run([str(word) for word in words], capture_output=True, text=True)


def close(a, b, relative=5e-4):
    """Four significant digits (the report's) agree with the CSV's value to half a unit in the
    fourth digit."""
    return math.isclose(a, b, rel_tol=relative, abs_tol=1e-300)


def interval_cell(text):
    low, high = text.split(" – ")
    return float(low), float(high)


def check_refusals(cli, work):
    missing = run(cli, "report", work / "nowhere")
    check(missing.returncode == 2 and "nowhere: no such directory" in missing.stderr,
          f"a missing directory: exit {missing.returncode}, {missing.stderr!r}")
    (work / "empty").mkdir()
    empty = run(cli, "report", work / "empty")
    check(empty.returncode == 2 and "empty: is not a results directory: it has no summary.csv" in empty.stderr,
          f"a directory without summary.csv: exit {empty.returncode}, {empty.stderr!r}")
    (work / "file").write_text("x")
    not_directory = run(cli, "report", work / "file")
    check(not_directory.returncode == 2 and "file: is not a directory" in not_directory.stderr,
          f"a file: exit {not_directory.returncode}, {not_directory.stderr!r}")
    (work / "broken").mkdir()
    (work / "broken" / "summary.csv").write_text("line,quantity\nwild_type,p\n")
    broken = run(cli, "report", work / "broken")
    check(broken.returncode == 2 and broken.stderr.startswith("growthuq report: error: ") and
          "summary.csv: no column 'unit'" in broken.stderr and not (work / "broken" / "report.html").exists(),
          f"a summary.csv without its columns: exit {broken.returncode}, {broken.stderr!r}")
    helped = run(cli, "report", "--help")
    check(helped.returncode == 0 and "--force" in helped.stdout and "provenance.json" in helped.stdout,
          f"--help: exit {helped.returncode}, {helped.stdout!r}")


def check_provenance(run_dir, campaign_path):
    provenance = json.loads((run_dir / "provenance.json").read_text())
    ini = configparser.ConfigParser()
    ini.read(campaign_path)
    check(provenance["campaign_sha256"] == hashlib.sha256(campaign_path.read_bytes()).hexdigest(),
          "provenance.json: campaign_sha256 is not the campaign file's SHA-256")
    check(provenance["seed"] == int(ini["campaign"]["seed"]), f"seed {provenance['seed']}")
    check(provenance["samples_per_line"] == int(ini["campaign"]["samples"]), "samples_per_line")
    check(provenance["probe_radius_um"] == float(ini["instrument"]["probe_radius_um"]), "probe_radius_um")
    check(provenance["data_interval_replicates"] == int(ini["data_uncertainty"]["replicates"]), "replicates")
    check(provenance["data_interval_samples"] == int(ini["data_uncertainty"]["samples"]), "data samples")
    lines = [section.split(" ", 1)[1] for section in ini.sections() if section.startswith("line ")]
    check([line["name"] for line in provenance["lines"]] == lines, f"lines {provenance['lines']}")
    check(all(line["fidelity"] == "closed_form" for line in provenance["lines"]), "fidelity per line")
    check(not any(key in provenance for key in ("date", "time", "processes")), "a per-run value in provenance.json")
    with h5py.File(run_dir / "results.h5", "r") as file:
        stored = file["provenance"].attrs
        for key in ("growthuq_version", "campaign_sha256", "seed", "samples_per_line", "probe_radius_um",
                    "data_interval_replicates", "reference_line"):
            check(stored[key] == provenance[key], f"results.h5 /provenance {key}: {stored[key]} vs {provenance[key]}")
        for line in provenance["lines"]:
            check(file[f"provenance/lines/{line['name']}"].attrs["fidelity"] == line["fidelity"],
                  f"results.h5 fidelity of {line['name']}")
        check("Arnoldi" in file["provenance/models/thin_shell_turgor"].attrs["reference"], "Arnoldi reference in h5")
    return provenance


def check_tables(report, run_dir):
    summary = list(csv.DictReader(open(run_dir / "summary.csv", newline="")))
    table = report.tables.get("summary")
    check(table is not None, "no summary table")
    if table is None:
        return
    header, rows = table[0], table[1:]
    check(header[3].startswith("data 95 % interval"), f"the data interval is not the first statistic: {header}")
    check(len(rows) == len(summary), f"summary table has {len(rows)} rows, summary.csv {len(summary)}")
    for row, expected in zip(rows, summary):
        check(row[:2] == [expected["line"], expected["quantity"]], f"row {row[:2]}")
        check(close(float(row[4]), float(expected["median"])), f"{row[:2]} median {row[4]} vs {expected['median']}")
        if expected["data_ci_low"]:
            low, high = interval_cell(row[3])
            check(close(low, float(expected["data_ci_low"])) and close(high, float(expected["data_ci_high"])),
                  f"{row[:2]} data interval {row[3]} vs {expected['data_ci_low']}, {expected['data_ci_high']}")
        check(row[8] == expected["n"] and row[9] == expected["n_flagged"], f"{row[:2]} counts {row[8:]}")
        check("um" not in row[2], f"unit not typeset: {row[2]}")
    units = {row[2] for row in rows}
    check("µm/s" in units and "MPa·s" in units, f"units {units}")
    letters = list(csv.DictReader(open(run_dir / "letters.csv", newline="")))
    table = report.tables.get("letters")
    check(table is not None, "no letters table")
    if table is not None:
        columns = table[0]
        found = {(row[0], line): cell for row in table[1:] for line, cell in zip(columns[1:], row[1:])}
        for expected in letters:
            check(found.get((expected["quantity"], expected["line"])) == expected["letters"],
                  f"letters of {expected['line']} {expected['quantity']}")
    with h5py.File(run_dir / "results.h5", "r") as file:
        for line in ("wild_type", "xeg113"):
            fits = file[f"lines/{line}/fits"][:]
            table = report.tables.get(f"fits-{line}")
            check(table is not None and len(table) == len(fits) + 1, f"fit table of {line}")
            if table is not None:
                check([row[4] for row in table[1:]] == [str(n) for n in fits["n"]], f"tubes of {line}")
    check("sensitivity" in report.tables, "no sensitivity table")


# A raw-data line beside a published reference line: in every bootstrap replicate the reference's
# v is calibrated to its published, fixed v_exp median, so its data interval has zero width but for
# rounding (the CSV holds ends such as 0.027999999999999997 and 0.028000000000000008).
FIXED_CAMPAIGN = """[campaign]
name = fixed_law
output_dir = out
seed = 7
samples = 40
outputs = p, E, eta, v, v_exp
formats = csv, hdf5

[instrument]
probe_radius_um = 0.5

[growth]
reference_line = wild_type

[line xxt1_xxt2]
raw = {source}/distributions/example_raw/xxt1_xxt2/raw.ini

[line wild_type]
distributions = {source}/distributions/wild_type.ini
"""


def cli_says_fixed(low, high):
    """The CLI's rule (src/campaign/campaign_report.cpp, data_interval_is_fixed), restated here."""
    return high - low <= 1e-12 * max(abs(low), abs(high))


def check_fixed(cli, source, work):
    """The report prints "fixed" exactly where the CLI's tables do, a rounded near-zero width
    included, and the interval elsewhere."""
    sys.path.insert(0, str(source / "tools"))
    from reporting.tables import interval
    check(interval("0.027999999999999997", "0.028000000000000008") == "fixed",
          f"a width of rounding: {interval('0.027999999999999997', '0.028000000000000008')!r}")
    check(interval("0.028", "0.028000001") == "0.028 – 0.028", "a narrow interval that is not fixed")
    campaign = work / "fixed.ini"
    campaign.write_text(FIXED_CAMPAIGN.format(source=source.resolve()))
    ran = run(cli, "run", campaign, "--quiet", "--out", work / "fixed")
    check(ran.returncode == 0, f"run of the fixed-law campaign: {ran.stderr}")
    if ran.returncode != 0:
        return
    made = run(cli, "report", work / "fixed")
    check(made.returncode == 0, f"report of the fixed-law campaign: {made.stderr}")
    if made.returncode != 0:
        return
    rows = parse_report((work / "fixed" / "report.html").read_text(encoding="utf-8")).tables["summary"][1:]
    cells = {(row[0], row[1]): row[3] for row in rows}
    fixed = []
    for expected in csv.DictReader(open(work / "fixed" / "summary.csv", newline="")):
        if not expected["data_ci_low"]:
            check(cells[expected["line"], expected["quantity"]] == "—", f"{expected['line']} {expected['quantity']}")
            continue
        low, high = float(expected["data_ci_low"]), float(expected["data_ci_high"])
        cell = cells[expected["line"], expected["quantity"]]
        if cli_says_fixed(low, high):
            fixed.append((expected["line"], expected["quantity"]))
            check(cell == "fixed", f"{expected['line']} {expected['quantity']} [{low!r}, {high!r}] printed {cell!r}")
        else:
            shown = interval_cell(cell)
            check(close(shown[0], low) and close(shown[1], high), f"{expected['line']} {expected['quantity']}: {cell}")
    check(("wild_type", "v") in fixed, f"the calibrated reference's v is not fixed: {fixed}")


def check_page(text, report, provenance):
    methods = report.sections.get("methods", "")
    for expected in (f"seed {provenance['seed']}", f"{provenance['samples_per_line']} Latin hypercube samples",
                     "probe radius of 0.5 µm", provenance["campaign_sha256"],
                     f"{provenance['data_interval_replicates']} replicates of {provenance['data_interval_samples']}"):
        check(expected in methods, f"methods paragraph lacks {expected!r}: {methods!r}")
    references = report.sections.get("references", "")
    for author in ("Arnoldi", "Vogler", "Lockhart", "McKay", "Iman"):
        check(author in references, f"no reference {author}")
    # Every line is given by raw data: the published study's table is used by none.
    check("gmunglani/Chip" not in references, "the published study cited for a campaign of raw-data lines")
    check("-55 %" in report.sections.get("warnings", ""), "no warning of the closed form's measured error")
    for forbidden in ("<script", "<link", 'src="http', "url("):
        check(forbidden not in text, f"the report is not self-contained: {forbidden}")
    check(len(report.images) >= 4, f"{len(report.images)} figures")
    for source in report.images:
        prefix = "data:image/png;base64,"
        check(source.startswith(prefix) and base64.b64decode(source[len(prefix):])[:8] == b"\x89PNG\r\n\x1a\n",
              f"an image that is not an embedded PNG: {source[:40]}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True, type=Path)
    parser.add_argument("--source-dir", required=True, type=Path)
    arguments = parser.parse_args()
    campaign = arguments.source_dir / "tests/campaign/data/raw_comparisons.ini"
    with tempfile.TemporaryDirectory(prefix="growthuq-report-test-") as scratch:
        work = Path(scratch)
        check_refusals(arguments.cli, work)
        run_dir = work / "run"
        ran = run(arguments.cli, "run", campaign, "--quiet", "--out", run_dir)
        if ran.returncode != 0:
            print(f"growthuq run failed ({ran.returncode}): {ran.stderr}", file=sys.stderr)
            return 1
        made = run(arguments.cli, "report", run_dir)
        check(made.returncode == 0 and f"wrote {run_dir / 'report.html'}" in made.stdout,
              f"report: exit {made.returncode}, {made.stdout!r} {made.stderr!r}")
        text = (run_dir / "report.html").read_text(encoding="utf-8")
        again = run(arguments.cli, "report", run_dir)
        check(again.returncode == 2 and "report.html: already exists" in again.stderr and "--force" in again.stderr,
              f"an existing report without --force: exit {again.returncode}, {again.stderr!r}")
        check((run_dir / "report.html").read_text(encoding="utf-8") == text, "the refused report was changed")
        forced = run(arguments.cli, "report", run_dir, "--force", "--out", work / "other.html")
        check(forced.returncode == 0 and (work / "other.html").is_file(), f"--out with --force: {forced.stderr!r}")
        provenance = check_provenance(run_dir, campaign)
        report = parse_report(text)
        check_tables(report, run_dir)
        check_page(text, report, provenance)
        check_fixed(arguments.cli, arguments.source_dir, work)
    if failures:
        print(f"{len(failures)} checks failed", file=sys.stderr)
        return 1
    print("report checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
