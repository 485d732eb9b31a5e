#!/usr/bin/python3
"""numpy/scipy peer of `growthuq run CAMPAIGN --formats hdf5`, for a side-by-side timing.

The same campaign, step for step, written as a competent vectorized numpy/scipy program
(tools/bench/bench-campaign runs both and compares them):

  design      per line: the `physics` rank correlation (uniform (p, E, h, d0) draws, forward
              thin-shell model with scipy's Lambert W, Spearman of (k, h, d, d0) over the tubes
              that hold), or a matrix file; S -> rho = 2 sin(pi S / 6), nearest correlation
              (Higham 2002) when not positive definite; per variable a random permutation (the
              strata) and one point per stratum; Iman-Conover on the strata (van der Waerden
              scores, the Q step, ordinal ranks, column 0 kept); each variable's quantile
              (scipy.special) evaluated per stratum and looked up by rank.
  evaluation  the thin-shell inverse (closed form; phi = x K1(x)/K0(x) from scipy's scaled
              Bessel functions, series below 1e-5, Hankel expansion above 1e3), modulus,
              viscosity eta = tau (1 - e_inf) E, growth v = (p - p0) d^2 / (4 eta h) with
              kappa = 1, statuses (the first non-ok status of a sample is kept); kappa
              calibrated on the reference line (run first) and applied to every line.
  summaries   per line and output: median, quartiles, p10/p90 (numpy's linear rule), mean, sd
              and the order-statistic 95 % confidence interval of the median (binomial ranks),
              one np.partition per column; achieved input Spearman from the strata ranks; the
              input/output Spearman (average ranks) and the PCA of the standardized inputs and
              outputs over samples with status ok.
  write       results.h5 with h5py (same groups, datasets and attributes as the engine,
              uncompressed), written line by line through results.h5.partial, and summary.csv.

Random numbers come from numpy's default Generator (PCG64) seeded from the campaign seed and
the line name, so results agree with the engine statistically, not bit for bit. Run it single
threaded (OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1). Per-phase wall times go to stderr.

  /usr/bin/python3 tools/bench/peer_campaign.py --campaign campaigns/arabidopsis_2022.ini \
      --samples 1000000 --out /tmp/peer_run
"""
import argparse
import configparser
import math
import os
import sys
import time

import h5py
import numpy as np
from scipy import special, stats

STATUS_NAMES = ['ok', 'invalid_input', 'lambda_not_above_one', 'beyond_membrane_limit', 'burst',
                'no_growth', 'fit_failed', 'stiffness_at_sensor_limit', 'out_of_range', 'unstable_branch',
                'not_converged', 'contact_lost', 'probe_beyond_mesh', 'window_not_reached', 'no_inflation_state',
                'no_modulus_root', 'outside_correction', 'probe_engulfed']
OK, INVALID, LAMBDA_NOT_ABOVE_ONE, BEYOND_MEMBRANE, BURST, NO_GROWTH = 0, 1, 2, 3, 4, 5
SENSOR_LIMIT, OUT_OF_RANGE, UNSTABLE_BRANCH = 7, 8, 9

# symbol: (column suffix, factor to SI)
UNITS = {'1': ('', 1.0), 'frac': ('frac', 1.0), '%': ('pct', 1e-2), 'm': ('m', 1.0), 'mm': ('mm', 1e-3),
         'um': ('um', 1e-6), 'nm': ('nm', 1e-9), 'N/m': ('N_per_m', 1.0), 'Pa': ('Pa', 1.0),
         'kPa': ('kPa', 1e3), 'MPa': ('MPa', 1e6), 's': ('s', 1.0), 'm/s': ('m_per_s', 1.0),
         'um/s': ('um_per_s', 1e-6), 'nm/s': ('nm_per_s', 1e-9), 'Pa s': ('Pa_s', 1.0),
         'MPa s': ('MPa_s', 1e6)}
DEFAULT_UNIT = {'p': 'MPa', 'E': 'MPa', 'eta': 'MPa s', 'v': 'um/s', 'lambda': '1', 'alpha': 'um', 'phi': '1',
                'hoop_stress': 'MPa', 'wall_stiffness': 'N/m'}
# The models (what each reads and writes), in the engine's order of preference.
MODELS = [('turgor', ['k', 'd', 'd0'], ['lambda', 'alpha', 'phi', 'p']),
          ('modulus', ['p', 'd', 'd0', 'h'], ['E', 'hoop_stress', 'wall_stiffness']),
          ('viscosity', ['tau', 'einf', 'E'], ['eta']),
          ('growth', ['p', 'd', 'eta', 'h'], ['v'])]
Z75 = special.ndtri(0.75)
EULER_GAMMA = 0.57721566490153286061


def column_name(quantity, unit):
    suffix = UNITS[unit][0]
    return quantity + ('_' + suffix if suffix else '')


