"""The growthuq package end to end: a small campaign (a raw-data line and a line file, in an order
that is not alphabetical, einf in % in one and as a fraction in the other) run through the CLI,
its results loaded and checked against samples.csv and summary.csv, against xarray and h5py
reading results.h5 directly, and against pandas' own Spearman correlation; the CLI's errors
as Python exceptions; eval_tubes against the CLI's single-tube path.

Run by CTest (tests/python/CMakeLists.txt) with GROWTHUQ_CLI set to the CLI just built:
    GROWTHUQ_CLI=$PWD/build/release/growthuq PYTHONPATH=tools/python /usr/bin/python3 -m unittest discover -s tools/python/tests
"""
import hashlib
import json
import os
import re
import subprocess
import tempfile
import unittest
from pathlib import Path

import h5py
import numpy as np
import pandas as pd
import xarray as xr

import growthuq

REPOSITORY = Path(__file__).resolve().parents[3]
SAMPLES = 40

CAMPAIGN = """[campaign]
name = python_package
seed = 7
samples = 300
outputs = p, E, eta, v, v_exp
output_dir = results/default
formats = csv, hdf5

[instrument]
probe_radius_um = 0.5
poisson_ratio = 0.2

[growth]
yield_pressure_MPa = 0
reference_line = wild_type

[physics_correlation]
p_MPa = 0.1:0.8
E_MPa = 5:200
h_nm = 100:300
d0_um = 4:8
samples = 2000

# einf of the fitted line is a fraction (einf_frac), of wild_type.ini in % (einf_pct).
[line xxt1_xxt2]
raw = {repository}/distributions/example_raw/xxt1_xxt2/raw.ini

[line wild_type]
distributions = {repository}/distributions/wild_type.ini
rank_correlation = physics
"""


def in_campaign_order(csv, lines):
    """The rows of a CSV result reordered as the campaign lists its lines (the run, and so the
    CSV, begins with the reference line)."""
    rank = csv["line"].map({line: i for i, line in enumerate(lines)})
    return csv.iloc[rank.argsort(kind="stable")].reset_index(drop=True)


def numbers(series):
    return pd.to_numeric(series, errors="coerce").to_numpy(dtype=float)


