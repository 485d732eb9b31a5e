#!/usr/bin/python3
"""CI test of tools/fe-correction/plot-errors (fidelity_errors.png of README.md, "Fidelity").

Writes the errors table with the real `growthuq fit-correction --errors` (the shipped training data,
a fraction of a second), draws it with the script as a user does, and reads what was drawn back
against the relative errors computed here from the table with the csv module: every panel on one
logarithmic axis of |error| in % (so the closed form's tens of per cent and the corrected form's
tenths sit on the same scale), each point the tube's |model / FE - 1|, the medians in the titles.

    /usr/bin/python3 tests/plot/test_fidelity_errors.py --cli build/release/growthuq --source-dir .
"""
import argparse
import csv
import importlib.machinery
import importlib.util
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import numpy as np
from matplotlib.image import imread

OPTIONS = None


def load_script(path):
    """The script (no .py suffix) as a module, to call its figure builder."""
    loader = importlib.machinery.SourceFileLoader("plot_errors", str(path))
    spec = importlib.util.spec_from_loader("plot_errors", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


class FidelityErrors(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.tmp = Path(tempfile.mkdtemp(prefix="growthuq-fidelity-errors-"))
        cls.errors = cls.tmp / "errors.csv"
        training = OPTIONS.source_dir / "src" / "correction" / "training.csv"  # the shipped training data
        done = subprocess.run([OPTIONS.cli, "fit-correction", "--training", training, "--out", cls.tmp / "correction.inc",
                               "--errors", cls.errors], capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"growthuq fit-correction failed: {done.stderr}")
        with open(cls.errors, newline="") as handle:
            cls.rows = [row for row in csv.DictReader(handle) if row["p_closed_form_MPa"]]
        cls.script = OPTIONS.source_dir / "tools" / "fe-correction" / "plot-errors"
        cls.module = load_script(cls.script)
        cls.figure = cls.module.error_figure(cls.module.read_rows(cls.errors))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_the_script_writes_the_png(self):
        out = self.tmp / "fidelity_errors.png"
        done = subprocess.run([sys.executable, self.script, self.errors, out], capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(done.stdout.strip(), f"wrote {out} ({len(self.rows)} rows: training tubes under their force windows)")
        pixels = imread(out)
        self.assertGreater(pixels.shape[1], 1000)
        self.assertLess(pixels[..., :3].min(), 0.3)

    def test_one_logarithmic_axis_for_every_panel(self):
        axes = self.figure.axes
        self.assertEqual(len(axes), 6)
        self.assertEqual({ax.get_yscale() for ax in axes}, {"log"})
        self.assertEqual(len({tuple(np.round(ax.get_ylim(), 12)) for ax in axes}), 1)
        self.assertEqual([axes[0].get_ylabel(), axes[3].get_ylabel()],
                         ["|error in p| (% of FE)", "|error in E| (% of FE)"])
        self.assertLessEqual(self.figure.get_figwidth(), 7.09)

    def test_each_point_is_the_tubes_relative_error_and_the_medians_are_stated(self):
        self.assertGreater(len(self.rows), 100)
        for quantity in ("p", "E"):
            all_errors, held_out_errors = {}, {}
            for form in ("closed_form", "corrected"):
                errors = []
                for held_out in ("0", "1"):
                    mine = [r for r in self.rows if r["held_out"] == held_out and r[f"{quantity}_{form}_MPa"]]
                    expected = [100 * abs(float(r[f"{quantity}_{form}_MPa"]) / float(r[f"{quantity}_fe_MPa"]) - 1)
                                for r in mine]
                    kind = "held_out" if held_out == "1" else "fitted"
                    for group in ("lambda", "h_over_d", "rho_over_d"):
                        (drawn,) = [c for c in self.figure.findobj(lambda a: a.get_gid() == f"{quantity}/{group}/{form}/{kind}")]
                        points = drawn.get_offsets()
                        self.assertTrue(np.allclose(points[:, 0], [float(r[group]) for r in mine], rtol=1e-12, atol=0))
                        self.assertTrue(np.allclose(points[:, 1], expected, rtol=1e-12, atol=0))
                    errors += expected
                    if held_out == "1":
                        held_out_errors[form] = np.array(expected)
                all_errors[form] = np.array(errors)
            # What the figure is for: the corrected form's worst error lies below the closed form's
            # best, and its median is a small fraction of the closed form's.
            self.assertGreater(all_errors["closed_form"].min(), all_errors["corrected"].max())
            self.assertGreater(np.median(all_errors["closed_form"]), 20 * np.median(all_errors["corrected"]))
            title = [ax.get_title(loc="left") for ax in self.figure.axes if ax.get_title(loc="left")]
            median_closed = np.median(held_out_errors["closed_form"])
            median_corrected = np.median(held_out_errors["corrected"])
            self.assertIn(f"{quantity}, held out: median |error| {median_closed:.0f} % (closed), "
                          f"{median_corrected:.2g} % (corrected)", title)

    def test_a_table_without_closed_form_values_is_one_line_naming_it(self):
        empty = self.tmp / "empty.csv"
        empty.write_text("index,held_out,lambda\n")
        done = subprocess.run([sys.executable, self.script, empty, self.tmp / "x.png"], capture_output=True, text=True)
        self.assertNotEqual(done.returncode, 0)
        self.assertNotIn("Traceback", done.stderr)
        self.assertEqual(done.stderr.strip(), f"plot-errors: {empty}: no row with a closed-form value (expected the "
                         "table `growthuq fit-correction --errors` writes)")
        self.assertFalse((self.tmp / "x.png").exists())


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, type=Path, help="the growthuq executable")
    parser.add_argument("--source-dir", required=True, type=Path, help="the checkout root")
    OPTIONS, rest = parser.parse_known_args()
    OPTIONS.source_dir = OPTIONS.source_dir.resolve()
    sys.dont_write_bytecode = True
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)