def fnv1a64(text):
    h = 0xcbf29ce484222325
    for byte in text.encode():
        h = ((h ^ byte) * 0x100000001b3) & 0xffffffffffffffff
    return h


# ---------------------------------------------------------------------------------------------
# Files

def read_ini(path):
    parser = configparser.ConfigParser(interpolation=None, comment_prefixes=('#', ';'))
    parser.optionxform = str
    with open(path) as f:
        text = f.read()
    parser.read_string(text, source=path)
    return parser, text


class Variable:
    """One line-file variable: its quantile function (vectorized) and unit."""

    def __init__(self, name, section):
        self.name = name
        self.unit = section['unit']
        law = section['law']
        self.law = law
        p = {key: section[key] for key in section if key not in ('law', 'unit', 'source', 'note')}
        number = lambda key: float(p[key])
        if law == 'lognormal':
            if 'median' in p:
                self.mu, self.sigma = math.log(number('median')), math.asinh(number('iqr') / (2 * number('median'))) / Z75
            else:
                self.mu, self.sigma = number('mu'), number('sigma')
        elif law in ('normal', 'truncated_normal'):
            self.mean, self.sd = number('mean'), number('sd')
            self.lower = float(p['lower']) if law == 'truncated_normal' else -math.inf
            self.upper = float(p['upper']) if law == 'truncated_normal' else math.inf
            a, b = (self.lower - self.mean) / self.sd, (self.upper - self.mean) / self.sd
            self.phi_a, self.q_b = special.ndtr(a), special.ndtr(-b)
            self.mass = special.ndtr(b) - self.phi_a if b <= 0 else (1 - self.q_b) - self.phi_a
        elif law == 'uniform':
            self.lower, self.upper = number('lower'), number('upper')
        elif law in ('gamma', 'weibull'):
            self.shape, self.scale = number('shape'), number('scale')
        elif law == 'empirical':
            self.sorted = np.sort(np.array([float(v) for v in p['values'].split(',')]))
        else:
            raise ValueError(f"{name}: law '{law}' is not supported by the peer")

    def quantile(self, u):
        if self.law == 'lognormal':
            return np.exp(self.mu + self.sigma * special.ndtri(u))
        if self.law == 'normal':
            return self.mean + self.sd * special.ndtri(u)
        if self.law == 'truncated_normal':
            # From the nearer end of the window, as the engine does: Phi^-1 of a lower-tail
            # probability below 1/2, or -Phi^-1 of an upper-tail one, so neither tail loses digits.
            lower_half = u <= 0.5
            z = special.ndtri(np.where(lower_half, self.phi_a + u * self.mass, self.q_b + (1 - u) * self.mass))
            z = np.where(lower_half, z, -z)
            return np.clip(self.mean + self.sd * z, self.lower, self.upper)
        if self.law == 'uniform':
            return self.lower + (self.upper - self.lower) * u
        if self.law == 'gamma':
            return self.scale * special.gammaincinv(self.shape, u)
        if self.law == 'weibull':
            return self.scale * (-np.log1p(-u)) ** (1 / self.shape)
        return np.interp(u, np.linspace(0, 1, len(self.sorted)), self.sorted)  # empirical

    def median_si(self):
        return float(self.quantile(np.array([0.5]))[0]) * UNITS[self.unit][1]


def read_line_file(path):
    parser, _ = read_ini(path)
    name = parser['line']['name']
    variables = [Variable(section, parser[section]) for section in parser.sections() if section != 'line']
    return name, variables


def read_matrix_csv(path):
    rows = [line.strip() for line in open(path) if line.strip() and not line.lstrip().startswith('#')]
    names = [cell.strip() for cell in rows[0].split(',')]
    return names, np.array([[float(cell) for cell in row.split(',')] for row in rows[1:]])


def range_si(text, factor):
    low, high = text.split(':')
    return float(low) * factor, float(high) * factor


