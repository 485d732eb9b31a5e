#!/usr/bin/python3
"""An independent numpy implementation of the force-curve steps of src/forcecurves/README.md
(Eqs. (C1)-(C7): baseline by numpy.polyfit, contact by deviation from the baseline, optional
Savitzky-Golay by numpy.convolve, the window mask, the slope by numpy.polyfit, the sensor in
series). It is the reference of tests/forcecurves/check_numpy_reference.py (agreement to 1e-9)
and the peer of tools/bench/bench-curves. Run as a program it times the steps on synthetic
curves drawn in memory:
  peer_curves.py --curves 10000 --samples 2000 --repeats 3
prints `median_seconds`, `median_cpu_seconds` and `curves_per_second` lines."""
import argparse
import statistics
import time

import numpy as np

EPS = np.finfo(float).eps


def savitzky_golay_quadratic(y, window):
    """Eq. (C5): c_i = 3 (3m^2 + 3m - 1 - 5 i^2) / ((2m + 1)(4m^2 + 4m - 3)); ends kept."""
    m = (window - 1) // 2
    i = np.arange(-m, m + 1)
    weights = 3.0 * (3 * m * m + 3 * m - 1 - 5 * i * i) / ((2 * m + 1) * (4 * m * m + 4 * m - 3))
    out = y.copy()
    out[m:len(y) - m] = np.convolve(y, weights[::-1], mode="valid")
    return out


def process(z, force, n, options):
    """The approach's (first n samples) measured slope k_m, the tube's k, the contact index and
    the window's sample count, or None when the curve does not reach an ok fit."""
    nb = int(options["baseline_fraction"] * n)
    z = z[:n]
    force = force[:n]
    if options["tilt"]:
        tilt, offset = np.polyfit(z[:nb], force[:nb], 1)
        residual = force[:nb] - (offset + tilt * z[:nb])
        sigma = np.sqrt(np.sum(residual * residual) / (nb - 2))
    else:
        tilt, offset = 0.0, np.mean(force[:nb])
        sigma = np.std(force[:nb], ddof=1)
    y = force - (offset + tilt * z)
    if options["smooth"]:
        y = savitzky_golay_quadratic(y, options["smooth"])
    peak = nb + int(np.argmax(y[nb:]))
    rounding = 64.0 * EPS * abs(np.max(force))
    threshold = max(options["threshold_sigma"] * sigma, rounding)
    if not y[peak] > threshold:
        return None
    below = np.nonzero(y[:peak + 1] <= threshold)[0]
    j = below[-1] if below.size else 0
    at_baseline = np.nonzero(y[:j + 1] <= rounding)[0]
    contact = int(at_baseline[-1]) if at_baseline.size else 0
    if options["relative"]:
        low, high = y[peak] - options["a"], y[peak] - options["b"]
    else:
        low, high = options["a"], options["b"]
    index = np.arange(n)
    mask = (index >= contact) & (index <= peak) & (y >= low) & (y <= high)
    if np.count_nonzero(mask) < 10:
        return None
    slope = np.polyfit(z[mask], y[mask], 1)[0]
    k_sys = options.get("k_sys", np.inf)
    k = slope if np.isinf(k_sys) else slope * k_sys / (k_sys - slope)
    return slope, k, contact, int(np.count_nonzero(mask))


def synthetic_curves(count, samples, seed):
    """Linear curves as src/synthetic's: k = 2.87 N/m, contact at 1.5 um of 4 um, offset 0.3 uN,
    drift 0.01 N/m of tilt, noise 0.01 uN (its own random numbers)."""
    rng = np.random.default_rng(seed)
    z = np.linspace(0.0, 4e-6, samples)
    shape = 2.87 * np.maximum(0.0, z - 1.5e-6) + 0.3e-6 + 0.01 * z
    return z, shape[None, :] + 1e-8 * rng.standard_normal((count, samples))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--curves", type=int, default=10000)
    parser.add_argument("--samples", type=int, default=2000)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    z, forces = synthetic_curves(args.curves, args.samples, 1)
    options = {"baseline_fraction": 0.25, "tilt": True, "smooth": 0, "threshold_sigma": 5.0, "relative": True,
               "a": 4e-6, "b": 0.5e-6, "k_sys": 100.0}
    walls, cpus = [], []
    for _ in range(args.repeats):
        wall, cpu = time.perf_counter(), time.thread_time()
        ok = sum(process(z, forces[c], args.samples, options) is not None for c in range(args.curves))
        cpus.append(time.thread_time() - cpu)
        walls.append(time.perf_counter() - wall)
    print(f"curves {args.curves}\nsamples {args.samples}\nok {ok}")
    print(f"median_seconds {statistics.median(walls):.4f}\nmedian_cpu_seconds {statistics.median(cpus):.4f}")
    print(f"curves_per_second {args.curves / statistics.median(walls):.0f}")


if __name__ == "__main__":
    main()
