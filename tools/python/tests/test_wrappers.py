"""The package's other CLI wrappers against the CLI itself: check, tradeoff, synth and fit_line;
progress shown live with quiet=False; the CLI's failures as typed exceptions by exit status.

Run by CTest (tests/python/CMakeLists.txt, test_python_package) with GROWTHUQ_CLI set:
    GROWTHUQ_CLI=$PWD/build/release/growthuq PYTHONPATH=tools/python /usr/bin/python3 -m unittest discover -s tools/python/tests
"""
import io
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import numpy as np
import pandas as pd

import growthuq
from growthuq.errors import cli_error

REPOSITORY = Path(__file__).resolve().parents[3]

# A raw-data line (curve fits and a bootstrap, so stderr has progress) and a line file.
CAMPAIGN = f"""[campaign]
name = wrappers
seed = 5
samples = 30
outputs = p, E
output_dir = out
formats = csv, hdf5

[instrument]
probe_radius_um = 0.5

[data_uncertainty]
replicates = 20

[line xeg113]
raw = {REPOSITORY}/distributions/example_raw/xeg113/raw.ini

[line pme48]
distributions = {REPOSITORY}/distributions/pme48.ini
"""


class Wrappers(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory(prefix="growthuq-wrappers-")
        self.work = Path(self.scratch.name)
        self.campaign = self.work / "campaign.ini"
        self.campaign.write_text(CAMPAIGN)

    def tearDown(self):
        self.scratch.cleanup()

    def test_check_prints_the_plan_and_writes_nothing(self):
        plan = growthuq.check(self.campaign, cwd=self.work, samples=12)
        self.assertIn("campaign 'wrappers' (", plan)
        self.assertIn("2 lines x 12 samples, seed 5", plan)
        self.assertIn("checked: nothing was sampled or written", plan)
        self.assertFalse((self.work / "out").exists())
        direct = subprocess.run([growthuq.find_cli(), "check", str(self.campaign), "--samples", "12", "--quiet"],
                                cwd=self.work, capture_output=True, text=True, check=True).stdout
        # The same plan but for the measured memory and disk (they change between two calls).
        def without_machine(text):
            return [line for line in text.splitlines() if not line.startswith("estimated peak memory")]
        self.assertEqual(without_machine(plan), without_machine(direct))

    def test_check_of_a_bad_campaign_raises_input_error_with_the_cli_message(self):
        (self.work / "bad.ini").write_text(CAMPAIGN.replace("samples = 30", "samples = many"))
        with self.assertRaises(growthuq.InputError) as caught:
            growthuq.check(self.work / "bad.ini", cwd=self.work)
        error = caught.exception
        self.assertIsInstance(error, growthuq.CliError)
        self.assertIsInstance(error, ValueError)
        self.assertIsInstance(error, growthuq.GrowthuqError)
        self.assertEqual(error.returncode, 2)
        self.assertTrue(str(error).startswith("growthuq check: error: "), str(error))
        self.assertIn("many", str(error))

    def test_tradeoff_table_has_the_medians_a_run_of_that_count_gives(self):
        table = growthuq.tradeoff(self.campaign, cwd=self.work, samples_list=[10, 30], out="trade.csv")
        self.assertEqual(table.attrs["path"], self.work / "trade.csv")
        self.assertIn("table: trade.csv", table.attrs["report"])
        self.assertEqual(sorted(set(table["samples"])), [10, 30])
        # The design depends on seed, line and count only: the 30-sample rows are a 30-sample run's.
        results = growthuq.run(self.campaign, cwd=self.work, out="run30")
        summary = pd.read_csv(self.work / "run30" / "summary.csv", float_precision="round_trip")
        largest = table[table["samples"] == 30].merge(summary, on=["line", "quantity"], suffixes=("", "_run"))
        self.assertEqual(len(largest), len(summary))
        np.testing.assert_array_equal(largest["median"], largest["median_run"])
        np.testing.assert_array_equal(largest["iqr"], largest["iqr_run"])
        self.assertEqual(results.lines, ["xeg113", "pme48"])

    def test_synth_then_fit_line_give_the_line_file_the_cli_writes(self):
        drawn = growthuq.synth(REPOSITORY / "distributions" / "pme48.ini", "raw", cwd=self.work, seed=3,
                               tubes="20:25", curves="3:4")
        self.assertEqual(drawn, {"pme48": self.work / "raw" / "pme48" / "raw.ini"})
        self.assertTrue(drawn["pme48"].is_file())
        fit = growthuq.fit_line(drawn["pme48"])
        direct = subprocess.run([growthuq.find_cli(), "fit-line", str(drawn["pme48"]), "--out", "-", "--quiet"],
                                capture_output=True, text=True, check=True)
        self.assertEqual(fit.text, direct.stdout)  # the line file, as the CLI writes it
        # Its fit report, but for the last line: where the CLI wrote the line file (a scratch file here).
        self.assertEqual(fit.report.splitlines(), direct.stderr.splitlines()[:-1])
        self.assertIn("name = pme48", fit.text)
        self.assertIsNone(fit.path)
        kept = growthuq.fit_line(drawn["pme48"], out="pme48_fitted.ini", cwd=self.work)
        self.assertEqual((self.work / "pme48_fitted.ini").read_text(), fit.text)
        with self.assertRaises(growthuq.InputError) as caught:  # no silent overwrite
            growthuq.fit_line(drawn["pme48"], out="pme48_fitted.ini", cwd=self.work)
        self.assertIn("--force", str(caught.exception))
        self.assertEqual(kept.path, self.work / "pme48_fitted.ini")


class LiveProgress(io.StringIO):
    """A stand-in for sys.stderr that notes, at each write, whether the run had finished yet (its
    summary.csv, moved into place last, exists)."""

    def __init__(self, finished):
        super().__init__()
        self.finished = finished
        self.written_while_running = 0

    def write(self, text):
        if not self.finished.exists():
            self.written_while_running += 1
        return super().write(text)


class Progress(unittest.TestCase):
    def run_with_stderr(self, quiet):
        with tempfile.TemporaryDirectory(prefix="growthuq-progress-") as scratch:
            work = Path(scratch)
            (work / "campaign.ini").write_text(CAMPAIGN)
            stream = LiveProgress(work / "out" / "summary.csv")
            saved, sys.stderr = sys.stderr, stream
            try:
                growthuq.run(work / "campaign.ini", cwd=work, quiet=quiet)
            finally:
                sys.stderr = saved
        return stream

    def test_quiet_false_shows_the_cli_progress_while_it_runs(self):
        stream = self.run_with_stderr(quiet=False)
        shown = stream.getvalue()
        self.assertIn("fitting relaxation curves of line xeg113", shown)
        self.assertIn("data uncertainty", shown)
        self.assertGreater(stream.written_while_running, 0)  # live, not after the run

    def test_fit_line_shows_its_curve_fits_unless_quiet(self):
        raw = REPOSITORY / "distributions" / "example_raw" / "xeg113" / "raw.ini"
        curves = sum(1 for line in (raw.parent / "relaxation_meta.csv").read_text().splitlines()
                     if line and not line.startswith(("#", "curve")))
        for quiet in (False, True):
            saved, sys.stderr = sys.stderr, io.StringIO()
            try:
                growthuq.fit_line(raw, quiet=quiet)
                shown = sys.stderr.getvalue()
            finally:
                sys.stderr = saved
            if quiet:
                self.assertEqual(shown, "")
            else:
                self.assertRegex(shown, rf"fitting relaxation curves: {curves} curves in [0-9.]+ s")

    def test_quiet_shows_nothing(self):
        self.assertEqual(self.run_with_stderr(quiet=True).getvalue(), "")

    def test_a_failure_after_progress_raises_with_the_error_line_only(self):
        with tempfile.TemporaryDirectory(prefix="growthuq-progress-") as scratch:
            work = Path(scratch)
            (work / "campaign.ini").write_text(CAMPAIGN)
            (work / "out").mkdir()
            (work / "out" / "keep.txt").write_text("a previous result")
            saved, sys.stderr = sys.stderr, io.StringIO()
            try:
                with self.assertRaises(growthuq.InputError) as caught:
                    growthuq.run(work / "campaign.ini", cwd=work, quiet=False)
            finally:
                sys.stderr = saved
        self.assertTrue(str(caught.exception).startswith("growthuq run: error: "), str(caught.exception))


class ExitStatuses(unittest.TestCase):
    def test_each_exit_status_has_its_exception(self):
        command = ["growthuq", "run"]
        cases = [(2, "growthuq run: error: x", growthuq.InputError),
                 (3, "growthuq run: internal error: x", growthuq.InternalError),
                 (3, "growthuq run: error: out of memory: this machine could not provide", growthuq.OutOfMemoryError),
                 (130, "interrupted", growthuq.Interrupted), (-9, "", growthuq.Interrupted),
                 (1, "other", growthuq.CliError)]
        for status, message, kind in cases:
            error = cli_error(message, status, command)
            self.assertIs(type(error), kind, status)
            self.assertEqual((str(error), error.returncode, error.command), (message, status, command))
        self.assertIsInstance(cli_error("out of memory", 3, command), MemoryError)

    def test_no_cli_and_a_nul_argument_are_growthuq_errors(self):
        with self.assertRaises(growthuq.CliNotFoundError) as caught:
            growthuq.check("campaign.ini", cli="/nonexistent/growthuq")
        self.assertIsInstance(caught.exception, FileNotFoundError)
        with self.assertRaises(growthuq.ArgumentError):
            growthuq.check("campaign\0.ini")


if __name__ == "__main__":
    unittest.main()
