"""Reads a results.h5 written by test_results_h5.cpp with h5py and xarray, as users will, and
checks values, units, layout and named dimensions. Usage: check_results_h5.py FILE. Exits non-zero
with a message on a mismatch."""
import sys

import h5py
import numpy as np
import xarray as xr


def expect(condition, what):
    if not condition:
        sys.exit("mismatch: " + what)


with h5py.File(sys.argv[1], "r") as f:
    expect(f.attrs["campaign_path"] == "campaigns/test.ini", "campaign_path")
    expect(f.attrs["campaign_text"].endswith("# \u00b5m and a newline\n"), "campaign_text (UTF-8)")
    expect(int(f.attrs["seed"]) == 18446744073709551557, "seed")
    expect(f.attrs["kappa"] == 0.8125, "kappa")
    expect(f.attrs["engine_version"] == "0.1.0", "engine_version")
    # The campaign's order, not the alphabet: the attribute, and the group's own listing.
    expect(list(f.attrs["line_order"]) == ["xxt1 xxt2", "wild_type"], "line_order")
    expect(list(f["lines"].keys()) == ["xxt1 xxt2", "wild_type"], "line groups in campaign order")

    wt = f["lines/wild_type"]
    expect(wt["p_MPa"].attrs["unit"] == "MPa" and wt["p_MPa"].attrs["quantity"] == "p", "p unit")
    expect(wt["k_N_per_m"].attrs["unit"] == "N/m" and wt["k_N_per_m"].attrs["role"] == "input", "k unit")
    expect(wt["v_um_per_s"].attrs["unit"] == "um/s", "v unit")
    expect(wt["d0_um"].dtype == np.float64, "float64 columns")
    np.testing.assert_array_equal(wt["k_N_per_m"][:], [2.87, 3.1, 2.2, 4.05, 1.9, 2.5])
    np.testing.assert_array_equal(wt["p_MPa"][:], [0.31, np.nan, 0.22, 0.45, 0.18, 0.27])
    np.testing.assert_array_equal(wt["sample"][:], np.arange(6))
    # einf given in % is stored as a fraction under the one name of the quantity.
    expect("einf_pct" not in wt and wt["einf_frac"].attrs["units"] == "frac", "einf canonical")
    np.testing.assert_allclose(wt["einf_frac"][:], [0.65, 0.70, 0.55, 0.80, 0.60, 0.72], rtol=1e-15)
    names = list(wt["status"].attrs["names"])
    expect(names[:3] == ["ok", "invalid_input", "lambda_not_above_one"], "status names")
    expect([names[c] for c in wt["status"][:]] == ["ok", "burst", "no_growth", "ok", "ok", "ok"], "status codes")

    summary = wt["summary"][:]
    expect(summary.dtype.names[:5] == ("line", "quantity", "unit", "n", "n_flagged"), "summary columns")
    v = summary[summary["quantity"] == b"v"][0]
    # v over ok and no_growth: 0.028, 0.0, 0.041, 0.012, 0.02 -> median 0.02, n 5 (numpy agrees).
    expect(v["n"] == 5 and v["n_flagged"] == 1, "v counts")
    expect(v["median"] == np.median([0.028, 0.0, 0.041, 0.012, 0.02]), "v median")
    expect(v["unit"] == b"um/s", "v summary unit")
    expect(np.isnan(v["median_ci_low"]), "no 95 % interval for n = 5")
    # p over every sample holding one: the no_growth sample's 0.22 too (computed before the flag).
    p = summary[summary["quantity"] == b"p"][0]
    expect(p["n"] == 5 and p["n_flagged"] == 1, "p counts")
    expect(np.isclose(p["q1"], np.quantile([0.31, 0.22, 0.45, 0.18, 0.27], 0.25), rtol=1e-15), "p q1")

    corr = wt["input_rank_correlation"]
    expect(list(corr.attrs["names"]) == ["k", "d0"], "correlation names")
    np.testing.assert_array_equal(corr["target"][:], [[1, 0.3], [0.3, 1]])
    expect("target" not in f["lines/xxt1 xxt2/input_rank_correlation"], "no target without a request")

    analysis = wt["analysis"]
    expect(analysis.attrs["samples_used"] == 4, "samples_used")
    expect(list(analysis["input_output_spearman"].attrs["rows"]) == ["k_N_per_m", "d0_um", "einf_frac"],
           "spearman rows")
    expect(analysis["loadings"].shape == (5, 5), "loadings shape")
    expect(abs(analysis["explained_variance_ratio"][:].sum() - 1) < 1e-14, "ratios sum to 1")
    empty = f["lines/xxt1 xxt2/analysis"]
    expect(empty["loadings"].shape == (0, 0) and len(empty.attrs["notes"]) == 1, "empty analysis with a note")

    table = f["summary"][:]
    expect(len(table) == 7 and set(table["line"]) == {b"wild_type", b"xxt1 xxt2"}, "root summary")

    # Every numeric dataset carries its units, but for row indices that hold no values (netCDF's
    # "dimension but not a variable").
    def check_units(name, node):
        unstored = b"not a netCDF variable" in node.attrs.get("NAME", b"")
        if isinstance(node, h5py.Dataset) and node.dtype.kind in "fiu" and not unstored:
            expect("units" in node.attrs, "units on " + name)
        if isinstance(node, h5py.Dataset) and node.dtype.names and name.rsplit("/", 1)[-1] != "summary":
            expect(len(node.attrs["column_units"]) == len(node.dtype.names), "column_units on " + name)
    f.visititems(check_units)

# xarray opens every group with named dimensions (no phony_dims needed).
path = sys.argv[1]
line = xr.open_dataset(path, group="lines/wild_type", engine="h5netcdf")
expect(dict(line.sizes) == {"sample": 6, "summary_row": 5}, "line dimensions %s" % dict(line.sizes))
expect(line["p_MPa"].dims == ("sample",) and line["p_MPa"].attrs["units"] == "MPa", "p_MPa on sample, in MPa")
expect(line["p_MPa"].attrs["long_name"] == "turgor pressure", "long_name")
np.testing.assert_array_equal(line["k_N_per_m"].values, [2.87, 3.1, 2.2, 4.05, 1.9, 2.5])
np.testing.assert_array_equal(line["sample"].values, np.arange(6))
correlation = xr.open_dataset(path, group="lines/wild_type/input_rank_correlation", engine="h5netcdf")
expect(correlation["target"].dims == ("row", "column"), "correlation dims")
expect(list(correlation["row"].values) == ["k", "d0"], "correlation labels")
expect(float(correlation["target"].sel(row="k", column="d0")) == 0.3, "target by label")
analysis = xr.open_dataset(path, group="lines/wild_type/analysis", engine="h5netcdf")
expect(analysis["input_output_spearman"].dims == ("input", "output"), "spearman dims")
expect(list(analysis["output"].values) == ["p_MPa", "v_um_per_s"], "spearman output labels")
expect(analysis["loadings"].dims == ("variable", "component"), "loadings dims")
expect(analysis["explained_variance_ratio"].dims == ("component",), "ratio dims")
empty = xr.open_dataset(path, group="lines/xxt1 xxt2/analysis", engine="h5netcdf")
expect(empty["loadings"].size == 0, "the empty analysis opens too")
root = xr.open_dataset(path, engine="h5netcdf")
expect(root.sizes["summary_row"] == 7, "root summary dimension")
print("results.h5 checked with h5py and xarray")
