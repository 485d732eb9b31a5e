// The Arabidopsis-like tube the tests of the public finite-element API share: d0 = 5.35 um,
// turgid h = 200 nm, p = 0.45 MPa, E = 45 MPa (p/E = 0.01, d/d0 about 1.18), rho = 0.25 um, nu =
// 0.2: k about 2.2 N/m, so the curve reaches the window's top (4 uN) near 1.9 um on the coarse
// mesh, shallower than 0.45 d0 = 2.4 um.
#pragma once

#include "growthuq/fe/indentation.hpp"

namespace growthuq::testing {

inline IndentationInput arabidopsis_like() {
  IndentationInput input;
  input.pressure = 0.45e6;
  input.young = 45e6;
  input.thickness = 200e-9;
  input.plasmolysed_diameter = 5.35e-6;
  input.instrument.probe_radius_m = 0.25e-6;
  input.instrument.poisson_ratio = 0.2;
  return input;
}

}  // namespace growthuq::testing
