#!/usr/bin/python3
"""CI test of tools/plot (issue 5, Plots).

Runs a small real campaign (campaigns/quick.ini, 200 samples per line, v_exp among the outputs)
with the growthuq CLI, runs tools/plot on it headless as a subprocess exactly as a user would,
checks the PNG and PDF files, and then rebuilds the figures in-process and reads back what was
drawn against references computed here, independently, from results.h5 with numpy and scipy:
box edges = quartiles, whisker ends = 10th/90th percentiles, n labels = counted samples, axis
labels with units, the correlogram's Spearman numbers = scipy.stats.spearmanr, its points where
its own tick labels say they are, PCA bars = the stored explained variance. The relaxation and
trade plots are checked against FIXTURES built below in the documented formats (clearly marked),
until `growthuq run` and `growthuq tradeoff` write them.

    /usr/bin/python3 tests/plot/test_plots.py --cli build/release/growthuq --source-dir .
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import h5py
import numpy as np
from matplotlib import colors as mcolors
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.image import imread
from matplotlib.legend import Legend
from scipy.stats import spearmanr

OPTIONS = None      # command-line options, set in __main__
SOURCE = None       # checkout root
PLOTTING = None     # the plotting package, imported from SOURCE/tools

TOLERANCE = 1e-12   # relative: the plots must carry the very numbers computed here (both are
                    # numpy's linear-interpolation quantiles of the same doubles)
EXPECTED_UNITS = {"p": "MPa", "E": "MPa", "eta": "MPa s", "v": "um/s"}
# The units as the figures typeset them (µ for the files' u, a centred dot for a product).
TYPESET = {"MPa": "MPa", "MPa s": "MPa·s", "um/s": "µm/s", "um": "µm", "N/m": "N/m", "nm": "nm", "s": "s",
           "%": "%", "frac": "frac"}


def display(line):
    """A line's name as the figures print it: "xxt1 xxt2", not the identifier xxt1_xxt2."""
    return line.replace("_", " ")


def close(a, b, tolerance=TOLERANCE):
    return np.allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=tolerance, atol=0)


# ---------------------------------------------------------------- independent reading of the file

class Reference:
    """What the plots should show, computed directly from results.h5 with h5py and numpy."""

    def __init__(self, path):
        with h5py.File(path, "r") as h5:
            self.kappa = float(h5.attrs["kappa"])
            summary_lines = [x.decode() if isinstance(x, bytes) else x for x in h5["summary"]["line"]]
            self.lines = list(dict.fromkeys(summary_lines))
            self.summary = {}
            for row in h5["summary"][()]:
                key = tuple(x.decode() if isinstance(x, bytes) else x for x in (row["line"], row["quantity"]))
                self.summary[key] = row
            self.status, self.columns, self.attrs, self.analysis = {}, {}, {}, {}
            for line in self.lines:
                group = h5["lines"][line]
                names = [str(n) for n in group["status"].attrs["names"]]
                self.status[line] = np.array(names, dtype=object)[group["status"][()]]
                for key, node in group.items():
                    if isinstance(node, h5py.Dataset) and "role" in node.attrs:
                        self.columns[line, key] = node[()]
                        self.attrs[line, key] = {a: str(node.attrs[a]) for a in ("quantity", "unit", "role")}
                analysis = group["analysis"]
                self.analysis[line] = {
                    "ratio": analysis["explained_variance_ratio"][()],
                    "rows": [str(r) for r in analysis["loadings"].attrs["rows"]],
                    "io": analysis["input_output_spearman"][()],
                    "io_rows": [str(r) for r in analysis["input_output_spearman"].attrs["rows"]],
                    "io_columns": [str(c) for c in analysis["input_output_spearman"].attrs["columns"]],
                }

    def dataset(self, line, quantity):
        return next(key for (owner, key), attrs in self.attrs.items()
                    if owner == line and attrs["quantity"] == quantity)

    def unit(self, line, quantity):
        return self.attrs[line, self.dataset(line, quantity)]["unit"]

    def counted(self, line, quantity):
        """growthuq's summary rule: the samples holding a value (NaN: the sample lacks it)."""
        values = self.columns[line, self.dataset(line, quantity)]
        return values[np.isfinite(values)]


def as_text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def percentiles(values):
    return dict(zip(("p10", "q1", "median", "q3", "p90"), np.percentile(values, [10, 25, 50, 75, 90])))


# ---------------------------------------------------------------- the campaign and the CLI runs

def run(command, **kwargs):
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}  # headless, as in CI
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    return subprocess.run([str(c) for c in command], capture_output=True, text=True, env=env, **kwargs)


def plot_command(*arguments):
    return run([SOURCE / "tools" / "plot", *arguments])


def write_campaign(directory, yield_pressure_MPa=0.0):
    """A copy of campaigns/quick.ini asking for v_exp beside v, with absolute line-file paths."""
    text = (SOURCE / "campaigns" / "quick.ini").read_text()
    text = re.sub(r"(?m)^outputs\s*=.*$", "outputs = p, E, eta, v, v_exp", text)
    text = re.sub(r"(?m)^yield_pressure_MPa\s*=.*$", f"yield_pressure_MPa = {yield_pressure_MPa}", text)
    text = text.replace("= ../distributions/", f"= {SOURCE / 'distributions'}/")
    path = directory / f"quick_v_exp_p0_{yield_pressure_MPa}.ini"
    path.write_text(text)
    return path


class Shared:
    """The campaign and the first tools/plot run, made once for every test."""
    tmp = None
    results_dir = None
    plot_run = None
    reference = None
    results = None


def setUpModule():
    Shared.tmp = Path(tempfile.mkdtemp(prefix="growthuq-plot-test-"))
    campaign = write_campaign(Shared.tmp)
    Shared.results_dir = Shared.tmp / "quick"
    done = run([OPTIONS.cli, "run", campaign, "--samples", 200, "--out", Shared.results_dir, "--quiet"])
    if done.returncode != 0:
        raise RuntimeError(f"growthuq run failed: {done.stderr}")
    Shared.plot_run = plot_command(Shared.results_dir)
    Shared.reference = Reference(Shared.results_dir / "results.h5")
    Shared.results = PLOTTING.results.read_results(Shared.results_dir / "results.h5")


def tearDownModule():
    if Shared.tmp is not None:
        shutil.rmtree(Shared.tmp, ignore_errors=True)


def assert_valid_png(test, path):
    with open(path, "rb") as handle:
        test.assertEqual(handle.read(8), b"\x89PNG\r\n\x1a\n", path)
    pixels = imread(path)  # decodes every row: a truncated file fails here
    test.assertGreater(pixels.shape[0], 300, path)
    test.assertGreater(pixels.shape[1], 300, path)
    test.assertLess(pixels[..., :3].min(), 0.3, f"{path}: nothing dark was drawn")


def assert_valid_pdf(test, path):
    data = Path(path).read_bytes()
    test.assertTrue(data.startswith(b"%PDF-"), path)
    test.assertTrue(data.rstrip().endswith(b"%%EOF"), path)
    test.assertEqual(len(re.findall(rb"/Type\s*/Page\b", data)), 1, f"{path}: one page expected")


def gid_artists(figure, pattern):
    """Every artist of `figure` whose gid matches the regular expression `pattern`."""
    found = []
    for artist in figure.findobj(lambda a: a.get_gid() is not None):
        if re.fullmatch(pattern, artist.get_gid()):
            found.append(artist)
    return found


def one(figure, gid):
    found = gid_artists(figure, re.escape(gid))
    if len(found) != 1:
        raise AssertionError(f"{len(found)} artists with gid {gid}")
    return found[0]


