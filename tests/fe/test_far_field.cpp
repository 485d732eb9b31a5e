// The far field of a closed-end tube: equilibrium substituted back through the element's own law
// (material_law.hpp, an independent code path) and through Hooke's law of the log strain, the
// small-strain limit, the engine's hoop relation (cauchy_log, nu = 0), the pressure maximum, and
// the inverse as the forward's round trip.
#include <doctest/doctest.h>

#include <cmath>

#include "fe/far_field.hpp"
#include "fe/material_law.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

using namespace growthuq::fe;
using growthuq::SampleStatus;
using growthuq::ShellFeLaw;

namespace {

constexpr FarFieldLaw all_laws[] = {FarFieldLaw::saint_venant_kirchhoff, FarFieldLaw::hencky, FarFieldLaw::cauchy_log};

// Residuals of sigma_t = p r / h and sigma_z = p r / (2h) (relative to p r / h), with the Cauchy
// stresses formed from the law: St-VK and Hencky through the membrane energy's S = 2 dW/dC at
// C = diag(l_t^2, l_z^2) (sigma_i = l_i^2 S_i / (J_2 h), J_2 = l_t l_z), cauchy_log directly.
std::pair<double, double> equilibrium_residuals(FarFieldLaw law, double p, double h0, double nu,
                                                const FarFieldInflation& s) {
  const double r = 0.5 * s.hoop_stretch, h = s.thickness_stretch * h0;
  double sigma_t, sigma_z;
  if (law == FarFieldLaw::cauchy_log) {
    const double et = std::log(s.hoop_stretch), ez = std::log(s.axial_stretch);
    sigma_t = (et + nu * ez) / (1 - nu * nu);
    sigma_z = (ez + nu * et) / (1 - nu * nu);
  } else {
    WallMaterial m;
    m.law = law == FarFieldLaw::hencky ? ShellFeLaw::hencky : ShellFeLaw::saint_venant_kirchhoff;
    m.poisson = nu;
    m.thickness = h0;
    const Eigen::Matrix2d stress =
        second_piola_kirchhoff(m, Eigen::Vector3d(s.hoop_stretch * s.hoop_stretch, s.axial_stretch * s.axial_stretch, 0));
    const double area_ratio = s.hoop_stretch * s.axial_stretch;
    sigma_t = s.hoop_stretch * s.hoop_stretch * stress(0, 0) / (area_ratio * h);
    sigma_z = s.axial_stretch * s.axial_stretch * stress(1, 1) / (area_ratio * h);
  }
  const double scale = p * r / h;
  return {std::fabs(sigma_t - scale) / scale, std::fabs(sigma_z - 0.5 * scale) / scale};
}

}  // namespace

TEST_CASE("far field: equilibrium substituted back, over the envelope of p/E and h0/d0") {
  // The root is solved to 1e-15 in the hoop stretch, which carries the strain l - 1 to ~1e-16
  // absolute: the stresses' relative residual is then ~1e-16/(l - 1) plus rounding ~1e-14.
  for (FarFieldLaw law : all_laws) {
    for (double nu : {0.0, 0.2, 0.45}) {
      const FarFieldState peak = far_field_pressure_maximum(law, nu);
      for (double h0 : {0.004, 0.03, 0.2}) {
        for (double fraction : {1e-6, 0.01, 0.3, 0.9, 0.999}) {
          if (law == FarFieldLaw::saint_venant_kirchhoff && nu > 0 && fraction > 0.3) continue;  // thickness collapse
          const double p = fraction * std::fmin(peak.pressure_group, 2.0) * h0;
          const FarFieldInflation s = far_field_inflation(law, p, h0, nu);
          REQUIRE_FALSE(s.burst);
          REQUIRE(s.thickness_stretch > 0);
          const auto [hoop, axial] = equilibrium_residuals(law, p, h0, nu, s);
          const double tolerance = 1e-13 + 1e-15 / (s.hoop_stretch - 1);
          CHECK(hoop < tolerance);
          CHECK(axial < tolerance);
        }
      }
    }
  }
}

TEST_CASE("far field: the small-strain limit of closed-end pressure") {
  // Linear thin shell with closed ends: eps_t = (p r/(E h)) (1 - nu/2), eps_z = (p r/(E h))
  // (1/2 - nu). At a strain of ~2.5e-6 the nonlinear laws differ from it by O(strain) relative.
  for (FarFieldLaw law : all_laws) {
    for (double nu : {0.0, 0.2, 0.4}) {
      const double h0 = 0.02, p = 1e-7;
      const FarFieldInflation s = far_field_inflation(law, p, h0, nu);
      const double hoop_strain = p * 0.5 / h0;
      CHECK(s.hoop_stretch - 1 == doctest::Approx(hoop_strain * (1 - nu / 2)).epsilon(1e-5));
      if (nu != 0.5) CHECK(s.axial_stretch - 1 == doctest::Approx(hoop_strain * (0.5 - nu)).epsilon(1e-5));
      CHECK(s.thickness_stretch - 1 == doctest::Approx(-nu / (1 - nu) * hoop_strain * (1.5 - 1.5 * nu)).epsilon(1e-5));
    }
  }
}

