"""Flagged samples as a user reads them with pandas and xarray: runs tests/campaign/data/
flagged_campaign.ini (a line whose samples carry every kind of flag the models raise) with the
CLI and checks that
  * samples.csv has an empty cell exactly where the sample lacks the output, the reference being
    the inputs themselves, not the status column: d <= d0 or d/d0 > e (no turgor from the thin
    shell, src/mechanics/README.md) leaves p, E, eta and v empty; tau <= 0
    (invalid for the viscosity only) keeps p and E and leaves eta and v empty; p <= p0 keeps p,
    E and eta, with v = 0;
  * pandas' median, quartiles, 10-90 %, mean and sd of every column equal summary.csv's, its
    count of non-empty cells is n and the rest n_flagged (0 for the inputs k and tau);
  * results.h5 read by xarray (h5netcdf) has missing values exactly where samples.csv has empty
    cells, declared as _FillValue = NaN, the same values elsewhere, and its summary is summary.csv.
Usage: check_flagged_cells.py CLI CAMPAIGN WORK_DIR. Exits non-zero with a message on a mismatch."""
import math
import shutil
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pandas as pd
import xarray as xr

YIELD_PRESSURE_MPA = 0.2  # flagged_campaign.ini
OUTPUTS = ["p_MPa", "E_MPa", "eta_MPa_s", "v_um_per_s"]
QUANTITY_COLUMNS = {"k": "k_N_per_m", "tau": "tau_s", "p": "p_MPa", "E": "E_MPa", "eta": "eta_MPa_s", "v": "v_um_per_s"}


def expect(condition, what):
    if not condition:
        sys.exit("mismatch: " + what)


def close(a, b, what, rtol=4e-15):
    # Both sides read the same round-trip decimal cells; numpy's and the engine's interpolation
    # (a + t (b - a) against b - (1 - t)(b - a)) and summation orders differ by a few ulps.
    expect(math.isclose(a, b, rel_tol=rtol, abs_tol=0.0), f"{what}: {a!r} against {b!r}")


cli, campaign, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
out = work / "out"
subprocess.run([cli, "run", str(campaign), "--out", str(out), "--quiet", "--summary-only"], check=True,
               stdout=subprocess.DEVNULL)

samples = pd.read_csv(out / "samples.csv", keep_default_na=False, na_values=[""], float_precision="round_trip")
summary = pd.read_csv(out / "summary.csv", keep_default_na=False, na_values=[""], float_precision="round_trip")
empty = samples[OUTPUTS].isna()

# Which outputs each sample lacks, from its inputs.
stretch = samples["d_um"] / samples["d0_um"]
no_turgor = (samples["d_um"] <= samples["d0_um"]) | (stretch > math.e)
no_relaxation = ~no_turgor & (samples["tau_s"] <= 0)
evaluated = ~no_turgor & ~no_relaxation
below_yield = evaluated & (samples["p_MPa"] <= YIELD_PRESSURE_MPA)
for group, name in [(no_turgor, "d <= d0 or d/d0 > e"), (no_relaxation, "tau <= 0"), (below_yield, "p <= p0")]:
    expect(group.sum() >= 10, f"the campaign has only {group.sum()} samples with {name}: the check would be empty")
expect(empty[no_turgor].all(axis=None), "d <= d0 or d/d0 > e: every output empty")
expect(samples["status"][no_turgor].isin(["lambda_not_above_one", "unstable_branch", "beyond_membrane_limit"]).all(),
       "d <= d0 or d/d0 > e: a status of the turgor model")
expect(not empty.loc[no_relaxation, ["p_MPa", "E_MPa"]].any(axis=None), "tau <= 0: p and E kept (they were computed)")
expect(empty.loc[no_relaxation, ["eta_MPa_s", "v_um_per_s"]].all(axis=None), "tau <= 0: eta and v empty")
expect((samples["status"][no_relaxation] == "invalid_input").all(), "tau <= 0: status invalid_input")
expect(not empty[evaluated].any(axis=None), "every output of the other samples present")
expect((samples["v_um_per_s"][below_yield] == 0).all(), "p <= p0: v = 0")
expect((samples["status"][below_yield] == "no_growth").all(), "p <= p0: status no_growth")
expect((samples["status"][evaluated & ~below_yield] == "ok").all(), "the rest ok")

# summary.csv is pandas' statistics of samples.csv's columns.
expect(len(summary) == len(QUANTITY_COLUMNS), "one summary row per output")
for _, row in summary.iterrows():
    column = samples[QUANTITY_COLUMNS[row["quantity"]]]
    what = f"summary.csv {row['quantity']}"
    expect(row["n"] == column.count(), f"{what}: n {row['n']} against {column.count()} non-empty cells")
    expect(row["n_flagged"] == len(column) - column.count(), f"{what}: n_flagged")
    if row["quantity"] in ("k", "tau"):
        expect(row["n_flagged"] == 0, f"{what}: an input lacks no sample")
    close(row["median"], column.median(), f"{what} median")
    for name, level in [("q1", 0.25), ("q3", 0.75), ("p10", 0.10), ("p90", 0.90)]:
        close(row[name], column.quantile(level), f"{what} {name}")
    close(row["mean"], column.mean(), f"{what} mean", rtol=1e-13)
    close(row["sd"], column.std(), f"{what} sd", rtol=1e-12)

# results.h5 as xarray reads it: the same cells missing, declared as such.
h5_path = out / "results.h5"
line = xr.open_dataset(h5_path, group="lines/flagged", engine="h5netcdf")
for column in ["k_N_per_m", "d_um", "d0_um", "tau_s"] + OUTPUTS:
    values = line[column]
    expect(math.isnan(values.encoding["_FillValue"]), f"results.h5 {column}: _FillValue NaN")
    np.testing.assert_array_equal(values.isnull().values, samples[column].isna().values, err_msg=column)
    np.testing.assert_array_equal(values.values, samples[column].to_numpy(dtype=float), err_msg=column)
frame = line[OUTPUTS].to_dataframe()
for quantity in ("p", "E", "eta", "v"):
    row = summary[summary["quantity"] == quantity].iloc[0]
    close(row["median"], frame[QUANTITY_COLUMNS[quantity]].median(), f"results.h5 {quantity} median (pandas)")
with h5py.File(h5_path, "r") as f:
    p = f["lines/flagged/p_MPa"]
    expect(math.isnan(p.fillvalue) and math.isnan(p.attrs["_FillValue"]), "h5py: fill value and _FillValue NaN")
    table = pd.DataFrame(f["summary"][:])
quantities = table["quantity"].str.decode("utf-8")
for _, row in summary.iterrows():
    stored = table[quantities == row["quantity"]].iloc[0]
    expect(stored["n"] == row["n"] and stored["n_flagged"] == row["n_flagged"], f"results.h5 summary {row['quantity']} counts")
    close(stored["median"], row["median"], f"results.h5 summary {row['quantity']} median")
print(f"{len(samples)} samples: {no_turgor.sum()} with d <= d0 or d/d0 > e, {no_relaxation.sum()} with tau <= 0, "
      f"{below_yield.sum()} below the yield pressure; every summary row equals pandas'")