def assert_box(test, figure, key, expected, position):
    """The box drawn under gid `key` spans the quartiles at `position`, its median line is the
    median, its whiskers run from the quartiles to the 10th and 90th percentiles."""
    box = one(figure, f"{key}/box").get_path().vertices
    test.assertTrue(close([box[:, 1].min(), box[:, 1].max()], [expected["q1"], expected["q3"]]), key)
    test.assertTrue(close((box[:, 0].min() + box[:, 0].max()) / 2, position, 1e-9), key)
    test.assertTrue(close(one(figure, f"{key}/median").get_ydata(), [expected["median"]] * 2), key)
    test.assertTrue(close(one(figure, f"{key}/whisker_low").get_ydata(),
                          [expected["q1"], expected["p10"]]), key)
    test.assertTrue(close(one(figure, f"{key}/whisker_high").get_ydata(),
                          [expected["q3"], expected["p90"]]), key)


def user_error(test, completed, *expected_fragments):
    test.assertEqual(completed.returncode, 2, completed.stdout + completed.stderr)
    test.assertNotIn("Traceback", completed.stderr)
    message = completed.stderr.strip()
    test.assertEqual(len(message.splitlines()), 1, message)
    for fragment in expected_fragments:
        test.assertIn(str(fragment), message)


# ---------------------------------------------------------------- the command as a user runs it

class CommandLine(unittest.TestCase):

    def test_writes_every_figure_as_valid_png_and_pdf_and_says_what_it_skipped(self):
        completed = Shared.plot_run
        self.assertEqual(completed.returncode, 0, completed.stderr)
        plots = Shared.results_dir / "plots"
        stems = ["boxes", "growth_rate", "sensitivity"] + [f"correlogram_{l}" for l in Shared.reference.lines]
        for stem in stems:
            for extension, check in (("png", assert_valid_png), ("pdf", assert_valid_pdf)):
                path = plots / f"{stem}.{extension}"
                self.assertIn(f"wrote {path}", completed.stdout.splitlines())
                check(self, path)
        written = [line for line in completed.stdout.splitlines() if line.startswith("wrote ")]
        self.assertEqual(len(written), 2 * len(stems) + 1)
        self.assertEqual(sorted(p.name for p in plots.iterdir()),
                         sorted([f"{s}.{e}" for s in stems for e in ("png", "pdf")] + ["captions.md"]))
        # The captions beside the figures, one paragraph per figure in the order drawn.
        captions = (plots / "captions.md").read_text().split("\n\n")[:-1]
        self.assertEqual([c.split("**")[1] for c in captions],
                         ["boxes", "growth_rate"] + [s for s in stems if s.startswith("correlogram_")] + ["sensitivity"])
        self.assertIn("Box q1-q3, line at the median, whiskers 10-90 %.", captions[0])
        self.assertRegex(completed.stdout, r"note: skipped relaxation curves: .*relaxation")
        self.assertRegex(completed.stdout, r"note: skipped force curves: .*force_curves")
        self.assertRegex(completed.stdout, r"note: skipped trade plot: no .*tradeoff\.csv")
        status = Shared.reference.status
        flagged = {line: int((status[line] != "ok").sum()) for line in Shared.reference.lines}
        expected = ", ".join(f"{line} {count}" for line, count in flagged.items() if count)
        self.assertIn(f"flagged samples (status not ok): {expected} (of 200 per line); a box leaves out only "
                      "those lacking its quantity", completed.stdout)

    def test_refuses_to_overwrite_plots_without_force(self):
        target = self.plots_copy()
        before = {p.name: p.stat().st_mtime_ns for p in (target / "plots").iterdir()}
        refused = plot_command(target, "--formats", "png", "--figures", "sensitivity")
        user_error(self, refused, target / "plots" / "sensitivity.png", "--force")
        self.assertEqual(before, {p.name: p.stat().st_mtime_ns for p in (target / "plots").iterdir()})
        forced = plot_command(target, "--formats", "png", "--figures", "sensitivity", "--force")
        self.assertEqual(forced.returncode, 0, forced.stderr)
        self.assertGreater((target / "plots" / "sensitivity.png").stat().st_mtime_ns, before["sensitivity.png"])
        self.assertFalse(list((target / "plots").glob("*.partial")))

    def plots_copy(self):
        target = Shared.tmp / "overwrite"
        if not target.exists():
            target.mkdir()
            shutil.copy(Shared.results_dir / "results.h5", target)
            self.assertEqual(plot_command(target, "--formats", "png", "--figures", "sensitivity").returncode, 0)
        return target

    def test_bad_input_is_one_line_naming_the_file_and_what_was_expected(self):
        missing = Shared.tmp / "does-not-exist"
        user_error(self, plot_command(missing), missing, "no such directory")

        empty = Shared.tmp / "empty"
        empty.mkdir(exist_ok=True)
        user_error(self, plot_command(empty), empty / "results.h5", "expected the results.h5")

        not_hdf5 = Shared.tmp / "not-hdf5"
        not_hdf5.mkdir(exist_ok=True)
        (not_hdf5 / "results.h5").write_text("line,quantity\nwild_type,p\n")
        user_error(self, plot_command(not_hdf5), not_hdf5 / "results.h5", "not a readable HDF5 file")

        foreign = Shared.tmp / "foreign"
        foreign.mkdir(exist_ok=True)
        with h5py.File(foreign / "results.h5", "w") as h5:
            h5["x"] = np.arange(3.0)
        user_error(self, plot_command(foreign), foreign / "results.h5", "not a growthuq results file")

        no_status = Shared.tmp / "no-status"
        no_status.mkdir(exist_ok=True)
        shutil.copy(Shared.results_dir / "results.h5", no_status)
        with h5py.File(no_status / "results.h5", "a") as h5:
            del h5["lines/pme48/status"]
        user_error(self, plot_command(no_status), "/lines/pme48/status: missing")

        bad_trade = Shared.tmp / "bad-trade"
        bad_trade.mkdir(exist_ok=True)
        shutil.copy(Shared.results_dir / "results.h5", bad_trade)
        (bad_trade / "tradeoff.csv").write_text("fidelity,samples\nthin_shell,100\n")
        user_error(self, plot_command(bad_trade, "--figures", "tradeoff"),
                   bad_trade / "tradeoff.csv", "header lacks", "median_error_pct")

        unknown = plot_command(Shared.results_dir, "--formats", "svg")
        self.assertEqual(unknown.returncode, 2)
        self.assertIn("expected a comma-separated list of png, pdf", unknown.stderr)


# ---------------------------------------------------------------- what was drawn