class Campaign:
    def __init__(self, path, samples=None, seed=None, out=None):
        parser, self.text = read_ini(path)
        self.path = path
        c = parser['campaign']
        self.name = c['name']
        self.seed = int(seed if seed is not None else c['seed'])
        self.samples = int(samples if samples is not None else c['samples'])
        self.outputs = [o.strip() for o in c['outputs'].split(',') if o.strip()]
        self.output_dir = out if out is not None else c['output_dir']
        self.centred = c.get('stratum_position', 'random') in ('centred', 'centered')
        i = parser['instrument']
        self.rho = float(i['probe_radius_um']) * 1e-6
        self.nu = float(i.get('poisson_ratio', '0.2'))
        k_sys = i.get('sensor_stiffness_N_per_m', 'inf')
        self.k_sys = math.inf if k_sys == 'inf' else float(k_sys)
        g = parser['growth'] if parser.has_section('growth') else {}
        self.p0 = float(g.get('yield_pressure_MPa', '0')) * 1e6
        self.reference_line = g.get('reference_line', '')
        ph = parser['physics_correlation'] if parser.has_section('physics_correlation') else {}
        self.physics = {'p': range_si(ph.get('p_MPa', '0.1:0.8'), 1e6), 'E': range_si(ph.get('E_MPa', '5:200'), 1e6),
                        'h': range_si(ph.get('h_nm', '100:300'), 1e-9), 'd0': range_si(ph.get('d0_um', '4:8'), 1e-6),
                        'log': ph.get('scale', 'uniform') == 'log_uniform', 'samples': int(ph.get('samples', '10000'))}
        folder = os.path.dirname(os.path.abspath(path))
        self.lines = []
        for section in parser.sections():
            if not section.startswith('line '):
                continue
            s = parser[section]
            correlation = s.get('rank_correlation', 'none')
            if correlation not in ('none', 'physics'):
                correlation = os.path.join(folder, correlation)
            self.lines.append(Line(section[5:].strip(), os.path.join(folder, s['distributions']), correlation, self))
        self.computed_outputs = [o for o in self.outputs
                                 if not any(line.variable(o) is not None for line in self.lines)]
        self.calibrates_kappa = 'v' in self.outputs
        if self.calibrates_kappa:
            reference = next(line for line in self.lines if line.name == self.reference_line)
            self.experimental_median = next(v for v in reference.all_variables if v.name == 'v_exp').median_si()
            self.lines.remove(reference)
            self.lines.insert(0, reference)  # kappa first, as the engine does


class Line:
    def __init__(self, name, path, correlation, campaign):
        self.name = name
        _, self.all_variables = read_line_file(path)
        inputs = [v.name for v in self.all_variables]
        # The models the outputs need (depth first, as the engine's planner), then the variables
        # they read: only those are sampled.
        self.plan = []

        def schedule(quantity):
            if quantity in inputs:
                return
            model = next(m for m in MODELS if quantity in m[2])
            if model in self.plan:
                return
            for read in model[1]:
                schedule(read)
            self.plan.append(model)

        for output in campaign.outputs:
            schedule(output)
        needed = set(campaign.outputs) | {read for model in self.plan for read in model[1]}
        self.variables = [v for v in self.all_variables if v.name in needed]
        self.correlation = correlation

    def variable(self, name):
        return next((v for v in self.variables if v.name == name), None)


# ---------------------------------------------------------------------------------------------
# Mechanics (Eqs. (M1)-(M16), src/mechanics/README.md)

def arnoldi_phi(x):
    """phi(x) = x K1(x)/K0(x): scaled Bessel functions, series below 1e-5, Hankel above 1e3."""
    with np.errstate(all='ignore'):
        phi = x * (special.k1e(x) / special.k0e(x))
        small = x < 1e-5
        if small.any():
            xs = x[small]
            L = math.log(2) - np.log(xs) - EULER_GAMMA
            x2 = xs * xs
            phi[small] = np.where(xs == 0, 0.0, (1 - 0.5 * x2 * (L + 0.5)) / (L + 0.25 * x2 * (L + 1)))
        large = x >= 1e3
        if large.any():
            u = 1 / x[large]
            phi[large] = x[large] + (0.5 + u * (-0.125 + u * (0.125 + u * (-25 / 128 + u * (13 / 32 + u * (-1073 / 1024))))))
    return phi


MASK64 = 0xffffffffffffffff


def mix64(x):
    """The SplitMix64 finalizer (Eq. (S3), src/sampling/README.md)."""
    x = (x + 0x9e3779b97f4a7c15) & MASK64
    x = ((x ^ (x >> 30)) * 0xbf58476d1ce4e5b9) & MASK64
    x = ((x ^ (x >> 27)) * 0x94d049bb133111eb) & MASK64
    return x ^ (x >> 31)


def derive_key(key, name):
    return mix64(key ^ fnv1a64(name))


