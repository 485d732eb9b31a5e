// The one wall viscosity of the engine (Eq. (R7), src/relaxation/README.md; Eq. (G1),
// src/growth/README.md): `growthuq relax` and raw-data campaigns per curve (E = E_r(0)), the
// viscosity evaluator per sample of a distribution campaign (E = the sample's modulus).
#pragma once

namespace growthuq {

// eta = tau (1 - e_inf) E [Pa s] (SI: tau in s, e_inf = E_inf/E_r(0) as a fraction, E in Pa).
// The slow Maxwell branch relaxes with time constant tau, its amplitude E0 = (1 - e_inf) E the
// modulus that relaxes: the only E0 the published laws of tau and e_inf determine. No
// validation: see the evaluator (growth/viscosity.hpp) and the fit (relaxation/analysis.hpp).
inline double relaxation_viscosity(double tau, double einf, double modulus) noexcept {
  return tau * (1.0 - einf) * modulus;
}

}  // namespace growthuq