class BoxPlots(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.figure = PLOTTING.boxes.box_figure(Shared.results)

    def test_one_panel_per_quantity_with_units_and_one_box_per_line(self):
        reference = Shared.reference
        panels = {ax.get_ylabel(): ax for ax in self.figure.axes}
        self.assertEqual(sorted(panels), sorted(f"{q} ({TYPESET[u]})" for q, u in EXPECTED_UNITS.items()))
        for quantity, unit in EXPECTED_UNITS.items():
            ax = panels[f"{quantity} ({TYPESET[unit]})"]
            self.assertEqual(unit, reference.unit(reference.lines[0], quantity))
            boxes = [p for p in ax.patches if (p.get_gid() or "").endswith("/box")]
            self.assertEqual(len(boxes), len(reference.lines))
            self.assertEqual([t.get_text() for t in ax.get_xticklabels()], [display(l) for l in reference.lines])
            self.assertEqual(ax.get_yscale(), "log" if quantity in ("E", "eta") else "linear")
            self.assertEqual(ax.get_title().endswith(" (log scale)"), quantity in ("E", "eta"), quantity)

    def test_boxes_are_quartiles_whiskers_are_10_and_90_percentiles_and_n_is_the_counted_samples(self):
        reference = Shared.reference
        for quantity in EXPECTED_UNITS:
            for position, line in enumerate(reference.lines):
                values = reference.counted(line, quantity)
                expected = percentiles(values)
                key = f"{line}/{quantity}"
                assert_box(self, self.figure, key, expected, position)
                # Under the box the samples it leaves out; it holds the other of the 200 per line.
                label = one(self.figure, f"{key}/n").get_text()
                flagged = 200 - values.size
                self.assertEqual(label, f"{flagged} flagged" if flagged else "", key)
                # The same numbers as the engine's summary (summary.csv, /summary in results.h5).
                row = reference.summary[line, quantity]
                self.assertEqual(int(row["n"]), values.size)
                self.assertTrue(close([row[k] for k in expected], list(expected.values())), key)


    def test_without_a_bootstrap_no_data_interval_is_drawn_and_the_caption_says_so(self):
        self.assertEqual(gid_artists(self.figure, r".*/data_interval"), [])
        self.assertIn("No data interval (no bootstrap over tubes).", PLOTTING.boxes.box_caption(Shared.results))

    def test_the_caption_is_outside_the_figure(self):
        # One title line naming the quantities; what the boxes mean is the caption's (captions.py).
        self.assertEqual(self.figure._suptitle.get_text(),
                         f"{Shared.results.campaign_name}: turgor pressure, wall modulus, wall viscosity, "
                         "growth rate (predicted) per line, 200 samples each")


class DataIntervals(unittest.TestCase):
    """A raw-data campaign (tests/campaign/data/raw_campaign.ini: the synthetic wild type from raw
    data with a 20-replicate bootstrap, pme48 from its line file): each box carries an error bar
    on its median spanning the data interval of results.h5's summary, and under the box the
    samples and, for the raw-data line, the tubes behind its laws (the n of its fits table)."""

    @classmethod
    def setUpClass(cls):
        text = (SOURCE / "tests" / "campaign" / "data" / "raw_campaign.ini").read_text()
        text = text.replace("= ../../../", f"= {SOURCE}/")
        text = re.sub(r"(?m)^outputs\s*=.*$", "outputs = p, E, eta, v, v_exp", text)
        campaign = Shared.tmp / "raw_campaign.ini"
        campaign.write_text(text)
        out = Shared.tmp / "raw"
        done = run([OPTIONS.cli, "run", campaign, "--out", out, "--quiet"])
        if done.returncode != 0:
            raise RuntimeError(f"growthuq run failed: {done.stderr}")
        cls.reference = Reference(out / "results.h5")
        with h5py.File(out / "results.h5", "r") as h5:
            cls.tubes = [int(n) for n in h5["lines/wild_type/fits"]["n"]]
        cls.results = PLOTTING.results.read_results(out / "results.h5")
        cls.figure = PLOTTING.boxes.box_figure(cls.results)
        cls.growth = PLOTTING.growth_rate.growth_rate_figure(cls.results)

    def test_the_growth_rate_shows_the_measured_tubes_and_the_data_intervals(self):
        # The tubes: the raw file's cells, read here with the csv module (not through results.h5).
        with open(SOURCE / "distributions" / "example_raw" / "wild_type" / "growth.csv", newline="") as handle:
            tubes = [float(row["v_exp_um_per_s"])
                     for row in csv.DictReader(text for text in handle if not text.startswith("#"))]
        points = one(self.growth, "wild_type/v_exp/tubes").get_offsets()
        self.assertEqual(len(points), len(tubes))
        self.assertTrue(close(points[:, 1], tubes))
        self.assertTrue(np.all(np.abs(points[:, 0] - (0 - 0.2)) <= 0.12 + 1e-12))
        self.assertGreater(len(set(np.round(points[:, 0], 9))), len(tubes) // 2)  # spread, not one column
        self.assertEqual(one(self.growth, "wild_type/growth/n").get_text(),
                         f"{len(tubes)} tubes\n{self.reference.counted('wild_type', 'v').size} samples")
        # pme48 comes from a line file: no tubes, a box of draws from its law.
        self.assertEqual(gid_artists(self.growth, r"pme48/v_exp/tubes"), [])
        assert_box(self, self.growth, "pme48/v_exp", percentiles(self.reference.counted("pme48", "v_exp")), 1 - 0.2)
        self.assertTrue(one(self.growth, "pme48/growth/n").get_text().startswith(
            f"{self.reference.counted('pme48', 'v_exp').size} draws\n"))
        for position, line in enumerate(self.reference.lines):
            for quantity, offset, bar in (("v_exp", -0.2, "v_exp_range"), ("v", 0.2, "v_range")):
                row = self.reference.summary[line, quantity]
                low, high = float(row["data_ci_low"]), float(row["data_ci_high"])
                self.assertTrue(low <= float(row["median"]) <= high and low < high, (line, quantity))
                (segment,) = one(self.growth, f"{line}/{quantity}/data_interval").get_segments()
                self.assertTrue(close(segment[:, 0], [position + offset] * 2, 1e-9), (line, quantity))
                self.assertTrue(close(sorted(segment[:, 1]), [low, high]), (line, quantity))
                # The medians' panel: the same intervals as bars.
                (drawn,) = one(self.growth, f"{line}/{bar}").get_segments()
                along = 0 if quantity == "v_exp" else 1
                self.assertTrue(close(sorted(drawn[:, along]), [low, high]), (line, quantity))
        self.assertEqual(self.growth.axes[1].get_title(), "medians\nbars: 95 % data intervals")

    def test_an_error_bar_on_each_median_spans_its_data_interval(self):
        reference = self.reference
        for position, line in enumerate(reference.lines):
            for quantity in EXPECTED_UNITS:
                key = f"{line}/{quantity}"
                row = reference.summary[line, quantity]
                low, high = float(row["data_ci_low"]), float(row["data_ci_high"])
                self.assertTrue(low < float(row["median"]) < high, key)  # computed, and around the median
                (segment,) = one(self.figure, f"{key}/data_interval").get_segments()
                self.assertTrue(close(segment[:, 0], [position, position], 1e-9), key)
                self.assertTrue(close(sorted(segment[:, 1]), [low, high]), key)
        legend = one(self.figure, "data_interval_legend")
        self.assertEqual([t.get_text() for t in legend.get_texts()],
                         ["median's 95 % data interval (bootstrap over tubes)"])
        caption = PLOTTING.boxes.box_caption(self.results)
        self.assertIn("Black bar: the median's 95 % data interval", caption)
        self.assertIn("Under a raw-data line's name: the tubes behind its laws", caption)

    def test_the_tubes_under_a_raw_data_lines_name_and_the_flagged_under_each_box(self):
        fewest, most = min(self.tubes), max(self.tubes)
        self.assertLess(fewest, most)
        for ax in self.figure.axes[:4]:
            self.assertEqual([t.get_text() for t in ax.get_xticklabels()],
                             [f"wild type\n{fewest}-{most} tubes", "pme48"])
        for line in self.reference.lines:
            for quantity in EXPECTED_UNITS:
                label = one(self.figure, f"{line}/{quantity}/n").get_text()
                flagged = 300 - self.reference.counted(line, quantity).size
                self.assertEqual(label, f"{flagged} flagged" if flagged else "", (line, quantity))


class ForceCurves(unittest.TestCase):
    """The force-curve figure of a real campaign: `growthuq synth` draws the wild type with two
    force curves per indented tube, its raw.ini takes k from them, `growthuq run` stores the
    processed curves in results.h5 and `tools/plot --figures force_curves` draws them. What was
    drawn is read back against results.h5 read here with h5py, and the window line against numpy's
    polyfit of the baselined points in the window (an independent fit of the same samples)."""

    @classmethod
    def setUpClass(cls):
        cls.directory = Shared.tmp / "force-curves"
        data = cls.directory / "data"
        done = run([OPTIONS.cli, "synth", SOURCE / "distributions" / "wild_type.ini", "--seed", 7, "--tubes", "12:12",
                    "--curves", "3:3", "--force-curves", 2, "--curve-samples", 300, "--out", data])
        if done.returncode != 0:
            raise RuntimeError(f"growthuq synth failed: {done.stderr}")
        campaign = cls.directory / "curves.ini"
        campaign.write_text("[campaign]\nname = curves\nseed = 3\nsamples = 100\noutputs = p, E\noutput_dir = out\n"
                            "formats = hdf5\n[instrument]\nprobe_radius_um = 0.5\n[line wild_type]\n"
                            f"raw = {data / 'wild_type' / 'raw.ini'}\nrank_correlation = none\n"
                            "[data_uncertainty]\nreplicates = 0\n")
        cls.out = cls.directory / "out"
        done = run([OPTIONS.cli, "run", campaign, "--out", cls.out, "--quiet"])
        if done.returncode != 0:
            raise RuntimeError(f"growthuq run failed: {done.stderr}")
        cls.plot_run = plot_command(cls.out, "--figures", "force_curves")
        with h5py.File(cls.out / "results.h5", "r") as h5:
            group = h5["lines/wild_type/force_curves"]
            cls.curves = group["curves"][()]
            cls.tubes = group["tubes"][()]
            cls.points = {name: group["points"][name][()] for name in ("curve_index", "z_um", "F_uN")}
        cls.figure = PLOTTING.force_curves.force_curves_figure(PLOTTING.results.read_results(cls.out / "results.h5"))

    def test_the_command_writes_the_figure(self):
        self.assertEqual(self.plot_run.returncode, 0, self.plot_run.stderr)
        assert_valid_png(self, self.out / "plots" / "force_curves.png")
        assert_valid_pdf(self, self.out / "plots" / "force_curves.pdf")
        self.assertIn("**force_curves**: Force-indentation curves", (self.out / "plots" / "captions.md").read_text())

    def test_curves_baseline_contact_window_and_window_line(self):
        curve_axes, tube_axes = self.figure.axes
        self.assertEqual((curve_axes.get_xlabel(), curve_axes.get_ylabel()), ("z (µm)", "F (µN)"))
        names = [as_text(n) for n in self.curves["curve"]]
        statuses = [as_text(n) for n in self.curves["status"]]
        tubes = [as_text(n) for n in self.curves["tube"]]
        drawn = [l.get_gid().split("/")[1] for l in curve_axes.lines if (l.get_gid() or "").endswith("/data")]
        # Ok curves of distinct tubes first, in file order.
        expected, seen = [], set()
        for name, status, tube in zip(names, statuses, tubes):
            if status == "ok" and tube not in seen:
                seen.add(tube)
                expected.append(name)
        self.assertEqual(drawn, expected[:3])
        for name in drawn:
            row = self.curves[names.index(name)]
            mine = self.points["curve_index"] == names.index(name)
            z, force = self.points["z_um"][mine], self.points["F_uN"][mine]
            data = one(self.figure, f"wild_type/{name}/data")
            self.assertTrue(np.array_equal(data.get_xdata(), z) and np.array_equal(data.get_ydata(), force), name)
            offset, tilt = row["baseline_offset_uN"], row["baseline_tilt_N_per_m"]
            baseline = one(self.figure, f"wild_type/{name}/baseline")
            self.assertTrue(close(baseline.get_ydata(), offset + tilt * np.asarray(baseline.get_xdata()), 1e-12))
            contact = one(self.figure, f"wild_type/{name}/contact")
            self.assertTrue(close(contact.get_xdata(), [row["contact_z_um"]]))
            self.assertTrue(close(contact.get_ydata(), [offset + tilt * row["contact_z_um"]], 1e-12))
            # The window line, refitted here: the baselined approach from contact to its maximum,
            # the samples whose force lies in [window_low, window_high], fitted by numpy's polyfit.
            above = force - (offset + tilt * z)
            start = int(np.argmax(z >= row["contact_z_um"]))
            peak = start + int(np.argmax(above[start:]))
            span = slice(start, peak + 1)
            inside = (above[span] >= row["window_low_uN"]) & (above[span] <= row["window_high_uN"])
            slope, intercept = np.polyfit(z[span][inside], above[span][inside], 1)
            self.assertTrue(close([slope], [row["k_m_N_per_m"]], 1e-9), name)
            fit = one(self.figure, f"wild_type/{name}/fit")
            x = np.asarray(fit.get_xdata())
            self.assertTrue(close(np.asarray(fit.get_ydata()) - (offset + tilt * x), intercept + slope * x, 1e-9), name)
            # It spans the window: its ends lie at the window's forces above the baseline.
            self.assertTrue(close(intercept + slope * x, [row["window_low_uN"], row["window_high_uN"]], 1e-9), name)
            self.assertGreaterEqual(x.min(), z[span][inside].min() - 0.05)
            self.assertLessEqual(x.max(), z[span][inside].max() + 0.05)
            window = one(self.figure, f"wild_type/{name}/window")
            self.assertTrue(close(sorted({float(v) for v in np.asarray(window.get_xy())[:, 0]}), x, 1e-12))

    def test_each_tube_k_with_its_95_percent_interval(self):
        tube_axes = self.figure.axes[1]
        self.assertEqual(tube_axes.get_ylabel(), "k (N/m)")
        ok = self.tubes[self.tubes["ok"] > 0]
        self.assertEqual(len(ok), 12)
        points = one(self.figure, "wild_type/tubes")
        self.assertTrue(close(points.get_ydata(), ok["k_N_per_m"]))
        segments = one(self.figure, "wild_type/tubes/interval").get_segments()
        self.assertTrue(close([s[0][1] for s in segments], ok["k_N_per_m"] - 1.959963984540054 * ok["u_N_per_m"], 1e-12))
        self.assertTrue(close([s[1][1] for s in segments], ok["k_N_per_m"] + 1.959963984540054 * ok["u_N_per_m"], 1e-12))
        self.assertEqual([t.get_text() for t in tube_axes.get_xticklabels()], [as_text(t) for t in ok["tube"]])
        # Each tube's k is the mean of its ok curves' k (Eq. (C10)).
        for tube in ok:
            mine = [as_text(t) == as_text(tube["tube"]) and as_text(s) == "ok"
                    for t, s in zip(self.curves["tube"], self.curves["status"])]
            self.assertTrue(close([np.mean(self.curves["k_N_per_m"][mine])], [tube["k_N_per_m"]], 1e-12))


class Letters(unittest.TestCase):
    """The compact letters of the line comparisons, over each box (tools/plotting/letters.py): a
    campaign of three raw-data lines with a 120-replicate bootstrap
    (tests/campaign/data/raw_comparisons.ini), its letters read back against letters.csv, and
    its results.h5 tables against the CSV files and against the intervals recomputed here with
    numpy from the stored replicate medians."""

    @classmethod
    def setUpClass(cls):
        cls.out = Shared.tmp / "comparisons"
        campaign = SOURCE / "tests" / "campaign" / "data" / "raw_comparisons.ini"
        done = run([OPTIONS.cli, "run", campaign, "--out", cls.out, "--quiet"])
        if done.returncode != 0:
            raise RuntimeError(f"growthuq run failed: {done.stderr}")
        cls.results = PLOTTING.results.read_results(cls.out / "results.h5")
        cls.figure = PLOTTING.boxes.box_figure(cls.results)
        FigureCanvasAgg(cls.figure)
        cls.figure.draw_without_rendering()  # the constrained layout, so extents are final
        with open(cls.out / "letters.csv", newline="") as handle:
            cls.letters = {(r["line"], r["quantity"]): r["letters"] for r in csv.DictReader(handle)}
        with open(cls.out / "comparisons.csv", newline="") as handle:
            cls.pairs = list(csv.DictReader(handle))

    def test_each_box_carries_its_letters_just_above_its_upper_whisker(self):
        reference = Reference(self.out / "results.h5")
        self.assertEqual(len(self.letters), 3 * 4)
        for (line, quantity), letters in self.letters.items():
            key = f"{line}/{quantity}"
            text = one(self.figure, f"{key}/letters")
            self.assertEqual(text.get_text(), letters, key)
            p90 = np.percentile(reference.counted(line, quantity), 90)
            x, y = text.get_position()
            self.assertTrue(close([x, y], [reference.lines.index(line), p90]), key)
            ax = text.axes
            whisker_top = ax.transData.transform((x, p90))[1]
            extent = text.get_window_extent()
            self.assertGreater(extent.y0, whisker_top, key)             # above the whisker
            self.assertLessEqual(extent.y1, ax.get_window_extent().y1, key)  # inside the panel
        self.assertIn("Letters: lines sharing a letter are not distinguishable",
                      PLOTTING.boxes.box_caption(self.results))

    def test_a_letters_table_without_its_members_is_one_line_naming_it(self):
        broken = Shared.tmp / "broken-letters"
        broken.mkdir(exist_ok=True)
        shutil.copy(self.out / "results.h5", broken)
        with h5py.File(broken / "results.h5", "a") as h5:
            del h5["line_letters"]
            h5["line_letters"] = np.array([(b"wild_type",)], dtype=[("line", "S16")])
        user_error(self, plot_command(broken, "--figures", "boxes"), broken / "results.h5",
                   "/line_letters: no member quantity", "expected a table with members quantity, line, letters")

    def test_no_letters_without_line_comparisons(self):
        self.assertEqual(Shared.results.letters, {})
        self.assertEqual(gid_artists(PLOTTING.boxes.box_figure(Shared.results), r".*/letters"), [])

    def test_results_h5_tables_equal_the_csv_files_and_numpy_percentiles_of_the_replicates(self):
        with h5py.File(self.out / "results.h5", "r") as h5:
            table = h5["line_comparisons"][()]
            self.assertIn("Bonferroni", str(h5["line_comparisons"].attrs["method"]))
            stored_letters = {(as_text(r["line"]), as_text(r["quantity"])): as_text(r["letters"])
                              for r in h5["line_letters"][()]}
            replicates = {(line, q): h5[f"lines/{line}/data_uncertainty_replicates/{q}"][()]
                          for line in ("wild_type", "xeg113", "pme48") for q in EXPECTED_UNITS}
        self.assertEqual(stored_letters, self.letters)
        self.assertEqual(len(table), len(self.pairs))
        checked = 0
        for row, csv_row in zip(table, self.pairs):
            for name in ("quantity", "unit", "line_a", "line_b", "differs", "note"):
                self.assertEqual(as_text(row[name]), csv_row[name], name)
            for name in ("ratio", "data_ci_low", "data_ci_high", "adjusted_ci_low", "adjusted_ci_high",
                         "adjusted_level"):
                self.assertEqual(float(row[name]), float(csv_row[name]), name)  # exact round trip
            self.assertEqual(int(row["replicates"]), int(csv_row["replicates"]))
            a = replicates[csv_row["line_a"], csv_row["quantity"]]
            b = replicates[csv_row["line_b"], csv_row["quantity"]]
            if a.size != 120 or b.size != 120:
                continue  # a replicate without a median: the arrays no longer pair by position
            tail = 100 * 0.05 / 6  # Bonferroni over 3 pairs, two-sided
            # Hyndman and Fan type 6, order statistic (B + 1) p: numpy's "weibull" method
            expected = np.percentile(a / b, [2.5, 97.5, tail, 100 - tail], method="weibull")
            drawn = [float(csv_row[n]) for n in ("data_ci_low", "data_ci_high", "adjusted_ci_low", "adjusted_ci_high")]
            self.assertTrue(close(drawn, expected, 1e-12), (csv_row, expected))
            excludes_one = expected[2] > 1 or expected[3] < 1
            self.assertEqual(csv_row["differs"], "yes" if excludes_one else "no")
            checked += 1
        self.assertGreaterEqual(checked, 9)


class GrowthRate(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.figure = PLOTTING.growth_rate.growth_rate_figure(Shared.results)

    def test_medians_and_10_90_ranges_of_measured_and_predicted_rates(self):
        # Line files only and no bootstrap: the measured side is draws from each v_exp law (no
        # tubes), and the bars are the 10-90 % ranges (no data interval to draw).
        reference = Shared.reference
        for line in reference.lines:
            measured = percentiles(reference.counted(line, "v_exp"))
            predicted = percentiles(reference.counted(line, "v"))
            point = one(self.figure, f"{line}/median_point")
            self.assertTrue(close(point.get_xdata(), [measured["median"]]), line)
            self.assertTrue(close(point.get_ydata(), [predicted["median"]]), line)
            (horizontal,) = one(self.figure, f"{line}/v_exp_range").get_segments()
            self.assertTrue(close(sorted(horizontal[:, 0]), [measured["p10"], measured["p90"]]), line)
            (vertical,) = one(self.figure, f"{line}/v_range").get_segments()
            self.assertTrue(close(sorted(vertical[:, 1]), [predicted["p10"], predicted["p90"]]), line)
            position = Shared.reference.lines.index(line)
            assert_box(self, self.figure, f"{line}/v_exp", measured, position - 0.2)
            assert_box(self, self.figure, f"{line}/v", predicted, position + 0.2)
            # The measured box is draws from the fitted law, counted as such, not as tubes.
            self.assertEqual(one(self.figure, f"{line}/growth/n").get_text(),
                             f"{reference.counted(line, 'v_exp').size} draws\n"
                             f"{reference.counted(line, 'v').size} samples")
        self.assertEqual(gid_artists(self.figure, r".*/(tubes|data_interval)"), [])
        self.assertEqual(self.figure.axes[1].get_title(), "medians\nbars: 10-90 % ranges")

    def test_labels_units_and_the_calibration_note_in_the_caption(self):
        boxes, scatter = self.figure.axes[:2]
        self.assertEqual(boxes.get_ylabel(), "v (µm/s)")
        self.assertEqual(scatter.get_xlabel(), "measured v_exp (µm/s)")
        self.assertEqual(scatter.get_ylabel(), "predicted v (µm/s)")
        self.assertEqual([t.get_text() for t in boxes.get_xticklabels()], [display(l) for l in Shared.reference.lines])
        drawn = [p for p in boxes.patches if p.get_gid().endswith("/box")]
        self.assertEqual(len(drawn), 2 * len(Shared.reference.lines))
        self.assertEqual(self.figure._suptitle.get_text(), "quick: growth rate, measured and predicted")
        caption = PLOTTING.captions.caption("growth_rate", Shared.results)
        self.assertIn(f"kappa = {Shared.reference.kappa:.4g} is calibrated on wild type", caption)
        self.assertIn("by construction", caption)
        self.assertIn("hatched box: draws from a line file's v_exp law", caption)
        one_to_one = one(self.figure, "one_to_one")
        self.assertTrue(np.array_equal(one_to_one.get_xdata(), one_to_one.get_ydata()))


class YieldPressure(unittest.TestCase):
    """With a yield pressure many tubes do not grow (status no_growth, v = 0): their p, E and eta
    were computed before the growth model flagged them, so growthuq's summary counts them in p,
    E and eta as in v (as 0); the plots must do the same."""

    @classmethod
    def setUpClass(cls):
        campaign = write_campaign(Shared.tmp, yield_pressure_MPa=0.2)
        out = Shared.tmp / "yield"
        done = run([OPTIONS.cli, "run", campaign, "--samples", 200, "--lines", "wild_type,pme48",
                    "--out", out, "--quiet"])
        if done.returncode != 0:
            raise RuntimeError(f"growthuq run failed: {done.stderr}")
        cls.reference = Reference(out / "results.h5")
        cls.results = PLOTTING.results.read_results(out / "results.h5")

    def test_no_growth_samples_count_in_every_quantity(self):
        reference = self.reference
        no_growth = {line: int((reference.status[line] == "no_growth").sum()) for line in reference.lines}
        self.assertGreater(no_growth["pme48"], 50)   # pme48's median turgor is below 0.2 MPa
        boxes = PLOTTING.boxes.box_figure(self.results)
        growth = PLOTTING.growth_rate.growth_rate_figure(self.results)
        for line in reference.lines:
            ok = int((reference.status[line] == "ok").sum())
            for quantity, n in (("p", ok + no_growth[line]), ("eta", ok + no_growth[line]), ("v", ok + no_growth[line])):
                label = one(boxes, f"{line}/{quantity}/n").get_text()
                self.assertEqual(label, f"{200 - n} flagged" if n < 200 else "", (line, quantity))
            v = reference.counted(line, "v")
            self.assertEqual(int((v == 0).sum()), no_growth[line])
            expected = percentiles(v)
            assert_box(self, boxes, f"{line}/v", expected, reference.lines.index(line))
            self.assertTrue(close(one(growth, f"{line}/median_point").get_ydata(), [expected["median"]]))


def tick_map(ticks, values, positions, coordinate):
    """The map from data value to drawn position (x: coordinate 0, y: 1) that the tick labels
    state (linear, or linear in log10), checked to also place `values` exactly at `positions`;
    None when neither fits."""
    tick_values = np.array([float(t.get_text()) for t in ticks])
    tick_positions = np.array([t.xy[coordinate] for t in ticks])
    for transform in (lambda x: np.asarray(x, dtype=float), np.log10):
        if transform is np.log10 and (tick_values.min() <= 0 or values.min() <= 0):
            continue
        slope, offset = np.polyfit(transform(tick_values), tick_positions, 1)
        if not np.allclose(slope * transform(tick_values) + offset, tick_positions, rtol=0, atol=1e-9):
            continue
        if np.allclose(slope * transform(values) + offset, positions, rtol=0, atol=1e-9):
            return lambda x, s=slope, o=offset, f=transform: s * f(x) + o
    return None


class Correlogram(unittest.TestCase):

    def test_k_by_k_cells_spearman_above_scatter_below_histograms_on_the_diagonal(self):
        reference = Shared.reference
        for line_index, line in enumerate(reference.lines):
            with self.subTest(line=line):
                figure = PLOTTING.correlogram.correlogram_figure(
                    Shared.results, Shared.results.lines[line_index])
                self.check_line(figure, line)

    def check_line(self, figure, line):
        reference = Shared.reference
        names = reference.analysis[line]["rows"]           # the engine's inputs then outputs
        k = len(names)
        ok = reference.status[line] == "ok"
        data = {name: reference.columns[line, name][ok] for name in names}
        cells = gid_artists(figure, r"cell/.*")
        self.assertEqual(len(cells), k * k)
        self.assertEqual({c.get_gid() for c in cells}, {f"cell/{a}/{b}" for a in names for b in names})
        (ax,) = figure.axes
        x_ticks = {j: [t for t in ax.texts if t.get_gid() == f"xtick/{j}"] for j in range(k)}
        y_ticks = {i: [t for t in ax.texts if t.get_gid() == f"ytick/{i}"] for i in range(k)}
        for j, name in enumerate(names):
            attrs = reference.attrs[line, name]
            label = f"{attrs['quantity']}\n({TYPESET[attrs['unit']]})"  # the unit under the symbol
            self.assertEqual(one(figure, f"xlabel/{j}").get_text(), label)
            self.assertEqual(one(figure, f"ylabel/{j}").get_text(), label)
        for i, row_name in enumerate(names):
            for j, column_name in enumerate(names):
                key = f"{row_name}/{column_name}"
                cell = one(figure, f"cell/{key}")
                self.assertEqual((cell.get_x(), cell.get_y()), (j, k - 1 - i), key)
                if i < j:
                    text = one(figure, f"spearman/{key}")
                    rho = spearmanr(data[row_name], data[column_name]).statistic
                    self.assertLessEqual(abs(float(text.get_text()) - rho), 0.005 + 1e-12, key)
                    x, y = text.get_position()
                    self.assertTrue(j < x < j + 1 and k - 1 - i < y < k - i, key)
                elif i > j:
                    points = one(figure, f"scatter/{key}").get_offsets()
                    self.assertEqual(len(points), data[row_name].size)
                    self.assertIsNotNone(tick_map(x_ticks[j], data[column_name], points[:, 0], 0),
                                         f"{key}: x positions are not the data at the tick labels' scale")
                    self.assertIsNotNone(tick_map(y_ticks[i], data[row_name], points[:, 1], 1),
                                         f"{key}: y positions are not the data at the tick labels' scale")
                else:
                    self.check_histogram(one(figure, f"histogram/{key}"), x_ticks[j],
                                         data[row_name], i, k, key)
        # The engine's stored input x output coefficients agree with scipy's on the same samples.
        stored = reference.analysis[line]
        for r, row_name in enumerate(stored["io_rows"]):
            for c, column_name in enumerate(stored["io_columns"]):
                rho = spearmanr(data[row_name], data[column_name]).statistic
                self.assertAlmostEqual(stored["io"][r, c], rho, delta=1e-9)

    def check_histogram(self, stairs, ticks, values, i, k, key):
        """Bar heights proportional to the number of samples in each bin, where the bins are read
        off the drawing through the tick labels' scale (linear or log10: with two ticks both fit
        the labels, and only the right one fits the bars)."""
        heights, edges, baseline = stairs.get_data()
        self.assertEqual(baseline, k - 1 - i, key)
        drawn = (heights - baseline) / (heights - baseline).max()
        tick_values = np.array([float(t.get_text()) for t in ticks])
        tick_positions = np.array([t.xy[0] for t in ticks])
        matched = False
        for forward, inverse in ((lambda x: x, lambda x: x), (np.log10, lambda x: 10 ** x)):
            if forward is np.log10 and tick_values.min() <= 0:
                continue
            slope, offset = np.polyfit(forward(tick_values), tick_positions, 1)
            if not np.allclose(slope * forward(tick_values) + offset, tick_positions, atol=1e-9):
                continue
            counts, _ = np.histogram(values, bins=inverse((edges - offset) / slope))
            matched |= counts.sum() == values.size and np.allclose(drawn, counts / counts.max(), atol=1e-9)
        self.assertTrue(matched, f"{key}: bar heights are not the sample counts of their bins")


class PrincipalComponents(unittest.TestCase):

    def test_bars_are_the_stored_explained_variance(self):
        figure = PLOTTING.pca.pca_figure(Shared.results)
        for line in Shared.reference.lines:
            ratio = Shared.reference.analysis[line]["ratio"]
            bars = [one(figure, f"{line}/PC{c}") for c in range(1, ratio.size + 1)]
            self.assertTrue(close([bar.get_height() for bar in bars], 100 * ratio))
            self.assertTrue(close(one(figure, f"{line}/cumulative").get_ydata(), 100 * np.cumsum(ratio)))
        self.assertEqual(figure.axes[0].get_ylabel(), "explained variance (%)")
        self.assertEqual(len(figure.axes), len(Shared.reference.lines))


# The symbol a reader knows for each dataset name of the sensitivity table (einf in the line
# files' unit, %, although the sampled column is einf_frac).
SYMBOLS = {"k_N_per_m": "k", "h_nm": "h", "d_um": "d", "d0_um": "d0", "tau_s": "tau", "einf_pct": "einf",
           "einf_frac": "einf", "v_exp_um_per_s": "v_exp", "p_MPa": "p", "E_MPa": "E", "eta_MPa_s": "eta",
           "v_um_per_s": "v"}


class Sensitivity(unittest.TestCase):

    def test_bars_and_intervals_are_the_stored_indices(self):
        figure = PLOTTING.sensitivity.sensitivity_figure(Shared.results)
        with h5py.File(Shared.results_dir / "results.h5") as h5:
            table = h5["sensitivity"][()]
        self.assertGreater(len(table), 0)
        for row in table:
            line, output, input_ = (as_text(row[name]) for name in ("line", "output", "input"))
            bar = one(figure, f"{line}/{output}/{input_}")
            self.assertTrue(close([bar.get_width()], [row["index"]]))
            # The bar's row is labelled with the symbols, "p ← k", not the dataset names p_MPa, k_N_per_m.
            ax = bar.axes
            labels = {round(y): label.get_text() for y, label in zip(ax.get_yticks(), ax.get_yticklabels())}
            self.assertEqual(labels[round(bar.get_y() + bar.get_height() / 2)],
                             f"{SYMBOLS[output]} ← {SYMBOLS[input_]}")
        self.assertEqual(len(figure.axes), len(Shared.reference.lines))


# ---------------------------------------------------------------- FIXTURES: relaxation and trade

def relaxation_curve(t, einf, tau_fast, tau_slow, force_uN=5.0):
    """A two-term generalized Maxwell force decay F(t) = F0 (e_inf + a1 e^-t/tau1 + a2 e^-t/tau2)."""
    a_fast = 0.4 * (1 - einf)
    return force_uN * (einf + a_fast * np.exp(-t / tau_fast) + (1 - einf - a_fast) * np.exp(-t / tau_slow))


def add_relaxation_fixture(path, rng):
    """FIXTURE, not engine output: /lines/<line>/relaxation in the documented layout, for two
    lines - wild_type with a compound fit table (5 curves, 4 ok), pme48 with column datasets and a
    coded status (2 curves, 1 ok) - points in shuffled order, the ramp at t <= 0 without a fit.
    Returns {line: [(name, status, t, F, F_fit)]} and {curve name: (tau_fast_s, tau_slow_s)} as written."""
    written, times_of = {}, {}
    t = np.concatenate([np.linspace(-0.05, 0, 6), np.geomspace(0.01, 5.0, 120)])
    with h5py.File(path, "a") as h5:
        for line, statuses, layout in (("wild_type", ["ok", "ok", "fit_failed", "ok", "ok"], "compound"),
                                       ("pme48", ["fit_failed", "ok"], "columns")):
            curves, index, times, forces, fits, taus = [], [], [], [], [], []
            for row, status in enumerate(statuses):
                einf, tau_fast, tau_slow = 0.6 + 0.05 * row, 0.2 + 0.02 * row, 3.0 + 0.5 * row
                clean = relaxation_curve(np.maximum(t, 0), einf, tau_fast, tau_slow)
                measured = clean * (1 + 0.005 * rng.standard_normal(t.size))
                fit = np.where((t > 0) & (status == "ok"), clean, np.nan)
                name = f"{line}_{row:02d}"
                curves.append((name, status, t, measured, fit))
                index += [row] * t.size
                times.append(t)
                forces.append(measured)
                fits.append(fit)
                taus.append((tau_fast, tau_slow, einf))
                times_of[name] = (tau_fast, tau_slow)
            order = rng.permutation(len(index))
            group = h5.create_group(f"lines/{line}/relaxation")
            points = group.create_group("points")
            points["curve_index"] = np.array(index, dtype=np.int64)[order]
            points["t_s"] = np.concatenate(times)[order]
            points["F_uN"] = np.concatenate(forces)[order]
            points["F_fit_uN"] = np.concatenate(fits)[order]
            names = [c[0] for c in curves]
            if layout == "compound":
                string = h5py.string_dtype()
                cells = [(n, s, tf, ts, e, 40.0) for n, s, (tf, ts, e) in zip(names, statuses, taus)]
                table = np.array(cells, dtype=[("curve", string), ("status", string), ("tau_fast_s", float),
                                  ("tau_slow_s", float), ("einf_frac", float), ("Er0_MPa", float)])
                group["fits"] = table
            else:
                codes = ["ok", "fit_failed"]
                group["curve"] = np.array(names, dtype=h5py.string_dtype())
                group["status"] = np.array([codes.index(s) for s in statuses], dtype=np.uint8)
                group["status"].attrs["names"] = codes
                group["tau_fast_s"] = np.array([x[0] for x in taus])
                group["tau_slow_s"] = np.array([x[1] for x in taus])
                group["einf_frac"] = np.array([x[2] for x in taus])
            written[line] = curves
    return written, times_of


TRADE_HEADER = ("fidelity,samples,seconds,line,quantity,unit,n,median,iqr,median_ci_low,"
                "median_ci_high,reference_median,reference_iqr,median_error_pct,iqr_error_pct,"
                "median_error_over_ci_half_width,fe_reference_median,fe_reference_iqr,"
                "fe_median_error_pct,fe_iqr_error_pct")


TRADE_COUNTS = (100, 300, 1000)


def run_real_tradeoff(directory):
    """tradeoff.csv written by the real `growthuq tradeoff` on the test campaign at small counts
    (the largest, 1000, is the reference), read back independently with the csv module."""
    campaign = write_campaign(directory)
    path = directory / "tradeoff.csv"
    done = run([OPTIONS.cli, "tradeoff", campaign, "--samples-list", ",".join(map(str, TRADE_COUNTS)),
                "--out", path, "--quiet"])
    if done.returncode != 0:
        raise RuntimeError(f"growthuq tradeoff failed: {done.stderr}")
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    numbers = TRADE_HEADER.split(",")[6:]
    for row in rows:
        row["samples"] = int(row["samples"])
        row["seconds"] = float(row["seconds"])
        for column in numbers:
            row[column] = float(row[column]) if row[column] != "" else math.nan
    return rows


class RelaxationAndTrade(unittest.TestCase):
    """On a copy of the campaign output with the relaxation FIXTURE added and a real tradeoff.csv."""

    @classmethod
    def setUpClass(cls):
        rng = np.random.default_rng(5)
        cls.directory = Shared.tmp / "with-fixtures"
        cls.directory.mkdir()
        shutil.copy(Shared.results_dir / "results.h5", cls.directory)
        cls.curves, cls.relaxation_times = add_relaxation_fixture(cls.directory / "results.h5", rng)
        cls.trade = run_real_tradeoff(cls.directory)
        cls.plot_run = plot_command(cls.directory, "--figures", "relaxation,tradeoff")
        cls.results = PLOTTING.results.read_results(cls.directory / "results.h5")

    def test_the_command_writes_both_figures(self):
        self.assertEqual(self.plot_run.returncode, 0, self.plot_run.stderr)
        for stem in ("relaxation", "tradeoff"):
            assert_valid_png(self, self.directory / "plots" / f"{stem}.png")
            assert_valid_pdf(self, self.directory / "plots" / f"{stem}.pdf")
        self.assertNotIn("skipped", self.plot_run.stdout)

    def test_relaxation_fits_the_page_with_text_of_6_5_pt_or_more(self):
        assert_print_size(self, PLOTTING.relaxation.relaxation_figure(self.results), "relaxation")

    def test_relaxation_panels_show_the_curves_and_their_fits(self):
        figure = PLOTTING.relaxation.relaxation_figure(self.results)
        self.assertEqual(len(figure.axes), 4)  # per line the forces over their residuals
        for ax, residual_ax, line in zip(figure.axes[0::2], figure.axes[1::2], ("wild_type", "pme48")):
            self.assertEqual((ax.get_ylabel(), ax.get_xscale()), ("F (µN)", "log"))
            self.assertEqual((residual_ax.get_xlabel(), residual_ax.get_ylabel(), residual_ax.get_xscale()),
                             ("t (s)", "F - F_fit (µN)", "log"))
            curves = self.curves[line]
            expected = ([c for c in curves if c[1] == "ok"] + [c for c in curves if c[1] != "ok"])[:4]
            drawn = [l.get_gid().split("/")[1] for l in ax.lines if l.get_gid().endswith("/data")]
            self.assertEqual(drawn, [c[0] for c in expected])
            self.assertIn(f"{len(expected)} of {len(curves)} curves", ax.get_title())
            self.assertIn(f"{sum(c[1] == 'ok' for c in curves)} fitted", ax.get_title())
            for name, status, t, measured, fit in expected:
                data = one(figure, f"{line}/{name}/data")
                after = t > 0
                self.assertTrue(np.array_equal(data.get_xdata(), t[after]))
                self.assertTrue(np.array_equal(data.get_ydata(), measured[after]))
                fitted = one(figure, f"{line}/{name}/fit")
                self.assertTrue(np.array_equal(fitted.get_ydata(), fit[after & np.isfinite(fit)]))
                self.assertEqual(fitted.get_xdata().size, 0 if status != "ok" else after.sum())
                residual = one(figure, f"{line}/{name}/residual")
                self.assertIs(residual.axes, residual_ax)
                with_fit = after & np.isfinite(fit)
                self.assertTrue(np.array_equal(residual.get_xdata(), t[with_fit]))
                self.assertTrue(close(residual.get_ydata(), measured[with_fit] - fit[with_fit]))
                self.assertEqual(mcolors.to_rgb(fitted.get_color()), mcolors.to_rgb(data.get_color()))
            # Curves of one line told apart: hues at least 0.3 apart in RGB (shades of one light
            # line colour were about 0.1 apart), and a marker each.
            data = [l for l in ax.lines if l.get_gid().endswith("/data")]
            hues = [np.array(mcolors.to_rgb(l.get_color())) for l in data]
            for a in range(len(hues)):
                for b in range(a + 1, len(hues)):
                    self.assertGreater(np.linalg.norm(hues[a] - hues[b]), 0.3, (line, a, b))
            self.assertEqual(len({l.get_marker() for l in data}), len(data))
            # The legend's title says which time is which; each entry gives the curve's fit.
            legend = ax.get_legend()
            self.assertEqual(legend.get_title().get_text(), "tau: fast, slow")
            entries = [t.get_text() for t in legend.get_texts()]
            expected_entries = [f"{name}: {self.relaxation_times[name][0]:.2g} s, {self.relaxation_times[name][1]:.2g} s"
                                if status == "ok" else f"{name} ({status})" for name, status, *_ in expected]
            self.assertEqual(entries, expected_entries)

    def test_trade_panels_show_ci_half_widths_median_errors_the_target_and_time(self):
        rows = PLOTTING.tradeoff_data.read_tradeoff(self.directory / "tradeoff.csv")
        figure = PLOTTING.tradeoff.tradeoff_figure(rows, "quick", Shared.reference.lines, target_pct=2.5)
        panels = figure.axes
        quantities = ["p", "E", "eta", "v", "v_exp"]
        long = ["turgor pressure", "wall modulus", "wall viscosity", "growth rate (predicted)",
                "growth rate (measured)"]
        # A percentage axis is labelled as one, not with the quantity's unit.
        self.assertEqual([ax.get_title() for ax in panels],
                         [f"{q}: {name}" for q, name in zip(quantities, long)] + ["time of the run (all lines)"])
        for ax in panels:
            self.assertEqual((ax.get_xscale(), ax.get_yscale()), ("log", "log"))
            self.assertEqual(ax.get_xlabel(), "samples per line")
        self.assertEqual({ax.get_ylabel() for ax in panels[:-1]}, {"% of the median"})
        self.assertEqual(panels[-1].get_ylabel(), "wall time (s)")
        legend = one(figure, "trade_legend")
        self.assertEqual([t.get_text() for t in legend.get_texts()],
                         [display(l) for l in Shared.reference.lines]
                         + ["95 % CI half-width of the median", "|median error| against the largest run",
                            "target 2.5 %"])
        # One coloured line per plant line (and only the CI half-widths are lines): 5 per panel.
        for ax, quantity in zip(panels, quantities):
            ci_lines = [l for l in ax.lines if l.get_gid().endswith("/ci")]
            self.assertEqual(len(ci_lines), len(Shared.reference.lines))
            colours = {mcolors.to_hex(l.get_color()) for l in ci_lines}
            self.assertEqual(len(colours), len(ci_lines))
            self.assertTrue(all(l.get_linestyle() == "None" for l in ax.lines if l.get_gid().endswith("/median")))
            target = one(figure, f"{quantity}/target")
            self.assertTrue(close(target.get_ydata(), [2.5, 2.5]))
        reference = max(TRADE_COUNTS)
        for line in Shared.reference.lines:
            for quantity in quantities:
                mine = [r for r in self.trade if r["line"] == line and r["quantity"] == quantity]
                self.assertEqual([r["samples"] for r in mine], list(TRADE_COUNTS))
                widths = [100 * (r["median_ci_high"] - r["median_ci_low"]) / 2 / abs(r["reference_median"])
                          for r in mine]
                drawn = one(figure, f"closed_form/{line}/{quantity}/ci")
                self.assertTrue(close(drawn.get_xdata(), TRADE_COUNTS), (line, quantity))
                self.assertTrue(close(drawn.get_ydata(), widths, 1e-9), (line, quantity))
                # The measured errors, the reference run excluded; a log axis cannot show an error
                # of exactly 0 (the reference line's v equals its measured median by the calibration).
                shown = [(r["samples"], abs(r["median_error_pct"])) for r in mine
                         if r["samples"] < reference and abs(r["median_error_pct"]) > 0]
                drawn = one(figure, f"closed_form/{line}/{quantity}/median")
                self.assertTrue(close(drawn.get_xdata(), [n for n, _ in shown]), (line, quantity))
                self.assertTrue(close(drawn.get_ydata(), [e for _, e in shown], 1e-9), (line, quantity))
        seconds = one(figure, "closed_form/seconds")
        by_count = {r["samples"]: r["seconds"] for r in self.trade}
        self.assertTrue(close(seconds.get_xdata(), list(TRADE_COUNTS)))
        self.assertTrue(close(seconds.get_ydata(), [by_count[n] for n in TRADE_COUNTS]))

    def test_the_trade_plot_fits_the_page_with_text_of_6_5_pt_or_more(self):
        rows = PLOTTING.tradeoff_data.read_tradeoff(self.directory / "tradeoff.csv")
        assert_print_size(self, PLOTTING.tradeoff.tradeoff_figure(rows, "quick", Shared.reference.lines), "tradeoff")

    def test_the_target_option_of_the_command(self):
        drawn = plot_command(self.directory, "--figures", "tradeoff", "--formats", "png", "--target", "0.5%",
                             "--out", self.directory / "target")
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        assert_valid_png(self, self.directory / "target" / "tradeoff.png")
        refused = plot_command(self.directory, "--target", "-1")
        self.assertEqual(refused.returncode, 2)
        self.assertIn("argument --target: '-1': expected a percentage > 0", refused.stderr)


def assert_print_size(test, figure, name):
    """Readable at print size: the figure fits a journal page's text width (18 cm) and no text in it
    is smaller than 6.5 pt at that size (matplotlib sizes fonts in points of the figure as saved, so
    a figure printed at its own width prints them at that size)."""
    test.assertLessEqual(figure.get_figwidth(), 7.09, name)
    FigureCanvasAgg(figure)
    figure.draw_without_rendering()
    texts = [t for t in figure.findobj(lambda a: hasattr(a, "get_fontsize") and hasattr(a, "get_text"))
             if t.get_visible() and t.get_text().strip()]
    test.assertGreater(len(texts), 10, name)
    small = sorted({(t.get_fontsize(), t.get_text()) for t in texts if t.get_fontsize() < 6.5})
    test.assertEqual(small, [], name)


class PrintSize(unittest.TestCase):

    def test_boxes_growth_rate_and_correlogram_fit_the_page_with_text_of_6_5_pt_or_more(self):
        assert_print_size(self, PLOTTING.boxes.box_figure(Shared.results), "boxes")
        assert_print_size(self, PLOTTING.growth_rate.growth_rate_figure(Shared.results), "growth_rate")
        for line in Shared.results.lines:
            assert_print_size(self, PLOTTING.correlogram.correlogram_figure(Shared.results, line), line.name)

    def test_sensitivity_fits_the_page_with_text_of_6_5_pt_or_more(self):
        assert_print_size(self, PLOTTING.sensitivity.sensitivity_figure(Shared.results), "sensitivity")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, type=Path, help="the growthuq executable")
    parser.add_argument("--source-dir", required=True, type=Path, help="the checkout root")
    OPTIONS, rest = parser.parse_known_args()
    SOURCE = OPTIONS.source_dir.resolve()
    sys.dont_write_bytecode = True
    sys.path.insert(0, str(SOURCE / "tools"))
    import plotting.boxes
    import plotting.captions
    import plotting.correlogram
    import plotting.force_curves
    import plotting.growth_rate
    import plotting.pca
    import plotting.relaxation
    import plotting.results
    import plotting.sensitivity
    import plotting.tradeoff
    import plotting.tradeoff_data
    PLOTTING = plotting
    unittest.main(argv=[sys.argv[0], *rest], verbosity=2)
