// The far field of a long closed-end tube under internal pressure: the uniform membrane state
// (hoop and axial equilibrium, plane stress through the wall) far from the tip and the ends, for
// the two laws of the shell model and for the commercial code's Cauchy = Hooke(log strain) law,
// with its inverse (measured turgid d/d0 and h/d0 -> p/E and h0/d0). Dimensionless: d0 = 1.
//
// Equilibrium (r = lambda_t d0/2, h = lambda_3 h0 current): sigma_t = p r / h, sigma_z = p r/(2h),
// sigma_3 = 0. In the laws' own stresses, with G = p d0 / (E h0):
//   saint_venant_kirchhoff: S_t = G lambda_z / 2,              S_z = G lambda_t^2 / (4 lambda_z)
//   hencky (Kirchhoff tau):  tau_t = G lambda_t^2 lambda_z / 2, tau_z = tau_t / 2
//   cauchy_log (Cauchy):     sigma_t lambda_3 = G lambda_t / 2, sigma_z = sigma_t / 2
// (the first two are also the stationarity conditions of the membrane energy minus p V, so the
// shell model's inflated tube tends to exactly this state). The ratio of the two equations does
// not contain G, which gives lambda_z(lambda_t) in closed form (Hencky and cauchy_log:
// eps_z = (1 - 2 nu)/(2 - nu) eps_t; St-VK: a quadratic in lambda_z^2); the hoop equation then
// gives G(lambda_t) explicitly. So the 2-D solve is one bracketed 1-D root (GSL Brent) on the
// rising branch of G, and the inverse needs no root at all.
//
// Burst: G(lambda_t) has a maximum for both log laws, at ln lambda_t = 1/(2 + kappa) (hencky) and
// 1/(1 + beta) (cauchy_log), kappa = (1 - 2 nu)/(2 - nu), beta = nu (1 + kappa)/(1 - nu); beyond
// it no equilibrium exists. For St-VK G rises without bound (no burst within hoop stretch 20,
// the search limit), but its plane-stress thickness vanishes where E_t + E_z = (1 - nu)/(2 nu):
// the thickness stretch is reported 0 there (see material_law.hpp).
#pragma once

#include "fe/material_law.hpp"

namespace growthuq::fe {

enum class FarFieldLaw { saint_venant_kirchhoff, hencky, cauchy_log };
FarFieldLaw far_field_law(ShellFeLaw law);

struct FarFieldInflation {
  double hoop_stretch, axial_stretch, thickness_stretch;
  bool burst;  // no equilibrium at this pressure: the stretches are those at the pressure maximum
};

// p/E >= 0, h0/d0 > 0, 0 <= nu < 1/2 (not validated here: the caller's options are).
FarFieldInflation far_field_inflation(FarFieldLaw law, double pressure_over_E, double h0_over_d0, double nu);

// The far-field state at a given hoop stretch (>= 1), and the group G = p d0/(E h0) it needs.
struct FarFieldState {
  double hoop_stretch, axial_stretch, thickness_stretch, pressure_group;
};
FarFieldState far_field_state(FarFieldLaw law, double hoop_stretch, double nu);

// The state at the pressure maximum (burst), or at the search limit (hoop stretch 20) if G is
// still rising there (St-VK).
FarFieldState far_field_pressure_maximum(FarFieldLaw law, double nu);

// Inflation at a given p/E of a wall whose *turgid* thickness h/d0 is given (h0 unknown): the hoop
// stretch l on the rising branch of G where h0 = (p/E) / G(l) thins to h, i.e.
// (p/E) lambda_3(l) / G(l) = h/d0. The left side falls from infinity at l = 1 to its least value
// at the pressure maximum (G rises, lambda_3 falls), so one bracketed root (GSL Brent) or none:
// `burst` when even the pressure maximum leaves the wall thicker than h. h0_over_d0 is 0 then.
struct FarFieldTurgidInflation {
  FarFieldInflation inflation;
  double h0_over_d0;
};
FarFieldTurgidInflation far_field_inflation_to_turgid_thickness(FarFieldLaw law, double pressure_over_E,
                                                                double h_over_d0, double nu);

// Inverse: measured turgid d/d0 and turgid h/d0 -> p/E and h0/d0 (h0 = h / lambda_3,
// p/E = G h0/d0).
enum class FarFieldInverseStatus {
  ok,
  invalid_input,            // non-finite or non-positive d/d0 or h/d0, nu outside [0, 1/2)
  not_stretched,            // d/d0 <= 1: no positive pressure gives it
  beyond_pressure_maximum,  // d/d0 past the burst stretch: an unstable state
  thickness_collapsed       // St-VK: the plane-stress thickness has vanished at this stretch
};
struct FarFieldInverse {
  double pressure_over_E = 0, h0_over_d0 = 0, axial_stretch = 0, thickness_stretch = 0;
  FarFieldInverseStatus status = FarFieldInverseStatus::ok;
};
FarFieldInverse far_field_inverse(FarFieldLaw law, double d_over_d0, double h_over_d0, double nu);

}  // namespace growthuq::fe
