#!/usr/bin/python3
"""`growthuq curves` against an independent numpy implementation of the same steps
(tools/bench/peer_curves.py: numpy.polyfit on the same window after the same baseline): on
curves drawn here with numpy's own random numbers, every curve's measured slope and k agree to
1e-9 (relative), its contact sample and window size exactly, for the relative and absolute
windows, the tilted and offset-only baselines, and with Savitzky-Golay smoothing. Also: an
existing output is not overwritten without --force, and `-` writes the table to standard output.
  check_numpy_reference.py GROWTHUQ_CLI SOURCE_DIR"""
import csv
import io
import os
import subprocess
import sys
import tempfile

import numpy as np

cli, source_dir = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(source_dir, "tools", "bench"))
import peer_curves  # noqa: E402

TOLERANCE = 1e-9
rng = np.random.default_rng(2029)
samples, tubes, repetitions = 2000, 12, 5


def draw_curves():
    """z in um and F in uN as text (repr: the doubles read back exactly), per curve."""
    curves = []
    for t in range(tubes):
        k = 2.87 * np.exp(0.2 * rng.standard_normal())
        k_sys = 100.0
        k_m = k * k_sys / (k + k_sys)
        for r in range(1, repetitions + 1):
            contact = rng.uniform(1.6, 2.2)
            z = np.linspace(0.0, 5.0 + 0.2 * r, samples)
            force = k_m * np.maximum(0.0, z - contact) + rng.uniform(-0.5, 0.5) + rng.uniform(-0.005, 0.005) * z \
                + 0.01 * rng.standard_normal(samples)
            retract_z = z[::-1][1:200]
            retract_f = force[::-1][1:200] - 0.3
            curves.append((f"t{t}r{r}", f"tube{t}", r, np.concatenate([z, retract_z]), np.concatenate([force, retract_f])))
    return curves


def write_inputs(folder, curves):
    with open(os.path.join(folder, "curves.csv"), "w") as out:
        out.write("curve,z_um,F_uN\n")
        for name, _, _, z, force in curves:
            for zi, fi in zip(z, force):
                out.write(f"{name},{zi!r},{fi!r}\n")
    with open(os.path.join(folder, "sheet.csv"), "w") as out:
        out.write("curve,tube,repetition,rho_um,k_sys_N_per_m\n")
        for name, tube, r, _, _ in curves:
            out.write(f"{name},{tube},{r},0.25,100\n")


def run(folder, arguments, out="k.csv"):
    command = [cli, "curves", "curves.csv", "--sheet", "sheet.csv", "--out", out, "--quiet"] + arguments
    return subprocess.run(command, cwd=folder, capture_output=True, text=True)


def compare(folder, curves, arguments, options):
    target = os.path.join(folder, "k.csv")
    if os.path.exists(target):
        os.remove(target)
    done = run(folder, arguments)
    assert done.returncode == 0, done.stderr
    rows = {row["curve"]: row for row in csv.DictReader(open(target))}
    worst = 0.0
    for name, _, _, z_um, f_uN in curves:
        z = np.array([float(repr(v)) for v in z_um]) * 1e-6
        force = np.array([float(repr(v)) for v in f_uN]) * 1e-6
        n = int(np.argmax(z)) + 1
        reference = peer_curves.process(z, force, n, options)
        row = rows[name]
        assert reference is not None, f"{name}: the numpy reference finds no ok fit"
        assert row["status"] == "ok", f"{name}: {row['status']} {row['reason']}"
        slope, k, contact, window = reference
        assert int(row["window_samples"]) == window, f"{name}: window of {row['window_samples']} samples, numpy {window}"
        assert abs(float(row["contact_um"]) - z[contact] * 1e6) <= 1e-12 * 5, f"{name}: contact {row['contact_um']}"
        for column, value in (("k_measured_N_per_m", slope), ("k_N_per_m", k)):
            error = abs(float(row[column]) - value) / abs(value)
            worst = max(worst, error)
            assert error <= TOLERANCE, f"{name}: {column} {row[column]} against numpy {value!r}: {error:.2e}"
    print(f"{' '.join(arguments) or 'defaults'}: {len(curves)} curves, worst relative difference {worst:.2e}")


def main():
    curves = draw_curves()
    with tempfile.TemporaryDirectory() as folder:
        write_inputs(folder, curves)
        base = {"baseline_fraction": 0.25, "tilt": True, "smooth": 0, "threshold_sigma": 5.0, "relative": True,
                "a": 4e-6, "b": 0.5e-6, "k_sys": 100.0}
        compare(folder, curves, [], base)
        compare(folder, curves, ["--window", "absolute", "--window-uN", "0.4,3", "--baseline", "offset"],
                dict(base, relative=False, a=0.4e-6, b=3e-6, tilt=False))
        compare(folder, curves, ["--smooth", "11", "--window-uN", "3,0.25"], dict(base, smooth=11, a=3e-6, b=0.25e-6))

        # An existing table is kept without --force; `-` is standard output.
        before = open(os.path.join(folder, "k.csv")).read()
        refused = run(folder, [])
        assert refused.returncode != 0 and "--force" in refused.stderr, refused.stderr
        assert open(os.path.join(folder, "k.csv")).read() == before
        assert run(folder, ["--force"]).returncode == 0
        piped = run(folder, ["--tubes", "tubes.csv"], out="-")
        assert piped.returncode == 0, piped.stderr
        assert next(csv.reader(io.StringIO(piped.stdout)))[:4] == ["curve", "tube", "repetition", "status"]
        assert "12 tube(s)" in piped.stderr, piped.stderr
        tube_rows = list(csv.DictReader(open(os.path.join(folder, "tubes.csv"))))
        assert len(tube_rows) == tubes and all(row["ok"] == "5" for row in tube_rows)
    print("ok")


main()