TEST_CASE("far field: cauchy_log at nu = 0 is the engine's hoop relation p d/(2h) = E ln(d/d0)") {
  // thin_shell_forward solves it with Lambert W (SI units): d0 = 5.35 um, E = 20 MPa.
  growthuq::Instrument parameters;
  parameters.probe_radius_m = 0.25e-6;
  parameters.poisson_ratio = 0.0;
  const double d0 = 5.35e-6, E = 20e6;
  for (double h : {0.1e-6, 0.145e-6, 0.5e-6}) {
    for (double p : {0.05e6, 0.3e6, 0.6e6}) {
      const growthuq::ForwardResult closed = growthuq::thin_shell_forward(p, E, h, d0, parameters);
      if (closed.status != growthuq::SampleStatus::ok) continue;
      const FarFieldInflation s = far_field_inflation(FarFieldLaw::cauchy_log, p / E, h / d0, 0.0);
      CHECK(s.hoop_stretch == doctest::Approx(closed.lambda).epsilon(1e-12));
      CHECK(s.thickness_stretch == 1.0);
    }
  }
  // Its burst: c d0 = 1/e, i.e. G = p d0/(E h0) = 2/e at lambda = e.
  const FarFieldState peak = far_field_pressure_maximum(FarFieldLaw::cauchy_log, 0.0);
  CHECK(peak.hoop_stretch == doctest::Approx(std::exp(1.0)).epsilon(1e-15));
  CHECK(peak.pressure_group == doctest::Approx(2 / std::exp(1.0)).epsilon(1e-15));
}

TEST_CASE("far field: the pressure maximum and burst") {
  for (FarFieldLaw law : {FarFieldLaw::hencky, FarFieldLaw::cauchy_log}) {
    for (double nu : {0.0, 0.2, 0.45}) {
      const FarFieldState peak = far_field_pressure_maximum(law, nu);
      // A maximum of G: lower on both sides.
      CHECK(far_field_state(law, peak.hoop_stretch * (1 - 1e-4), nu).pressure_group < peak.pressure_group);
      CHECK(far_field_state(law, peak.hoop_stretch * (1 + 1e-4), nu).pressure_group < peak.pressure_group);
      const double h0 = 0.03;
      CHECK(far_field_inflation(law, 1.001 * peak.pressure_group * h0, h0, nu).burst);
      const FarFieldInflation below = far_field_inflation(law, 0.999 * peak.pressure_group * h0, h0, nu);
      CHECK_FALSE(below.burst);
      CHECK(below.hoop_stretch < peak.hoop_stretch);
    }
  }
  // St-VK's membrane has no pressure maximum below hoop stretch 20.
  const FarFieldState stvk = far_field_pressure_maximum(FarFieldLaw::saint_venant_kirchhoff, 0.2);
  CHECK(stvk.hoop_stretch == 20.0);
  CHECK(stvk.thickness_stretch == 0.0);  // collapsed long before
}

TEST_CASE("far field: the inverse is the forward's round trip, and its statuses") {
  for (FarFieldLaw law : all_laws) {
    for (double nu : {0.0, 0.2, 0.4}) {
      for (double lambda : {1.001, 1.05, 1.2261, 1.4}) {
        const double h = 0.145 / 5.35;
        const FarFieldInverse inverse = far_field_inverse(law, lambda, h, nu);
        if (inverse.status != FarFieldInverseStatus::ok) {
          CHECK(law == FarFieldLaw::saint_venant_kirchhoff);  // only its thickness can collapse here
          CHECK(inverse.status == FarFieldInverseStatus::thickness_collapsed);
          continue;
        }
        const FarFieldInflation forward = far_field_inflation(law, inverse.pressure_over_E, inverse.h0_over_d0, nu);
        CHECK(forward.hoop_stretch == doctest::Approx(lambda).epsilon(1e-12));
        CHECK(forward.thickness_stretch * inverse.h0_over_d0 == doctest::Approx(h).epsilon(1e-12));
      }
    }
  }
  CHECK(far_field_inverse(FarFieldLaw::hencky, 0.99, 0.03, 0.2).status == FarFieldInverseStatus::not_stretched);
  CHECK(far_field_inverse(FarFieldLaw::hencky, 1.7, 0.03, 0.2).status == FarFieldInverseStatus::beyond_pressure_maximum);
  CHECK(far_field_inverse(FarFieldLaw::hencky, NAN, 0.03, 0.2).status == FarFieldInverseStatus::invalid_input);
  CHECK(far_field_inverse(FarFieldLaw::hencky, 1.2, -1, 0.2).status == FarFieldInverseStatus::invalid_input);
  CHECK(far_field_inverse(FarFieldLaw::hencky, 1.2, 0.03, 0.5).status == FarFieldInverseStatus::invalid_input);
}

