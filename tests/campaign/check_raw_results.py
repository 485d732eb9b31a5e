"""Reads the results of tests/campaign/data/raw_campaign.ini with h5py, as the plotting tools do,
and checks the raw-data layout of results.h5 (campaign/raw_data_outputs.hpp) against the raw
files themselves, and the campaign's per-curve eta against `growthuq relax` on the same curves (one
viscosity, Eq. (R7) of src/relaxation/README.md). Usage: check_raw_results.py RESULTS_DIR RAW_DIR
RELAX_FITS_CSV. Exits non-zero on a mismatch."""
import csv
import sys

import h5py
import numpy as np


def expect(condition, what):
    if not condition:
        sys.exit("mismatch: " + what)


def table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def text(value):
    return value.decode() if isinstance(value, bytes) else value


results, raw, relax_fits = sys.argv[1], sys.argv[2], sys.argv[3]
with h5py.File(results + "/results.h5", "r") as f:
    wt = f["lines/wild_type"]
    fits = wt["fits"][:]
    for field in ["variable", "family", "parameters", "n", "log_likelihood", "aic", "ks", "ad", "unit", "source"]:
        expect(field in fits.dtype.names, "fits field " + field)
    variables = [text(v) for v in fits["variable"]]
    # k of force curves comes after the measurements and the relaxation's tau and einf.
    expect(variables == ["d", "d0", "h", "v_exp", "tau", "einf", "k"], "fitted variables " + str(variables))
    counts = {"k": len(table(raw + "/indentation.csv")), "d0": len(table(raw + "/plasmolysis.csv")),
              "h": len(table(raw + "/tem_sections.csv")), "v_exp": len(table(raw + "/growth.csv"))}
    for row in fits:
        name = text(row["variable"])
        if name in counts:
            expect(row["n"] == counts[name], "n of " + name)
        expect(abs(row["aic"] - (4 - 2 * row["log_likelihood"])) < 1e-9 * abs(row["aic"]), "AIC = 2k - 2 logL for " + name)
        expect(0 < row["ks"] < 1 and row["ad"] > 0, "KS and AD of " + name)
    # The values each law was fitted to are the raw files' cells, in the files' order and unit.
    # (k comes from the force curves, [force_curves] in raw.ini: its values are the tubes' k with
    # an ok curve, checked against the force-curve tables below.)
    tube_k = wt["force_curves/tubes"][:]
    expect(np.array_equal(wt["fit_data/k"][:], tube_k["k_N_per_m"][tube_k["ok"] > 0]), "fit_data of k: the tubes' k")
    expect(text(wt["fit_data/k"].attrs["units"]) == text(fits[variables.index("k")]["unit"]), "fit_data unit of k")
    for name, file, column in [("h", "tem_sections.csv", "h_nm"), ("v_exp", "growth.csv", "v_exp_um_per_s")]:
        stored = wt["fit_data/" + name]
        expect(np.allclose(stored[:], [float(r[column]) for r in table(raw + "/" + file)], rtol=1e-14, atol=0),
               "fit_data of " + name)
        expect(text(stored.attrs["units"]) == text(fits[variables.index(name)]["unit"]), "fit_data unit of " + name)
    expect(len(wt["fit_data/tau"]) == fits[variables.index("tau")]["n"], "fit_data of tau: one per fitted curve")
    candidates = wt["fit_candidates"][:]
    for name in variables:
        rows = candidates[[text(v) == name for v in candidates["variable"]]]
        # einf, a fraction, also has the bounded beta law (distributions/README.md, "Laws of fractions").
        families = 5 if name == "einf" else 4
        expect(len(rows) == families, "%d candidate families for %s" % (families, name))
        ok = rows[[text(s) == "ok" for s in rows["status"]]]
        expect(np.all(ok["delta_aic"] >= 0) and np.sum(ok["delta_aic"] == 0) == 1, "one least-AIC family for " + name)

    # The parameters as numbers: each ok candidate's, rounded as the text column prints them
    # (%.6g, as describe() does), give that text back; the chosen family is the fits table's.
    numbers = wt["fit_parameters"][:]
    expect(list(wt["fit_parameters"].attrs["column_units"]) == ["", "", "", "1", "", ""], "fit_parameters units")
    for name in variables:
        for candidate in candidates[[text(v) == name for v in candidates["variable"]]]:
            family = text(candidate["family"])
            mine = numbers[[text(v) == name and text(f) == family for v, f in zip(numbers["variable"], numbers["family"])]]
            if text(candidate["status"]) != "ok":
                expect(len(mine) == 0, "no numbers for the failed %s of %s" % (family, name))
                continue
            printed = ", ".join("%s=%.6g" % (text(p), v) for p, v in zip(mine["parameter"], mine["value"]))
            expect(text(candidate["parameters"]).startswith(printed),
                   "%s of %s: %r vs %r" % (family, name, printed, text(candidate["parameters"])))
            expect(np.all(mine["chosen"] == (candidate["delta_aic"] == 0)), "chosen flag of %s of %s" % (family, name))
    chosen = numbers[numbers["chosen"] == 1]
    expect([text(v) for v in dict.fromkeys(chosen["variable"])] == variables, "one chosen law per variable")

    relaxation = wt["relaxation"]
    expect(text(relaxation.attrs["fit"]) == "step", "fit attribute")
    curve_fits = relaxation["fits"][:]
    meta = table(raw + "/relaxation_meta.csv")
    expect([text(c) for c in curve_fits["curve"]] == [m["curve"] for m in meta], "one fit row per curve, in order")
    for field in ["status", "reason", "tau_fast_s", "tau_slow_s", "einf_frac", "Er0_MPa", "eta_MPa_s", "delta_um", "p_MPa"]:
        expect(field in curve_fits.dtype.names, "relaxation fits field " + field)
    expect(np.allclose(curve_fits["p_MPa"], [float(m["p_MPa"]) for m in meta]), "tube sheet p")
    # ok and extrapolated (tau_slow beyond the hold) are fits; both enter the laws of tau and einf.
    fitted = sum(text(s) in ("ok", "extrapolated") for s in curve_fits["status"])
    expect(fits[variables.index("tau")]["n"] == fitted, "tau fitted to the ok and extrapolated curves")

    # One viscosity: the campaign's per-curve eta is relax's on the same curves, and both are
    # eta = tau_slow (1 - einf) E_r(0), the formula of the campaigns' samples (Eq. (G1)).
    relax = table(relax_fits)
    expect([r["curve"] for r in relax] == [text(c) for c in curve_fits["curve"]], "relax fits the same curves")
    etas = []
    for row, mine in zip(curve_fits, relax):
        name = text(row["curve"])
        expect(text(row["status"]) == mine["status"], "status of " + name)
        if mine["status"] == "fit_failed":
            expect(np.isnan(row["eta_MPa_s"]) and mine["eta_MPa_s"] == "", "no eta for failed " + name)
            continue
        for field in ["tau_slow_s", "tau_slow_low_s", "tau_slow_high_s", "einf_frac", "Er0_MPa", "E0_MPa", "eta_MPa_s"]:
            expect(abs(row[field] - float(mine[field])) <= 1e-14 * abs(row[field]), field + " of " + name + " as relax")
        by_hand = row["tau_slow_s"] * (1.0 - row["einf_frac"]) * row["Er0_MPa"]
        expect(abs(row["eta_MPa_s"] - by_hand) <= 1e-14 * by_hand, "eta = tau_slow (1 - einf) Er0 for " + name)
        expect(abs(row["E0_MPa"] - (1.0 - row["einf_frac"]) * row["Er0_MPa"]) <= 1e-14 * row["Er0_MPa"], "E0 of " + name)
        etas.append(float(mine["eta_MPa_s"]))
    expect(np.median(etas) == np.nanmedian(curve_fits["eta_MPa_s"]), "median eta over the curves as relax")
    print("median eta over %d curves: %.6g MPa s (relax and the campaign)" % (len(etas), np.median(etas)))

    points = relaxation["points"]
    index, t, force, model = points["curve_index"][:], points["t_s"][:], points["F_uN"][:], points["F_fit_uN"][:]
    expect(points["curve_index"].dtype == np.int32, "curve_index is int32")
    expect(len(index) == len(t) == len(force) == len(model), "point arrays of equal length")
    data = table(raw + "/relaxation_curves.csv")
    expect(len(data) == len(t), "every sample of the curves file")
    expect(np.allclose(t, [float(r["t_s"]) for r in data], rtol=0, atol=1e-12), "t_s as in the file")
    expect(np.allclose(force, [float(r["F_uN"]) for r in data], rtol=1e-12, atol=0), "F_uN as in the file")
    expect(index.min() == 0 and index.max() == len(curve_fits) - 1, "curve_index spans the fits table")
    worst = 0.0
    for c, row in enumerate(curve_fits):
        mask = index == c
        fc, m = force[mask], model[mask]
        peak = int(np.argmax(fc))
        expect(np.all(np.isnan(m[:peak])), "no step model before the force maximum, curve %d" % c)
        if text(row["status"]) == "ok":
            expect(np.all(np.isfinite(m[peak:])), "model over the hold, curve %d" % c)
            worst = max(worst, np.sqrt(np.mean((m[peak:] - fc[peak:]) ** 2)) / fc[peak])
    # 0.2 % force noise of the synthetic set: the model follows the data to about that.
    expect(worst < 0.005, "fitted model follows the ok curves (worst rms %.4f of the peak force)" % worst)
    expect("fits" not in f["lines/pme48"], "no fits for a line given by its line file")

    # The force curves: one row per curve of the sheet, in its order, the approaches' samples as in
    # the file, every tube's k the mean of its ok curves and the n of k's law (Eq. (C10)).
    force_curves = wt["force_curves"]
    sheet = table(raw + "/force_curves_sheet.csv")
    rows = force_curves["curves"][:]
    expect([text(c) for c in rows["curve"]] == [r["curve"] for r in sheet], "one force-curve row per curve, in order")
    approach = [r for r in table(raw + "/force_curves.csv") if r["segment"] == "approach"]
    z = force_curves["points"]["z_um"][:]
    expect(len(z) == len(approach), "every approach sample of the force curves")
    expect(np.allclose(z, [float(r["z_um"]) for r in approach], rtol=0, atol=1e-12), "z_um as in the file")
    tubes = force_curves["tubes"][:]
    ok = [text(s) == "ok" for s in rows["status"]]
    for tube in tubes:
        mine = [o and text(t) == text(tube["tube"]) for o, t in zip(ok, rows["tube"])]
        expect(abs(np.mean(rows["k_N_per_m"][mine]) - tube["k_N_per_m"]) <= 1e-12 * tube["k_N_per_m"], "tube k is its curves' mean")
    expect(fits[variables.index("k")]["n"] == np.sum(tubes["ok"] > 0), "k fitted to the tubes with an ok curve")
    expect(fits[variables.index("k")]["n"] == counts["k"], "every indented tube has an ok curve")

    uncertainty = f["data_uncertainty"][:]
    summary = {(r["line"], r["quantity"]): r for r in table(results + "/summary.csv")}
    csv_rows = table(results + "/data_uncertainty.csv")
    expect(len(uncertainty) == 8 and len(csv_rows) == 8, "2 lines x 4 outputs")
    for row, csv_row in zip(uncertainty, csv_rows):
        key = (text(row["line"]), text(row["quantity"]))
        expect(key == (csv_row["line"], csv_row["quantity"]), "same rows in CSV and HDF5")
        # wild_type's k comes from force curves, drawn within each tube's u (the default): its
        # interval includes measurement error; pme48's line file has none to draw.
        included = "included" if key[0] == "wild_type" else "none"
        expect(csv_row["measurement_error"] == included and text(row["measurement_error"]) == included,
               "measurement_error of " + str(key))
        expect(row["median"] == float(summary[key]["median"]), "median as in summary.csv " + str(key))
        expect(row["data_ci_low"] <= row["data_ci_high"], "ordered interval " + str(key))
        expect(abs(row["data_ci_low"] - float(csv_row["data_ci_low"])) <= 1e-15 * abs(row["data_ci_low"]), "CSV interval")
        replicates = f["lines/%s/data_uncertainty_replicates/%s" % key][:]
        expect(len(replicates) == row["replicates"] and row["replicates"] + row["failed_replicates"] == 20, "replicates")
        expect(abs(np.percentile(replicates, 2.5) - row["data_ci_low"]) <= 1e-12 * abs(row["data_ci_low"]), "2.5 % of replicates")
        # The data interval sits beside the Monte Carlo CI in summary.csv, /summary and the line's
        # summary, the same numbers as the bootstrap's table (the 97.5 % of its replicate medians).
        expect(abs(np.percentile(replicates, 97.5) - row["data_ci_high"]) <= 1e-12 * abs(row["data_ci_high"]), "97.5 %")
        for end in ("data_ci_low", "data_ci_high"):
            expect(float(summary[key][end]) == row[end], "summary.csv %s %s" % (end, key))
            for h5_summary in (f["summary"][:], f["lines/%s/summary" % key[0]][:]):
                match = [r for r in h5_summary if (text(r["line"]), text(r["quantity"])) == key]
                expect(len(match) == 1 and match[0][end] == row[end], "results.h5 summary %s %s" % (end, key))
print("raw-data results checked with h5py")