class RunAndLoad(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.TemporaryDirectory(prefix="growthuq-python-")
        cls.work = Path(cls.scratch.name)
        cls.campaign = cls.work / "campaign.ini"
        cls.campaign.write_text(CAMPAIGN.format(repository=REPOSITORY))
        cls.results = growthuq.run(cls.campaign, cwd=cls.work, samples=SAMPLES, out="out")
        cls.out = cls.work / "out"
        csv = {name: pd.read_csv(cls.out / f"{name}.csv", keep_default_na=False, na_values=[""],
                                 float_precision="round_trip") for name in ("samples", "summary")}
        cls.run_order = list(dict.fromkeys(csv["summary"]["line"]))
        cls.samples_csv = in_campaign_order(csv["samples"], ["xxt1_xxt2", "wild_type"])
        cls.summary_csv = in_campaign_order(csv["summary"], ["xxt1_xxt2", "wild_type"])

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def test_lines_in_campaign_order(self):
        self.assertEqual(self.run_order, ["wild_type", "xxt1_xxt2"])  # the reference line runs first
        self.assertEqual(self.results.lines, ["xxt1_xxt2", "wild_type"])
        self.assertEqual(list(dict.fromkeys(self.results.summary["line"])), ["xxt1_xxt2", "wild_type"])
        self.assertEqual(list(self.results.samples["line"].cat.categories), ["xxt1_xxt2", "wild_type"])
        self.assertEqual(list(self.results.dataset["line"].values), ["xxt1_xxt2", "wild_type"])
        with h5py.File(self.out / "results.h5") as f:
            self.assertEqual(list(f["lines"]), ["xxt1_xxt2", "wild_type"])  # the groups list in it too

    def test_samples_are_those_of_samples_csv_with_one_einf_column(self):
        frame, csv = self.results.samples, self.samples_csv
        self.assertEqual(len(frame), 2 * SAMPLES)
        # samples.csv's columns, the two einf columns as one; line, sample, inputs, outputs, status.
        self.assertEqual(set(frame.columns), set(csv.columns) - {"einf_pct"})
        self.assertEqual(list(frame.columns[:2]), ["line", "sample"])
        self.assertEqual(frame.columns[-1], "status")
        roles = [self.results.dataset[c].attrs["role"] for c in frame.columns[2:-1]]
        self.assertEqual(roles, sorted(roles))  # "input" < "output"
        self.assertEqual(list(frame["line"].astype(str)), list(csv["line"]))
        np.testing.assert_array_equal(frame["sample"], csv["sample"])
        self.assertEqual(list(frame["status"]), list(csv["status"]))
        # samples.csv keeps each line file's unit: two half-empty einf columns. The frame has one.
        self.assertNotIn("einf_pct", frame.columns)
        wild = (csv["line"] == "wild_type").to_numpy()
        np.testing.assert_array_equal(frame["einf_frac"][~wild], csv["einf_frac"][~wild])
        np.testing.assert_allclose(frame["einf_frac"][wild], csv["einf_pct"][wild] / 100, rtol=1e-15)
        self.assertFalse(frame["einf_frac"].isna().any())
        for column in ["k_N_per_m", "d_um", "d0_um", "h_nm", "tau_s", "v_exp_um_per_s", "p_MPa", "E_MPa",
                       "eta_MPa_s", "v_um_per_s"]:
            np.testing.assert_array_equal(frame[column].to_numpy(dtype=float), numbers(csv[column]), err_msg=column)
        self.assertEqual(frame.attrs["units"]["p_MPa"], "MPa")
        self.assertEqual(frame.attrs["units"]["einf_frac"], "frac")
        self.assertEqual(frame.attrs["units"]["eta_MPa_s"], "MPa s")

    def test_summary_is_summary_csv(self):
        frame, csv = self.results.summary, self.summary_csv
        self.assertEqual(list(frame.columns), list(csv.columns))
        for column in csv.columns:
            if csv[column].dtype == object:
                self.assertEqual(list(frame[column].astype(str)), list(csv[column]), column)
            else:
                np.testing.assert_array_equal(frame[column].to_numpy(dtype=float), csv[column].to_numpy(dtype=float),
                                              err_msg=column)
        self.assertEqual(list(frame["line"].cat.categories), self.results.lines)

    def test_dataset_has_named_dimensions_and_units(self):
        dataset = self.results.dataset
        self.assertEqual(dict(dataset.sizes), {"line": 2, "sample": SAMPLES, "quantity": 5, "statistic": 14})
        self.assertEqual(dataset["p_MPa"].dims, ("line", "sample"))
        self.assertEqual(dataset["p_MPa"].attrs["units"], "MPa")
        self.assertEqual(dataset["p_MPa"].attrs["long_name"], "turgor pressure")
        self.assertEqual(dataset["tau_s"].attrs["units"], "s")
        self.assertEqual(dataset.attrs["seed"], 7)
        # The mean of the ok samples is summary.csv's mean.
        ok = dataset["status"] == "ok"
        mean = float(dataset["E_MPa"].sel(line="wild_type").where(ok.sel(line="wild_type")).mean())
        row = self.summary_csv[(self.summary_csv["line"] == "wild_type") & (self.summary_csv["quantity"] == "E")]
        self.assertAlmostEqual(mean, float(row["mean"].iloc[0]), delta=1e-12 * abs(mean))

    def test_xarray_and_h5py_open_the_file_directly(self):
        path = self.out / "results.h5"
        line = xr.open_dataset(path, group="lines/wild_type", engine="h5netcdf")
        self.assertEqual(line["p_MPa"].dims, ("sample",))
        np.testing.assert_array_equal(line["p_MPa"].values, self.results.dataset["p_MPa"].sel(line="wild_type").values)
        analysis = xr.open_dataset(path, group="lines/wild_type/analysis", engine="h5netcdf")
        self.assertEqual(analysis["loadings"].dims, ("variable", "component"))
        self.assertIn("einf_frac", list(analysis["variable"].values))
        points = xr.open_dataset(path, group="lines/xxt1_xxt2/relaxation/points", engine="h5netcdf")
        self.assertEqual(points["F_uN"].dims, ("point",))
        self.assertEqual(points["F_uN"].attrs["units"], "uN")
        self.assertEqual(points["t_s"].attrs["units"], "s")
        with h5py.File(path) as f:
            self.assertIsInstance(f["lines/wild_type/p_MPa"].attrs["units"], str)
            self.assertIsInstance(f.attrs["campaign_text"], str)
            self.assertEqual(list(f.attrs["line_order"]), ["xxt1_xxt2", "wild_type"])

    def test_correlations_match_pandas_spearman(self):
        correlations = self.results.correlations
        frame = self.results.samples
        ok = frame[(frame["line"] == "wild_type") & (frame["status"] == "ok")]
        expected = ok["k_N_per_m"].corr(ok["p_MPa"], method="spearman")
        row = correlations[(correlations["line"] == "wild_type") & (correlations["matrix"] == "input_output")
                           & (correlations["row"] == "k_N_per_m") & (correlations["column"] == "p_MPa")]
        self.assertEqual(len(row), 1)
        self.assertAlmostEqual(float(row["spearman"].iloc[0]), expected, delta=1e-12)
        achieved = correlations[(correlations["matrix"] == "achieved") & (correlations["row"] == correlations["column"])]
        np.testing.assert_allclose(achieved["spearman"], 1.0, rtol=0, atol=1e-12)
        self.assertEqual(set(correlations[correlations["matrix"] == "target"]["line"]), {"wild_type"})

    def test_data_uncertainty_is_data_uncertainty_csv_and_no_comparison_of_one_raw_line(self):
        csv = pd.read_csv(self.out / "data_uncertainty.csv", float_precision="round_trip")
        assert_frame_is_csv(self, self.results.data_uncertainty, in_campaign_order(csv, self.results.lines))
        self.assertTrue(self.results.comparisons.empty)  # one line given by raw data: nothing to compare
        self.assertTrue(self.results.letters.empty)

    def test_provenance_is_provenance_json_and_names_the_campaign_file(self):
        stated = json.loads((self.out / "provenance.json").read_text())
        provenance = self.results.provenance
        for key in ("growthuq_version", "seed", "samples_per_line", "probe_radius_um", "campaign_sha256"):
            self.assertEqual(provenance[key], stated[key], key)
        self.assertEqual(provenance["campaign_sha256"], hashlib.sha256(self.campaign.read_bytes()).hexdigest())
        self.assertEqual(provenance["samples_per_line"], SAMPLES)
        self.assertEqual(sorted(provenance["lines"]), sorted(line["name"] for line in stated["lines"]))
        self.assertIn("Arnoldi", provenance["models"]["thin_shell_turgor"]["reference"])

    def test_sensitivity_is_sensitivity_csv(self):
        read = pd.read_csv(self.out / "sensitivity.csv", float_precision="round_trip")
        self.assertEqual(len(read), len(self.results.sensitivity))
        self.assertGreater(len(read), 0)
        assert_frame_is_csv(self, self.results.sensitivity, read)

    def test_fits_as_numbers(self):
        fits, parameters = self.results.fits, self.results.fit_parameters
        self.assertEqual(set(fits["line"]), {"xxt1_xxt2"})
        self.assertIn("k", list(fits["variable"]))
        chosen = parameters[(parameters["chosen"] == 1)]
        for _, fit in fits.iterrows():
            mine = chosen[chosen["variable"] == fit["variable"]]
            self.assertTrue((mine["family"] == fit["family"]).all())
            printed = ", ".join("%s=%.6g" % (p, v) for p, v in zip(mine["parameter"], mine["value"]))
            self.assertTrue(fit["parameters"].startswith(printed), (printed, fit["parameters"]))
        self.assertEqual(parameters["value"].dtype, np.float64)

    def test_long_frame_holds_every_value_of_samples_csv_once(self):
        long, csv = self.results.long, self.samples_csv
        self.assertEqual(list(long.columns), ["line", "sample", "quantity", "value", "unit"])
        dataset = self.results.dataset
        for column in self.results.samples.columns[2:-1]:
            quantity, unit = dataset[column].attrs["quantity"], dataset[column].attrs["units"]
            for line in self.results.lines:
                rows = long[(long["line"] == line) & (long["quantity"] == quantity)]
                self.assertEqual(set(rows["unit"]), {unit}, (line, column))
                # samples.csv keeps wild_type.ini's einf in %: the long frame has it as a fraction.
                source = "einf_pct" if column == "einf_frac" and line == "wild_type" else column
                scale = 0.01 if source == "einf_pct" else 1.0
                mine = csv[csv["line"] == line]
                values = numbers(mine[source]) * scale
                held = ~np.isnan(values)
                np.testing.assert_array_equal(rows["sample"].to_numpy(), mine["sample"].to_numpy()[held])
                np.testing.assert_allclose(rows["value"].to_numpy(), values[held], rtol=1e-15, err_msg=(line, column))
        # An output's rows are the values its summary row counts, with its median.
        summary = self.summary_csv
        for _, row in summary.iterrows():
            values = long[(long["line"] == row["line"]) & (long["quantity"] == row["quantity"])]["value"]
            self.assertEqual(len(values), row["n"], (row["line"], row["quantity"]))
            self.assertAlmostEqual(values.median(), row["median"], delta=1e-12 * abs(row["median"]))

    def test_summary_in_the_dataset_is_summary_csv(self):
        summary = self.results.dataset["summary"]
        self.assertEqual(summary.dims, ("line", "quantity", "statistic"))
        for _, row in self.summary_csv.iterrows():
            cell = summary.sel(line=row["line"], quantity=row["quantity"])
            self.assertEqual(str(cell["unit"].values), row["unit"])
            for statistic in cell["statistic"].values:
                expected = float(row[statistic]) if row[statistic] != "" else np.nan
                np.testing.assert_array_equal(float(cell.sel(statistic=statistic)), expected,
                                              err_msg=(row["line"], row["quantity"], statistic))

    def test_bootstrap_replicates_give_the_data_intervals_of_data_uncertainty_csv(self):
        csv = pd.read_csv(self.out / "data_uncertainty.csv", float_precision="round_trip")
        replicates = self.results.replicates
        self.assertEqual(list(replicates.columns), ["line", "quantity", "replicate", "median", "unit"])
        for _, row in csv.iterrows():
            mine = replicates[(replicates["line"] == row["line"]) & (replicates["quantity"] == row["quantity"])]
            self.assertEqual(len(mine), row["replicates"])
            self.assertEqual(list(mine["replicate"]), list(range(row["replicates"])))
            self.assertEqual(set(mine["unit"]), {row["unit"]})
            medians = mine["median"].to_numpy()
            # The interval is the 2.5 and 97.5 % quantiles of the replicate medians, data_sd their sd.
            scale = abs(row["median"])
            self.assertAlmostEqual(np.quantile(medians, 0.025), row["data_ci_low"], delta=1e-12 * scale)
            self.assertAlmostEqual(np.quantile(medians, 0.975), row["data_ci_high"], delta=1e-12 * scale)
            self.assertAlmostEqual(np.std(medians, ddof=1), row["data_sd"], delta=1e-9 * scale)

    def test_principal_components_are_those_of_the_samples_correlation(self):
        loadings, explained = self.results.loadings, self.results.explained_variance
        for line in self.results.lines:
            mine = loadings[loadings["line"] == line]
            variables = list(dict.fromkeys(mine["variable"]))
            components = [f"PC{i + 1}" for i in range(len(variables))]
            matrix = mine.pivot(index="variable", columns="component", values="loading").loc[variables, components]
            ok = self.results.samples[(self.results.samples["line"] == line) & (self.results.samples["status"] == "ok")]
            values, vectors = np.linalg.eigh(np.corrcoef(ok[variables].to_numpy(dtype=float), rowvar=False))
            values, vectors = values[::-1], vectors[:, ::-1]
            ratios = explained[explained["line"] == line]
            self.assertEqual(list(ratios["component"]), components)
            np.testing.assert_allclose(ratios["explained_variance_ratio"], values / len(variables), atol=1e-12)
            # Each component up to its sign (the report's largest entry positive).
            overlap = np.abs(matrix.to_numpy().T @ vectors)
            np.testing.assert_allclose(overlap, np.eye(len(variables)), atol=1e-8, err_msg=line)

    def test_relaxation_points_are_the_curves_file_and_fits_count_them(self):
        curves = pd.read_csv(REPOSITORY / "distributions/example_raw/xxt1_xxt2/relaxation_curves.csv", comment="#",
                             float_precision="round_trip")
        points, fits = self.results.relaxation_points, self.results.relaxation_fits
        self.assertEqual(set(points["line"]), {"xxt1_xxt2"})
        self.assertEqual(list(points["curve"]), list(curves["curve"]))
        np.testing.assert_array_equal(points["t_s"], curves["t_s"])
        # Within an ulp: the force goes through SI units and back.
        np.testing.assert_allclose(points["F_uN"], curves["F_uN"], rtol=1e-15, atol=0)
        self.assertEqual(list(fits["curve"]), list(dict.fromkeys(curves["curve"])))
        self.assertEqual(points.attrs["units"]["F_uN"], "uN")
        fitted = points.groupby("curve_index")["F_fit_uN"].count()
        for index, fit in fits.iterrows():
            if fit["status"] != "fit_failed":
                self.assertEqual(fitted[index], fit["points"], fit["curve"])

    def test_fit_candidates_choose_the_least_aic_law_of_fits(self):
        candidates, fits = self.results.fit_candidates, self.results.fits
        for _, fit in fits.iterrows():
            tried = candidates[(candidates["variable"] == fit["variable"]) & (candidates["status"] == "ok")]
            best = tried.loc[tried["aic"].idxmin()]
            self.assertEqual(best["family"], fit["family"], fit["variable"])
            self.assertEqual(best["aic"], fit["aic"])
            np.testing.assert_allclose(tried["delta_aic"], tried["aic"] - best["aic"], atol=1e-9)

    def test_repr_is_short_and_names_what_the_results_hold(self):
        text = repr(self.results)
        self.assertLess(len(text), 1000)
        self.assertIn("2 lines x 40 samples, seed 7", text)
        self.assertIn("xxt1_xxt2, wild_type", text)
        self.assertIn(f"relaxation_points {len(self.results.relaxation_points)}x6", text)
        self.assertIn(f"replicates {len(self.results.replicates)}x5", text)
        self.assertNotIn("comparisons", text)  # empty here

    def test_the_report_prints_fixed_for_a_median_the_bootstrap_does_not_move(self):
        csv = pd.read_csv(self.out / "data_uncertainty.csv", float_precision="round_trip")
        report = self.results.report
        # The summary table (above the line saying what its intervals are) and the data-uncertainty
        # table of the bootstrap's section: the interval is the column after the median in both.
        tables = {"summary": report[:report.index("\ndata 95 % interval: ")],
                  "data uncertainty": report[report.index("\ndata uncertainty of the medians"):]}
        for name, table in tables.items():
            rows = {(line, quantity): text for line, quantity, text in
                    re.findall(r"^(\S+)\s+(\S+)\s+\S+(?: \S+)?\s+\S+\s+(fixed|\[[^]]+\])", table, re.MULTILINE)}
            self.assertEqual(len(rows), len(csv), name)
            for _, row in csv.iterrows():
                width = row["data_ci_high"] - row["data_ci_low"]
                text = rows[(row["line"], row["quantity"])]
                if width <= 1e-12 * abs(row["data_ci_high"]):
                    self.assertEqual(text, "fixed", (name, row["line"], row["quantity"]))
                else:
                    low, high = (float(x) for x in text.strip("[]").split(", "))
                    self.assertAlmostEqual(low, row["data_ci_low"], delta=1e-3 * abs(row["data_ci_low"]))
                    self.assertAlmostEqual(high, row["data_ci_high"], delta=1e-3 * abs(row["data_ci_high"]))
            # The reference line's v is calibrated to its published (fixed) v_exp median in every replicate.
            self.assertEqual(rows[("wild_type", "v")], "fixed", name)
        self.assertIn("fixed: the bootstrap does not move this median", report)

    def test_help_run_names_every_file_the_run_wrote(self):
        help_text = assert_help_run_names_the_files_in(self, self.out)
        for words in ("fidelity", "closed_form", "shell_fe", "data 95 % interval"):
            self.assertIn(words, help_text)

    def test_the_readme_figure(self):
        """The Python example of the package's README, run as written on these results."""
        readme = (REPOSITORY / "tools" / "python" / "README.md").read_text()
        code = readme.split("<!-- python-figure", 1)[1].split("```python\n", 1)[1].split("```", 1)[0]
        self.assertIn('growthuq.load("results/quick")', code)
        code = code.replace('"results/quick"', repr(str(self.out)))
        here = os.getcwd()
        os.chdir(self.work)
        try:
            namespace = {}
            exec(compile(code, "tools/python/README.md", "exec"), namespace)  # noqa: S102 - the README's own example
        finally:
            os.chdir(here)
        self.assertEqual((self.work / "turgor.png").read_bytes()[:8], b"\x89PNG\r\n\x1a\n")
        axes = namespace["ax"]
        self.assertEqual([label.get_text() for label in axes.get_xticklabels()], self.results.lines)
        self.assertEqual(axes.get_ylabel(), "turgor p [MPa]")

    def test_run_without_out_loads_the_campaigns_output_directory(self):
        results = growthuq.run(self.campaign, cwd=self.work, samples=5, lines=["wild_type"])
        self.assertEqual(results.path, self.work / "results" / "default" / "results.h5")
        self.assertEqual(results.lines, ["wild_type"])
        self.assertIn("campaign 'python_package'", results.report)

    def test_cli_errors_arrive_as_exceptions_with_its_message(self):
        with self.assertRaises(growthuq.CliError) as caught:
            growthuq.run(self.campaign, cwd=self.work, samples=0, out="never")
        self.assertIn("--samples = '0': expected a whole number", str(caught.exception))
        self.assertNotEqual(caught.exception.returncode, 0)
        self.assertFalse((self.work / "never").exists())
        with self.assertRaises(growthuq.CliError) as caught:
            growthuq.run(self.campaign, cwd=self.work, samples=5, out="out")  # exists: no silent overwrite
        self.assertIn("--force", str(caught.exception))

    def damaged_copy(self, name, damage):
        """A copy of the run's results.h5 in a folder of its own, `damage`d (a function of the path)."""
        folder = self.work / name
        folder.mkdir()
        copy = folder / "results.h5"
        copy.write_bytes((self.out / "results.h5").read_bytes())
        damage(copy)
        return copy

    def assert_load_names(self, path, *parts):
        with self.assertRaises(growthuq.ResultsError) as caught:
            growthuq.load(path)
        message = str(caught.exception)
        self.assertTrue(message.startswith(f"{path}: "), message)
        for part in parts:
            self.assertIn(part, message)

    def test_a_damaged_results_file_raises_results_error_naming_it_and_what_is_missing(self):
        def without(name):
            def damage(path):
                with h5py.File(path, "r+") as h5:
                    del h5[name]
            return damage

        self.assert_load_names(self.damaged_copy("no_summary", without("summary")), "no /summary (the summary table)")
        self.assert_load_names(self.damaged_copy("no_line", without("lines/wild_type")),
                               "no /lines/wild_type (the group of the line 'wild_type' that line_order lists)")

        def garble_header(name):
            def damage(path):
                # The object header of `name` overwritten: h5py raises KeyError ("bad object header
                # version number") when it is opened, deep inside the reading.
                with h5py.File(path, "r") as h5:
                    address = h5py.h5o.get_info(h5[name].id).addr
                with open(path, "r+b") as raw:
                    raw.seek(address)
                    raw.write(b"\xff" * 32)
            return damage

        self.assert_load_names(self.damaged_copy("garbled", garble_header("lines/wild_type/analysis/input_output_spearman")),
                               "cannot be read as growthuq's results", "bad object header")

        def garble_superblock(path):
            with open(path, "r+b") as raw:
                raw.write(b"\xff" * 64)

        self.assert_load_names(self.damaged_copy("no_superblock", garble_superblock), "not a readable HDF5 file")

        def truncate(path):
            size = path.stat().st_size
            with open(path, "r+b") as raw:
                raw.truncate(size // 2)  # the second half of the blocks gone

        self.assert_load_names(self.damaged_copy("truncated", truncate), "results.h5")

    def test_a_nul_in_an_argument_is_refused_naming_it(self):
        with self.assertRaises(ValueError) as caught:
            growthuq.run(self.campaign, cwd=self.work, samples=5, out="o\0x")
        self.assertIn("'o\\x00x' contains a NUL character", str(caught.exception))
        self.assertNotIn("embedded null byte", str(caught.exception))


class EvalTubes(unittest.TestCase):
    def test_frame_of_tubes_as_the_single_tube_path_gives(self):
        tubes = pd.DataFrame({"k_N_per_m": [2.87, 3.0], "d_um": [5.6, 9.0], "d0_um": [5.35, 3.0], "h_nm": [200, 200]},
                             index=["tube A", "tube B"])
        results = growthuq.eval_tubes(tubes, rho_um=0.5)
        self.assertEqual(list(results.index), ["tube A", "tube B"])
        self.assertEqual(list(results["status"]), ["ok", "beyond_membrane_limit"])
        self.assertTrue(np.isnan(results.loc["tube B", "p_MPa"]))
        single = subprocess.run([growthuq.find_cli(), "eval", "--k", "2.87", "--d-um", "5.6", "--d0-um", "5.35",
                                 "--h-nm", "200", "--rho-um", "0.5"], capture_output=True, text=True, check=True).stdout
        for quantity, column in [("p", "p_MPa"), ("E", "E_MPa"), ("alpha", "alpha_um")]:
            value = float(re.search(r"^\s+%s\s+(\S+)" % quantity, single, re.MULTILINE).group(1))
            self.assertEqual(results.loc["tube A", column], value, column)
        with_nu = growthuq.eval_tubes(tubes.iloc[:1], rho_um=0.5, nu=0.3)
        self.assertNotEqual(with_nu["p_MPa"].iloc[0], results["p_MPa"].iloc[0])  # the option reached the CLI

    def test_bad_tubes_raise_the_cli_message(self):
        with self.assertRaises(growthuq.CliError) as caught:
            growthuq.eval_tubes(pd.DataFrame({"k_N_per_m": [2.87], "d_um": [5.6]}), rho_um=0.5)
        self.assertIn("d0", str(caught.exception))
        self.assertIn("growthuq eval: error:", str(caught.exception))


class FindCli(unittest.TestCase):
    def test_argument_then_environment(self):
        self.assertEqual(growthuq.find_cli(os.environ["GROWTHUQ_CLI"]), os.environ["GROWTHUQ_CLI"])
        saved = os.environ["GROWTHUQ_CLI"]
        try:
            os.environ["GROWTHUQ_CLI"] = "/nonexistent/growthuq"
            with self.assertRaises(FileNotFoundError) as caught:
                growthuq.find_cli()
            self.assertIn("/nonexistent/growthuq: not an executable file", str(caught.exception))
            self.assertIn("GROWTHUQ_CLI", str(caught.exception))
            self.assertEqual(growthuq.find_cli(saved), saved)  # the argument comes first
        finally:
            os.environ["GROWTHUQ_CLI"] = saved

    def test_load_names_the_missing_file(self):
        with tempfile.TemporaryDirectory() as empty:
            with self.assertRaises(growthuq.ResultsError) as caught:
                growthuq.load(empty)
        self.assertIn("results.h5: no such file", str(caught.exception))



def assert_help_run_names_the_files_in(test, directory):
    """`growthuq help run` names every file of `directory`, a run's output; returns the help text
    (its words joined by single spaces)."""
    help_text = subprocess.run([growthuq.find_cli(), "help", "run"], capture_output=True, text=True, check=True).stdout
    for name in sorted(path.name for path in Path(directory).iterdir()):
        test.assertIn(name, help_text)
    return " ".join(help_text.split())


def assert_frame_is_csv(test, frame, csv):
    """Same columns, rows and values (text as text, numbers exactly, empty as NaN)."""
    test.assertEqual(list(frame.columns), list(csv.columns))
    test.assertEqual(len(frame), len(csv))
    for column in csv.columns:
        if frame[column].dtype == object or isinstance(frame[column].dtype, pd.CategoricalDtype):
            test.assertEqual(list(frame[column].astype(str)), list(csv[column].fillna("").astype(str)), column)
        else:
            np.testing.assert_array_equal(frame[column].to_numpy(dtype=float), csv[column].to_numpy(dtype=float),
                                          err_msg=column)


class LineComparisons(unittest.TestCase):
    """Two lines given by raw data, listed against the alphabet: the bootstrap's comparisons and
    letters as comparisons.csv and letters.csv hold them, line columns in the campaign's order."""

    def test_comparisons_and_letters_are_the_csvs(self):
        with tempfile.TemporaryDirectory(prefix="growthuq-python-") as scratch:
            work = Path(scratch)
            (work / "campaign.ini").write_text(f"""[campaign]
name = comparisons
seed = 11
samples = 40
outputs = p, E
output_dir = out
formats = csv, hdf5

[instrument]
probe_radius_um = 0.5

[data_uncertainty]
replicates = 30

[line xeg113]
raw = {REPOSITORY}/distributions/example_raw/xeg113/raw.ini

[line wild_type]
raw = {REPOSITORY}/distributions/example_raw/wild_type/raw.ini
""")
            results = growthuq.run(work / "campaign.ini", cwd=work)
            read = {name: pd.read_csv(work / "out" / f"{name}.csv", keep_default_na=False, na_values=[""],
                                      float_precision="round_trip")
                    for name in ("comparisons", "letters", "data_uncertainty")}
            self.assertGreater(len(read["comparisons"]), 0)
            assert_frame_is_csv(self, results.comparisons, read["comparisons"])
            assert_frame_is_csv(self, results.letters, read["letters"])
            assert_frame_is_csv(self, results.data_uncertainty, in_campaign_order(read["data_uncertainty"], results.lines))
            self.assertEqual(list(results.comparisons["line_a"].cat.categories), ["xeg113", "wild_type"])
            self.assertEqual(list(results.letters["line"].cat.categories), ["xeg113", "wild_type"])
            self.assertIn("letters.csv", [path.name for path in (work / "out").iterdir()])
            assert_help_run_names_the_files_in(self, work / "out")


if __name__ == "__main__":
    unittest.main()