TEST_CASE("far field: inflation to a given turgid thickness inverts the inverse, up to the pressure maximum") {
  // From (d/d0, turgid h/d0) the inverse gives p/E and h0 without a root; the inflation to the
  // turgid h at that p/E must find them again, also just below the pressure maximum, where a
  // fixed point h0 <- h / lambda_3(p/E, h0) started at h0 = h lands beyond the maximum.
  const double h = 0.145 / 5.35;
  for (FarFieldLaw law : all_laws) {
    for (double nu : {0.0, 0.2, 0.4}) {
      const double peak = far_field_pressure_maximum(law, nu).hoop_stretch;
      for (double lambda : {1.001, 1.05, 1.2261, 1.4, 1.0 + 0.999 * (std::fmin(peak, 1.6) - 1.0)}) {
        const FarFieldInverse inverse = far_field_inverse(law, lambda, h, nu);
        if (inverse.status != FarFieldInverseStatus::ok) continue;  // St-VK's collapsed thickness
        const FarFieldTurgidInflation forward = far_field_inflation_to_turgid_thickness(law, inverse.pressure_over_E, h, nu);
        REQUIRE_FALSE(forward.inflation.burst);
        CHECK(forward.inflation.hoop_stretch == doctest::Approx(lambda).epsilon(1e-10));
        CHECK(forward.h0_over_d0 == doctest::Approx(inverse.h0_over_d0).epsilon(1e-10));
      }
    }
  }
  // A wall already thinner than the pressure maximum's at this p/E: burst, h0 = 0.
  const FarFieldState peak = far_field_pressure_maximum(FarFieldLaw::hencky, 0.2);
  const double thinnest = 0.01 * peak.thickness_stretch / peak.pressure_group;
  CHECK(far_field_inflation_to_turgid_thickness(FarFieldLaw::hencky, 0.01, 0.999 * thinnest, 0.2).inflation.burst);
  CHECK_FALSE(far_field_inflation_to_turgid_thickness(FarFieldLaw::hencky, 0.01, 1.001 * thinnest, 0.2).inflation.burst);
  // No pressure, no stretch.
  CHECK(far_field_inflation_to_turgid_thickness(FarFieldLaw::hencky, 0.0, h, 0.2).inflation.hoop_stretch == 1.0);
}

TEST_CASE("far field: the three laws at the study's stretch (d/d0 = 6.56/5.35, h = 145 nm, nu = 0.2)") {
  // Hencky and cauchy_log share the kinematics (eps_z = kappa eps_t, the same eps_3) and differ
  // only in which stress is Hooke's law of the log strain: Cauchy = Kirchhoff / J, so cauchy_log
  // needs exactly J = l_t l_z l_3 times Hencky's pressure. St-VK's 2nd PK stress grows with
  // (l^2 - 1)/2 > ln l and its Cauchy stress with a further l^2/J, so it needs the most.
  // Values: St-VK 1.5486e-2, Hencky 8.1678e-3, cauchy_log 1.0015e-2; the engine's
  // closed-form hoop relation (nu = 0, no thickness change) 9.0136e-3.
  const double lambda = 6.56 / 5.35, h = 0.145 / 5.35, nu = 0.2;
  FarFieldInverse inverse[3];
  for (int i = 0; i < 3; ++i) {
    inverse[i] = far_field_inverse(all_laws[i], lambda, h, nu);
    REQUIRE(inverse[i].status == FarFieldInverseStatus::ok);
  }
  const double volume_ratio = lambda * inverse[1].axial_stretch * inverse[1].thickness_stretch;
  CHECK(inverse[2].pressure_over_E == doctest::Approx(volume_ratio * inverse[1].pressure_over_E).epsilon(1e-14));
  CHECK(inverse[2].axial_stretch == inverse[1].axial_stretch);
  CHECK(inverse[0].pressure_over_E > inverse[2].pressure_over_E);
  CHECK(inverse[0].pressure_over_E == doctest::Approx(1.5486e-2).epsilon(1e-4));
  CHECK(inverse[1].pressure_over_E == doctest::Approx(8.1678e-3).epsilon(1e-4));
}
