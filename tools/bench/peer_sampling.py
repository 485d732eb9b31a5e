#!/usr/bin/python3
"""Peer of tools/bench/bench_sampling.cpp in vectorized numpy/scipy, for a side-by-side timing.

The same steps, with the same shortcuts: per variable a random permutation (the strata) and one
uniform per stratum, the lognormal quantile exp(mu + sigma ndtri(u)) evaluated per stratum and
looked up by rank (no sorting), van der Waerden scores ndtri(k/(n+1)) computed once, their
correlation T, Cholesky factors, scores @ (P Q^-1)^T, np.argsort of columns 1.. only (column 0
keeps its order), ranks by scattering arange(n). Single thread (BLAS threads pinned to 1 by the
driver). Prints the same lines as bench_sampling.
"""
import argparse
import time

import numpy as np
from scipy.linalg import solve_triangular
from scipy.special import ndtri

Z75 = ndtri(0.75)


def lognormal(median, iqr):
    """mu, sigma of the lognormal with this median and IQR (Eq. (D1),
    src/distributions/README.md)."""
    return np.log(median), np.arcsinh(iqr / (2 * median)) / Z75


VARIABLES = [lognormal(2.87, 0.83), lognormal(145, 31), lognormal(6.56, 1.19), lognormal(5.35, 1.15)]
SPEARMAN = np.array([[1.0, 0.25, 0.55, 0.30],
                     [0.25, 1.0, -0.10, 0.05],
                     [0.55, -0.10, 1.0, 0.70],
                     [0.30, 0.05, 0.70, 1.0]])


def design(n, seed):
    rng = np.random.default_rng(seed)
    m = len(VARIABLES)
    ranks = np.empty((m, n), dtype=np.int64)
    value_by_stratum = np.empty((m, n))
    k = np.arange(n)
    for j, (mu, sigma) in enumerate(VARIABLES):
        ranks[j] = rng.permutation(n)
        u = (k + rng.random(n)) / n
        value_by_stratum[j] = np.exp(mu + sigma * ndtri(u))

    rho = 2 * np.sin(np.pi * SPEARMAN / 6)
    scores = ndtri(np.arange(1, n + 1) / (n + 1))
    s = scores[ranks.T]                            # n x m, score of each sample's rank
    t = (s.T @ s) / np.dot(scores, scores)
    p = np.linalg.cholesky(rho)
    q = np.linalg.cholesky(t)
    mix = solve_triangular(q, p.T, trans='T', lower=True).T   # P Q^-1
    s = s @ mix.T
    for j in range(1, m):
        order = np.argsort(s[:, j])
        ranks[j, order] = k
    values = np.take_along_axis(value_by_stratum, ranks, axis=1)
    return values, ranks


def spearman_of_ranks(ranks):
    n = ranks.shape[1]
    r = ranks.astype(np.float64) - (n - 1) / 2
    c = r @ r.T
    d = np.sqrt(np.diag(c))
    return c / np.outer(d, d)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('--samples', type=int, default=1_000_000)
    parser.add_argument('--repeats', type=int, default=5)
    parser.add_argument('--seed', type=int, default=2022)
    args = parser.parse_args()
    times, cpu_times = [], []
    for r in range(args.repeats):
        start, cpu_start = time.perf_counter(), time.thread_time()
        _, ranks = design(args.samples, args.seed + r)
        cpu_times.append(time.thread_time() - cpu_start)
        times.append(time.perf_counter() - start)
    error = np.max(np.abs(spearman_of_ranks(ranks) - SPEARMAN))
    print(f"samples {args.samples}, repeats {args.repeats}, single thread (numpy {np.__version__})")
    print(f"median_seconds {np.median(times):.6f}")
    print(f"median_cpu_seconds {np.median(cpu_times):.6f}")
    print(f"max_spearman_error {error:.6f}")


if __name__ == '__main__':
    main()
