// The Arnoldi factor phi(x) = x K1(x) / K0(x) of the apparent stiffness of a pressurized
// cylinder under a probe (Arnoldi et al. 2000; Eqs. (M2), (M4), src/mechanics/README.md), and its
// inverse. Both are accurate to a few ulp over all positive doubles and never throw.
#pragma once

namespace growthuq {

// phi(x) = x K1(x) / K0(x), x = rho / alpha (probe radius over decay length).
// Strictly increasing from phi(0) = 0 (phi ~ 1 / (ln(2/x) - gamma_Euler) as x -> 0, so
// phi(1e-300) is still 1.4e-3) to phi ~ x + 1/2 - 1/(8x) for large x.
// GSL's exponentially scaled Bessel functions for 1e-5 <= x < 1e3, the small-x series below
// and the Hankel expansion above. Within 1e-14 relative of 50-digit values for
// 1e-300 <= x <= 1e10 (tested), finite for every finite x >= 0 (subnormal x included).
// NaN for x < 0 or NaN; +inf for x = +inf. Thread-safe, ~130 ns.
double arnoldi_phi(double x);

// The x >= 0 with arnoldi_phi(x) == phi: defined for every phi >= 0 (phi = 0 gives 0,
// phi = +inf gives +inf); NaN for phi < 0 or NaN. Because phi -> 0 only logarithmically,
// phi below arnoldi_phi(DBL_MIN) = 1.4114e-3 maps to a subnormal x, and below
// arnoldi_phi(denorm_min) = 1.3431e-3 to 0 (underflow: the decay length rho/x is beyond
// double range; rho^2/alpha^2 = x^2 is then 0 to double precision).
// A monotone 1-D root (GSL Brent on ln x) bracketed by x < phi(x) < x + 1/2, polished by one
// Newton step, with closed forms where the small-x series (phi < phi(1e-20)) or the large-x
// expansion (phi > 1e8) is exact in double. phi(inverse(phi)) == phi to 8 ulp; ~2 us.
double arnoldi_phi_inverse(double phi);

// d phi / dx = (phi^2 - x^2) / x (from K0' = -K1, K1' = -K0 - K1/x), > 0 for every x > 0.
double arnoldi_phi_derivative(double x);

}  // namespace growthuq
