"""Reads a results.h5 written by test_results_h5.cpp with h5py, as users will, and checks values,
units and layout. Usage: check_results_h5.py FILE. Exits non-zero with a message on a mismatch."""
import sys

import h5py
import numpy as np


def expect(condition, what):
    if not condition:
        sys.exit("mismatch: " + what)


with h5py.File(sys.argv[1], "r") as f:
    expect(f.attrs["campaign_path"] == "campaigns/test.ini", "campaign_path")
    expect(f.attrs["campaign_text"].endswith("# \u00b5m and a newline\n"), "campaign_text (UTF-8)")
    expect(int(f.attrs["seed"]) == 18446744073709551557, "seed")
    expect(f.attrs["kappa"] == 0.8125, "kappa")
    expect(f.attrs["engine_version"] == "0.1.0", "engine_version")
    expect(sorted(f["lines"].keys()) == ["wild_type", "xxt1 xxt2"], "line groups")

    wt = f["lines/wild_type"]
    expect(wt["p_MPa"].attrs["unit"] == "MPa" and wt["p_MPa"].attrs["quantity"] == "p", "p unit")
    expect(wt["k_N_per_m"].attrs["unit"] == "N/m" and wt["k_N_per_m"].attrs["role"] == "input", "k unit")
    expect(wt["v_um_per_s"].attrs["unit"] == "um/s", "v unit")
    expect(wt["d0_um"].dtype == np.float64, "float64 columns")
    np.testing.assert_array_equal(wt["k_N_per_m"][:], [2.87, 3.1, 2.2, 4.05, 1.9, 2.5])
    np.testing.assert_array_equal(wt["p_MPa"][:], [0.31, np.nan, 0.22, 0.45, 0.18, 0.27])
    np.testing.assert_array_equal(wt["sample"][:], np.arange(6))
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
    p = summary[summary["quantity"] == b"p"][0]
    expect(p["n"] == 4 and np.isclose(p["q1"], np.quantile([0.31, 0.45, 0.18, 0.27], 0.25), rtol=1e-15), "p q1")

    corr = wt["input_rank_correlation"]
    expect(list(corr.attrs["names"]) == ["k", "d0"], "correlation names")
    np.testing.assert_array_equal(corr["target"][:], [[1, 0.3], [0.3, 1]])
    expect("target" not in f["lines/xxt1 xxt2/input_rank_correlation"], "no target without a request")

    analysis = wt["analysis"]
    expect(analysis.attrs["samples_used"] == 4, "samples_used")
    expect(list(analysis["input_output_spearman"].attrs["rows"]) == ["k_N_per_m", "d0_um"], "spearman rows")
    expect(analysis["loadings"].shape == (4, 4), "loadings shape")
    expect(abs(analysis["explained_variance_ratio"][:].sum() - 1) < 1e-14, "ratios sum to 1")
    empty = f["lines/xxt1 xxt2/analysis"]
    expect(empty["loadings"].shape == (0, 0) and len(empty.attrs["notes"]) == 1, "empty analysis with a note")

    table = f["summary"][:]
    expect(len(table) == 6 and set(table["line"]) == {b"wild_type", b"xxt1 xxt2"}, "root summary")
print("results.h5 checked with h5py")