def mt19937_64(seed, count):
    """The first `count` outputs of std::mt19937_64 seeded with `seed` (C++ [rand.eng.mers]),
    the twist vectorized in the three slices whose inputs are all known."""
    n, m, upper, lower = 312, 156, np.uint64(0xffffffff80000000), np.uint64(0x7fffffff)
    a = np.uint64(0xb5026f5aa96619e9)
    state = [seed & MASK64]
    for i in range(1, n):
        state.append((6364136223846793005 * (state[-1] ^ (state[-1] >> 62)) + i) & MASK64)
    state = np.array(state, dtype=np.uint64)
    one, zero = np.uint64(1), np.uint64(0)

    def step(x_i, x_next):
        y = (x_i & upper) | (x_next & lower)
        return (y >> one) ^ np.where((y & one) == one, a, zero)

    out = np.empty(((count + n - 1) // n, n), dtype=np.uint64)
    for block in out:
        old = state
        state = np.empty_like(old)
        state[:n - m] = old[m:] ^ step(old[:n - m], old[1:n - m + 1])
        state[n - m:n - 1] = state[:m - 1] ^ step(old[n - m:n - 1], old[n - m + 1:])
        state[n - 1] = state[m - 1] ^ step(old[n - 1:], state[:1])[0]
        y = state.copy()
        y ^= (y >> np.uint64(29)) & np.uint64(0x5555555555555555)
        y ^= (y << np.uint64(17)) & np.uint64(0x71d67fffeda60000)
        y ^= (y << np.uint64(37)) & np.uint64(0xfff7eee000000000)
        y ^= y >> np.uint64(43)
        block[:] = y
    return out.ravel()[:count]


def physics_rank_correlation(campaign, line_name):
    """Spearman of (k, h, d, d0) over forward-model tubes that hold their turgor.

    The tubes are drawn with the engine's documented generator and key (std::mt19937_64 seeded
    with derive_key(derive_key(mix64(seed), line), "physics_correlation"), p, E, h, d0 per tube,
    (bits >> 11) 2^-53), so both programs impose the same target and their results differ only
    by the sampling of the design, which the confidence intervals cover."""
    ph = campaign.physics
    key = derive_key(derive_key(mix64(campaign.seed), line_name), 'physics_correlation')
    u = (mt19937_64(key, 4 * ph['samples']) >> np.uint64(11)).astype(np.float64).reshape(-1, 4) * 2.0 ** -53
    drawn = []
    for j, name in enumerate(('p', 'E', 'h', 'd0')):
        low, high = ph[name]
        drawn.append(low * np.exp(u[:, j] * math.log(high / low)) if ph['log'] else low + (high - low) * u[:, j])
    p, E, h, d0 = drawn
    z = p / (2 * h * E) * d0
    hold = z <= 1 / math.e
    p, E, h, d0, z = p[hold], E[hold], h[hold], d0[hold], z[hold]
    ln_lambda = -special.lambertw(-z).real
    d = d0 * ln_lambda / z
    q = (1 - campaign.nu ** 2) * ln_lambda
    keep = q < 1
    alpha = d[keep] * np.sqrt(3 * q[keep] / (16 * (1 - q[keep])))
    k = 0.75 * math.pi * p[keep] * d[keep] * arnoldi_phi(campaign.rho / alpha)
    k = k / (1 + k / campaign.k_sys)
    return ['k', 'h', 'd', 'd0'], spearman_matrix([k, h[keep], d[keep], d0[keep]])


def evaluate(line, campaign, si):
    """The planned models on SI columns; returns SI outputs and statuses (kappa = 1)."""
    n = len(next(iter(si.values())))
    status = np.zeros(n, dtype=np.uint8)
    out = {}

    def flag(condition, code):
        status[(status == OK) & condition] = code

    def positive_finite(x):
        return np.isfinite(x) & (x > 0)

    with np.errstate(all='ignore'):
        for name, _, _ in line.plan:
            if name == 'turgor':
                k_m, d, d0 = si['k'], si['d'], si['d0']
                flag(~(positive_finite(k_m) & positive_finite(d) & positive_finite(d0)), INVALID)
                flag(k_m >= campaign.k_sys, SENSOR_LIMIT)
                k = k_m / (1 - k_m / campaign.k_sys)
                lam = d / d0
                flag(~(d > d0), LAMBDA_NOT_ABOVE_ONE)
                ln_lambda = np.log1p((d - d0) / d0)
                q = (1 - campaign.nu ** 2) * ln_lambda
                flag(~(q < 1), BEYOND_MEMBRANE)
                flag(ln_lambda > 1, UNSTABLE_BRANCH)  # past the hoop relation's pressure maximum
                alpha = d * np.sqrt(3 * q / (16 * (1 - q)))
                phi = arnoldi_phi(campaign.rho / alpha)
                p = 4 * k / (3 * math.pi * d * phi)
                flag(~(positive_finite(p) & positive_finite(k)), OUT_OF_RANGE)
                good = status == OK
                for key, value in (('lambda', lam), ('alpha', alpha), ('phi', phi), ('p', p)):
                    out[key] = np.where(good, value, np.nan)
                si['p'] = out['p']
            elif name == 'modulus':
                p, d, d0, h = si['p'], si['d'], si['d0'], si['h']
                flag(~(positive_finite(p) & positive_finite(d) & positive_finite(d0) & positive_finite(h)), INVALID)
                flag(~(d > d0), LAMBDA_NOT_ABOVE_ONE)
                ln_lambda = np.log1p((d - d0) / d0)
                flag(ln_lambda > 1, UNSTABLE_BRANCH)
                hoop = p * d / (2 * h)
                E = hoop / ln_lambda
                flag(~(positive_finite(hoop) & positive_finite(E) & positive_finite(E * h)), OUT_OF_RANGE)
                good = status == OK
                for key, value in (('E', E), ('hoop_stress', hoop), ('wall_stiffness', E * h)):
                    out[key] = np.where(good, value, np.nan)
                si['E'] = out['E']
            elif name == 'viscosity':
                tau, einf, E = si['tau'], si['einf'], si['E']
                flag(~(positive_finite(tau) & (einf >= 0) & (einf < 1) & positive_finite(E)), INVALID)
                eta = tau * (1 - einf) * E
                flag(~(np.isfinite(eta) & (eta >= np.finfo(float).tiny)), OUT_OF_RANGE)
                out['eta'] = np.where(status == OK, eta, np.nan)
                si['eta'] = out['eta']
            elif name == 'growth':
                p, d, eta, h = si['p'], si['d'], si['eta'], si['h']
                flag(~(np.isfinite(p) & (p >= 0) & positive_finite(d) & positive_finite(eta) & positive_finite(h)), INVALID)
                overpressure = p - campaign.p0
                no_growth = (status == OK) & ~(overpressure > 0)
                status[no_growth] = NO_GROWTH
                v = 0.25 * (overpressure / eta) * (d / h) * d
                flag(~(np.isfinite(v) & (v >= np.finfo(float).tiny)), OUT_OF_RANGE)
                v = np.where(status == OK, v, np.nan)
                v[no_growth] = 0.0  # a true zero, counted through the status
                out['v'] = v
    return out, status


# ---------------------------------------------------------------------------------------------
# Sampling (src/sampling/README.md and src/correlation/README.md)

def nearest_correlation(a, floor=1e-6, tolerance=1e-12, iterations=1000):
    """Higham (2002) alternating projections with Dykstra's correction, eigenvalues >= floor."""
    def psd(r):
        w, v = np.linalg.eigh(r)
        x = (v * np.maximum(w, floor)) @ v.T
        return 0.5 * (x + x.T)

    y, dykstra = a.copy(), np.zeros_like(a)
    for _ in range(iterations):
        r = y - dykstra
        x = psd(r)
        dykstra = x - r
        previous, y = y, x.copy()
        np.fill_diagonal(y, 1)
        if np.linalg.norm(y - previous) / np.linalg.norm(y) < tolerance and np.linalg.norm(y - x) / np.linalg.norm(y) < tolerance:
            break
    x = psd(y)
    s = 1 / np.sqrt(np.diag(x))
    y = x * np.outer(s, s)
    np.fill_diagonal(y, 1)
    return y


def line_target(line, campaign):
    """The m x m Spearman target over the sampled variables, or None."""
    names = [v.name for v in line.variables]
    if line.correlation == 'none':
        return None, []
    if line.correlation == 'physics':
        file_names, matrix = physics_rank_correlation(campaign, line.name)
    else:
        file_names, matrix = read_matrix_csv(line.correlation)
    keep = [i for i, name in enumerate(file_names) if name in names]
    if len(keep) < 2:
        return None, []
    spearman = np.eye(len(names))
    position = [names.index(file_names[i]) for i in keep]
    spearman[np.ix_(position, position)] = matrix[np.ix_(keep, keep)]
    rho = 2 * np.sin(np.pi * spearman / 6)
    np.fill_diagonal(rho, 1)
    warnings = []
    if np.linalg.eigvalsh(rho).min() < 1e-6:
        rho = nearest_correlation(rho)
        spearman = 6 / np.pi * np.arcsin(rho / 2)
        np.fill_diagonal(spearman, 1)
        warnings.append('the rank correlation target is not attainable: using the nearest correlation matrix')
    return (spearman, rho), warnings


def iman_conover(ranks, rho, warnings):
    """Reorders columns 1.. of `ranks` (m x n strata) so their normal scores correlate as rho."""
    m, n = ranks.shape
    if n <= m:
        warnings.append('a rank correlation cannot be imposed on this few samples; the design is uncorrelated')
        return
    scores = special.ndtri(np.arange(1, n + 1) / (n + 1))
    s = scores[ranks]  # m x n: the score of each sample's stratum
    t = (s @ s.T) / np.dot(scores, scores)
    try:
        q = np.linalg.cholesky(t)
    except np.linalg.LinAlgError:
        warnings.append("the samples' score correlation is singular; the design is uncorrelated")
        return
    p = np.linalg.cholesky(rho)
    mix = np.linalg.solve(q.T, p.T).T  # M = P Q^-1 from Q^T M^T = P^T
    mixed = mix @ s
    k = np.arange(n)
    for j in range(1, m):
        ranks[j, np.argsort(mixed[j])] = k


def design_line(line, campaign):
    """Strata ranks (m x n) and values (line-file units) of one line's correlated LHS."""
    n, m = campaign.samples, len(line.variables)
    target, warnings = line_target(line, campaign)
    rng = np.random.default_rng([campaign.seed, fnv1a64(line.name)])
    ranks = np.empty((m, n), dtype=np.int64)
    for j in range(m):
        ranks[j] = rng.permutation(n)
    if target is not None:
        iman_conover(ranks, target[1], warnings)
    values = np.empty((m, n))
    k = np.arange(n, dtype=np.float64)
    for j, variable in enumerate(line.variables):
        offset = 0.5 if campaign.centred else rng.random(n) + 2.0 ** -54  # in (0, 1)
        value_by_stratum = variable.quantile((k + offset) / n)
        values[j] = value_by_stratum[ranks[j]]
    return ranks, values, (target[0] if target is not None else None), warnings


# ---------------------------------------------------------------------------------------------
# Statistics

def ordinal_or_average_ranks(x, one_to_n):
    """Average ranks (1-based); argsort and a scatter when there are no ties (the usual case)."""
    order = np.argsort(x)
    sorted_x = x[order]
    if np.any(sorted_x[1:] == sorted_x[:-1]):
        return stats.rankdata(x)
    rank = np.empty(len(x))
    rank[order] = one_to_n
    return rank


def spearman_matrix(columns):
    """Spearman matrix of equally long 1-D columns, from average ranks."""
    n = len(columns[0])
    one_to_n = np.arange(1, n + 1, dtype=np.float64)
    centred = np.empty((len(columns), n))
    for j, x in enumerate(columns):
        centred[j] = ordinal_or_average_ranks(x, one_to_n)
    centred -= 0.5 * (n + 1)
    products = centred @ centred.T
    scale = np.sqrt(np.diag(products))
    result = products / np.outer(scale, scale)
    np.fill_diagonal(result, 1)
    return result


def spearman_of_strata(ranks):
    n = ranks.shape[1]
    r = ranks.astype(np.float64) - (n - 1) / 2
    c = r @ r.T
    d = np.sqrt(np.diag(c))
    result = c / np.outer(d, d)
    np.fill_diagonal(result, 1)
    return result


def median_confidence_ranks(n, level=0.95):
    """(lower, upper) 1-based order-statistic ranks of the distribution-free CI of the median."""
    tail = 0.5 * (1 - level)
    good, low, high = 0, 1, (n + 1) // 2
    while low <= high:
        mid = (low + high) // 2
        if stats.binom.cdf(mid - 1, n, 0.5) <= tail:
            good, low = mid, mid + 1
        else:
            high = mid - 1
    return (good, n + 1 - good) if good > 0 else None


def summarize(line, quantity, unit, values):
    # The engine's rule: every sample holding a value (NaN where the sample lacks the quantity).
    x = values[np.isfinite(values)]
    n = len(x)
    row = {'line': line, 'quantity': quantity, 'unit': unit, 'n': n, 'n_flagged': len(values) - n}
    keys = ['median', 'q1', 'q3', 'iqr', 'p10', 'p90', 'mean', 'sd', 'median_ci_low', 'median_ci_high']
    row.update({key: math.nan for key in keys})
    if n == 0:
        return row
    levels = {'p10': 0.10, 'q1': 0.25, 'median': 0.50, 'q3': 0.75, 'p90': 0.90}
    ci = median_confidence_ranks(n)
    positions = set()
    for level in levels.values():
        below = int(math.floor((n - 1) * level))
        positions.update((below, min(below + 1, n - 1)))
    if ci:
        positions.update((ci[0] - 1, ci[1] - 1))
    x = np.partition(x, sorted(positions))
    for key, level in levels.items():
        h = (n - 1) * level
        below = int(math.floor(h))
        row[key] = x[below] if below + 1 >= n else x[below] + (h - below) * (x[below + 1] - x[below])
    row['iqr'] = row['q3'] - row['q1']
    row['mean'] = x.mean()
    row['sd'] = x.std(ddof=1) if n > 1 else math.nan
    if ci:
        row['median_ci_low'], row['median_ci_high'] = x[ci[0] - 1], x[ci[1] - 1]
    return row


def analyze_line(columns, status):
    """Input/output Spearman and PCA of the standardized columns over samples with status ok."""
    used = status == OK
    analysis = {'samples_used': int(used.sum()), 'notes': [], 'inputs': [], 'outputs': [], 'pca_names': []}
    if analysis['samples_used'] < 3:
        analysis['notes'].append('fewer than 3 samples have status ok')
        return analysis
    kept = []
    for name, _, _, is_input, values in columns:
        x = values[used]
        if not np.all(np.isfinite(x)):
            analysis['notes'].append(f'{name} left out: a sample with status ok has no finite value')
        elif x.min() == x.max():
            analysis['notes'].append(f'{name} left out: constant over the samples used, so its correlations are undefined')
        else:
            kept.append((name, is_input, x))
    kept.sort(key=lambda c: not c[1])  # inputs first (stable)
    analysis['inputs'] = [name for name, is_input, _ in kept if is_input]
    analysis['outputs'] = [name for name, is_input, _ in kept if not is_input]
    analysis['pca_names'] = [name for name, _, _ in kept]
    data = [x for _, _, x in kept]
    spearman = spearman_matrix(data)
    ni = len(analysis['inputs'])
    analysis['input_output_spearman'] = spearman[:ni, ni:]
    correlation = np.corrcoef(np.array(data))
    eigenvalues, vectors = np.linalg.eigh(correlation)
    eigenvalues, vectors = np.maximum(eigenvalues[::-1], 0), vectors[:, ::-1]
    for c in range(vectors.shape[1]):
        magnitude = np.abs(vectors[:, c])
        first = np.argmax(magnitude >= magnitude.max() * (1 - 1e-10))
        if vectors[first, c] < 0:
            vectors[:, c] = -vectors[:, c]
    analysis['explained_variance_ratio'] = eigenvalues / eigenvalues.sum()
    analysis['loadings'] = vectors
    return analysis


# ---------------------------------------------------------------------------------------------
# Output

SUMMARY_FIELDS = ['line', 'quantity', 'unit', 'n', 'n_flagged', 'median', 'q1', 'q3', 'iqr', 'p10', 'p90', 'mean',
                  'sd', 'median_ci_low', 'median_ci_high']
SUMMARY_DTYPE = np.dtype([(f, h5py.string_dtype()) for f in SUMMARY_FIELDS[:3]] +
                         [(f, np.uint64) for f in SUMMARY_FIELDS[3:5]] + [(f, np.float64) for f in SUMMARY_FIELDS[5:]])
STRINGS = h5py.string_dtype()


def summary_table(rows):
    return np.array([tuple(row[f] for f in SUMMARY_FIELDS) for row in rows], dtype=SUMMARY_DTYPE)


def write_h5_line(h5, name, columns, status, rows, achieved, names, target, analysis):
    group = h5.create_group('lines/' + name)
    n = len(status)
    group.attrs.create('samples', n, dtype=np.uint64)
    for column, quantity, unit, is_input, values in columns:
        dataset = group.create_dataset(column, data=values, dtype=np.float64)
        dataset.attrs['quantity'] = quantity
        dataset.attrs['unit'] = unit
        dataset.attrs['role'] = 'input' if is_input else 'output'
    group.create_dataset('sample', data=np.arange(n, dtype=np.uint64))
    group.create_dataset('status', data=status).attrs.create('names', STATUS_NAMES, dtype=STRINGS)
    group.create_dataset('summary', data=summary_table(rows))
    correlation = group.create_group('input_rank_correlation')
    correlation.attrs.create('names', names, dtype=STRINGS)
    correlation.create_dataset('achieved', data=achieved)
    if target is not None:
        correlation.create_dataset('target', data=target)
    a = group.create_group('analysis')
    a.attrs.create('samples_used', analysis['samples_used'], dtype=np.uint64)
    a.attrs.create('notes', analysis['notes'], dtype=STRINGS)
    if 'loadings' in analysis:
        s = a.create_dataset('input_output_spearman', data=analysis['input_output_spearman'])
        s.attrs.create('rows', analysis['inputs'], dtype=STRINGS)
        s.attrs.create('columns', analysis['outputs'], dtype=STRINGS)
        a.create_dataset('explained_variance_ratio', data=analysis['explained_variance_ratio'])
        a.create_dataset('loadings', data=analysis['loadings']).attrs.create('rows', analysis['pca_names'], dtype=STRINGS)


def cell(value):
    if isinstance(value, str):
        return value if not any(c in value for c in ',"\n') else '"' + value.replace('"', '""') + '"'
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    return repr(float(value)) if math.isfinite(value) else ''


def short(value):
    return f'{value:.4g}' if math.isfinite(value) else '-'


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--campaign', default='campaigns/arabidopsis_2022.ini')
    parser.add_argument('--samples', type=int)
    parser.add_argument('--seed', type=int)
    parser.add_argument('--out')
    parser.add_argument('--force', action='store_true', help='reuse an existing output directory')
    parser.add_argument('--quiet', action='store_true', help='no summary table on stdout')
    args = parser.parse_args()
    start = time.perf_counter()
    campaign = Campaign(args.campaign, args.samples, args.seed, args.out)
    if os.path.exists(campaign.output_dir) and not args.force:
        sys.exit(f'{campaign.output_dir}: output directory already exists; choose another (--out DIR) or --force')
    os.makedirs(campaign.output_dir, exist_ok=True)
    h5_path = os.path.join(campaign.output_dir, 'results.h5')
    h5 = h5py.File(h5_path + '.partial', 'w')
    h5.create_group('lines')
    phase = dict.fromkeys(['design', 'evaluation', 'summaries+analysis', 'write'], 0.0)
    kappa, rows, reports = math.nan, [], []
    for line in campaign.lines:
        t0 = time.perf_counter()
        ranks, values, target, warnings = design_line(line, campaign)
        t1 = time.perf_counter()
        si = {v.name: values[j] * UNITS[v.unit][1] for j, v in enumerate(line.variables)}
        outputs, status = evaluate(line, campaign, si)
        if campaign.calibrates_kappa:
            if line.name == campaign.reference_line:
                kappa = campaign.experimental_median / np.median(outputs['v'][status == OK])
            v = outputs['v']
            ok = status == OK
            v[ok] *= kappa
            bad = ok & ~(np.isfinite(v) & (v >= np.finfo(float).tiny))
            v[bad], status[bad] = np.nan, OUT_OF_RANGE
        columns = [(column_name(v.name, v.unit), v.name, v.unit, True, values[j]) for j, v in enumerate(line.variables)]
        for output in campaign.computed_outputs:
            unit = DEFAULT_UNIT[output]
            columns.append((column_name(output, unit), output, unit, False, outputs[output] / UNITS[unit][1]))
        t2 = time.perf_counter()
        line_rows = [summarize(line.name, q, unit, x)
                     for output in campaign.outputs for _, q, unit, _, x in columns if q == output]
        achieved = spearman_of_strata(ranks) if campaign.samples >= 2 else np.zeros((0, 0))
        analysis = analyze_line(columns, status)
        rows += line_rows
        t3 = time.perf_counter()
        names = [v.name for v in line.variables]
        write_h5_line(h5, line.name, columns, status, line_rows, achieved, names, target, analysis)
        t4 = time.perf_counter()
        for key, seconds in zip(phase, (t1 - t0, t2 - t1, t3 - t2, t4 - t3)):
            phase[key] += seconds
        reports.append((line.name, names, target, achieved, analysis, warnings))
        del ranks, values, si, outputs, columns
    t0 = time.perf_counter()
    h5.create_dataset('summary', data=summary_table(rows))
    for key, value in (('campaign_text', campaign.text), ('campaign_path', campaign.path),
                       ('command_line', ' '.join(sys.argv)), ('engine_version', 'numpy peer')):
        h5.attrs[key] = value
    h5.attrs.create('seed', campaign.seed, dtype=np.uint64)
    h5.attrs.create('kappa', kappa, dtype=np.float64)
    h5.attrs.create('samples_per_line', campaign.samples, dtype=np.uint64)
    h5.close()
    os.replace(h5_path + '.partial', h5_path)
    with open(os.path.join(campaign.output_dir, 'summary.csv.partial'), 'w') as f:
        f.write(','.join(SUMMARY_FIELDS) + '\n')
        for row in rows:
            f.write(','.join(cell(row[field]) for field in SUMMARY_FIELDS) + '\n')
    os.replace(os.path.join(campaign.output_dir, 'summary.csv.partial'), os.path.join(campaign.output_dir, 'summary.csv'))
    phase['write'] += time.perf_counter() - t0
    total = time.perf_counter() - start
    if not args.quiet:
        print(f"campaign '{campaign.name}' (numpy peer): {len(campaign.lines)} lines x {campaign.samples} samples, "
              f"seed {campaign.seed}, results in {campaign.output_dir}\n")
        print(f"{'line':18}{'quantity':10}{'unit':8}{'median [95 % CI]':30}{'IQR':11}{'10-90 %':22}flagged")
        for r in rows:
            median = f"{short(r['median'])} [{short(r['median_ci_low'])}, {short(r['median_ci_high'])}]"
            print(f"{r['line']:18}{r['quantity']:10}{r['unit']:8}{median:30}{short(r['iqr']):11}"
                  f"{short(r['p10']) + ' - ' + short(r['p90']):22}{r['n_flagged']} of {r['n'] + r['n_flagged']}")
        if campaign.calibrates_kappa:
            print(f'\nkappa = {kappa!r} (calibrated on {campaign.reference_line})')
        with np.printoptions(precision=3, suppress=True, linewidth=150):
            for name, names, target, achieved, analysis, warnings in reports:
                print(f"\nline {name}: input rank correlation {names}\n  achieved\n{achieved}")
                if target is not None:
                    print(f'  target\n{target}')
                for warning in warnings:
                    print(f'  warning: {warning}')
                if 'loadings' in analysis:
                    print(f"  {analysis['samples_used']} samples with status ok; Spearman inputs {analysis['inputs']} x "
                          f"outputs {analysis['outputs']}\n{analysis['input_output_spearman']}")
                    print(f"  PCA explained variance {analysis['explained_variance_ratio']}\n  loadings "
                          f"(rows {analysis['pca_names']})\n{analysis['loadings']}")
                for note in analysis['notes']:
                    print(f'  note: {note}')
    print('peer phases (wall s): ' + ', '.join(f'{key} {value:.3f}' for key, value in phase.items()) +
          f', total {total:.3f}', file=sys.stderr)


if __name__ == '__main__':
    main()
