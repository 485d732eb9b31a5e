#!/usr/bin/python3
"""The report in a real browser (issue 30): Debian's headless chromium renders a report of a
small campaign; the screenshot must not be blank (a blank page, rendered the same way, is the
control that shows the measure can fail) and the DOM chromium built must hold the summary table
with summary.csv's rows and the embedded figures. chromium is optional (tools/install-deps
installs it): without it the test is skipped with exit status 77 (CTest SKIP_RETURN_CODE).
Usage: test_report_browser.py --cli GROWTHUQ --source-dir SOURCE"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from matplotlib import image

sys.path.insert(0, str(Path(__file__).resolve().parent))
from report_html import parse_report  # noqa: E402

SKIPPED = 77
WINDOW = (1200, 1600)


def chromium_command(browser, *arguments):
    command = [browser, "--headless", "--disable-gpu", "--hide-scrollbars", f"--window-size={WINDOW[0]},{WINDOW[1]}"]
    if os.geteuid() == 0:
        command.append("--no-sandbox")  # chromium refuses to run as root with its sandbox
    return command + list(arguments)


def screenshot(browser, page, target):
    """The page rendered to a PNG, read as an RGB array in [0, 1]."""
    done = subprocess.run(chromium_command(browser, f"--screenshot={target}", page.as_uri()),
                          capture_output=True, text=True, timeout=120)
    if done.returncode != 0 or not target.is_file():
        raise RuntimeError(f"chromium --screenshot failed ({done.returncode}): {done.stderr[-2000:]}")
    pixels = image.imread(target)[..., :3]
    return pixels


def ink(pixels):
    """(grey-level standard deviation, share of pixels darker than near-white): both about 0 for
    a blank page."""
    grey = pixels.mean(axis=2)
    return float(grey.std()), float((grey < 0.9).mean())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True, type=Path)
    parser.add_argument("--source-dir", required=True, type=Path)
    arguments = parser.parse_args()
    browser = shutil.which("chromium")
    if browser is None:
        print("SKIPPED: chromium not found (an optional tool: tools/install-deps installs it)")
        return SKIPPED
    failures = []
    with tempfile.TemporaryDirectory(prefix="growthuq-report-browser-") as scratch:
        work = Path(scratch)
        run_dir = work / "run"
        ran = subprocess.run([str(arguments.cli), "run", str(arguments.source_dir / "campaigns/quick.ini"), "--quiet",
                              "--samples", "100", "--out", str(run_dir)], capture_output=True, text=True)
        made = subprocess.run([str(arguments.cli), "report", str(run_dir)], capture_output=True, text=True)
        if ran.returncode != 0 or made.returncode != 0:
            print(f"run or report failed: {ran.stderr} {made.stderr}", file=sys.stderr)
            return 1
        page = run_dir / "report.html"
        blank = work / "blank.html"
        blank.write_text("<!DOCTYPE html><html><body></body></html>")
        spread, inked = ink(screenshot(browser, page, work / "report.png"))
        blank_spread, blank_inked = ink(screenshot(browser, blank, work / "blank.png"))
        print(f"report: grey sd {spread:.4f}, {100 * inked:.2f} % of pixels inked; blank page: grey sd "
              f"{blank_spread:.4f}, {100 * blank_inked:.2f} %")
        if not (blank_spread < 0.01 and blank_inked < 0.001):
            failures.append("the blank page does not measure as blank: the measure is broken")
        if not (spread > 0.1 and inked > 0.02):
            failures.append("the report's screenshot is (nearly) blank")
        dumped = subprocess.run(chromium_command(browser, "--dump-dom", page.as_uri()), capture_output=True,
                                text=True, timeout=120)
        report = parse_report(dumped.stdout)
        summary = list(csv.DictReader(open(run_dir / "summary.csv", newline="")))
        rows = report.tables.get("summary", [])[1:]
        if [row[:2] for row in rows] != [[row["line"], row["quantity"]] for row in summary]:
            failures.append(f"the browser's summary table has {len(rows)} rows, not summary.csv's {len(summary)}")
        if not any(source.startswith("data:image/png;base64,") for source in report.images):
            failures.append("no embedded figure in the browser's DOM")
        if "methods" not in report.sections or "references" not in report.sections:
            failures.append("the methods or references section is missing from the browser's DOM")
    for failure in failures:
        print(f"FAIL: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
