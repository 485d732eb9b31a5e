// Stability at the extremes: the thin-shell evaluators over a grid of the envelope of
// src/mechanics/README.md, edges included. Every output is finite or its sample carries a status,
// no exception leaves a batch, and each status appears exactly where the model says it must.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "growthuq/mechanics/thin_shell_evaluators.hpp"

using namespace growthuq;

namespace {

constexpr double um = 1e-6;
constexpr double nm = 1e-9;
constexpr double MPa = 1e6;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// Every output column of `block` is finite and positive for ok samples. A flagged sample has
// NaN in every column of the evaluator that flagged it and of later ones; columns written
// before (p when only h is bad) may hold their finite value.
void check_outputs(const SampleBlock& block, const std::vector<std::string>& outputs) {
  for (const std::string& name : outputs) {
    const std::span<const double> column = block.column(name);
    for (std::size_t i = 0; i < block.size(); ++i) {
      const bool flagged = block.status()[i] != SampleStatus::ok;
      if (!((std::isfinite(column[i]) && column[i] > 0) || (flagged && std::isnan(column[i])))) {
        CAPTURE(name);
        CAPTURE(i);
        CAPTURE(to_string(block.status()[i]));
        CHECK(column[i] > 0);
        CHECK(std::isfinite(column[i]));
      }
    }
  }
}

// The outputs of `names` are NaN for every sample whose status is `status`.
void check_empty(const SampleBlock& block, SampleStatus status, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    for (std::size_t i = 0; i < block.size(); ++i) {
      if (block.status()[i] == status) CHECK(std::isnan(block.column(name)[i]));
    }
  }
}

struct Inverse {
  double k, d, d0, h;
  SampleStatus expected;
};

}  // namespace

TEST_CASE("inverse evaluators over the envelope: a value or the status the model predicts") {
  // Stretch edges: 1 + 1e-12, the physiological range, just below and above e (the largest
  // stable stretch), q = 1 - 1e-12 (the largest membrane stretch: unstable_branch unless nu = 0,
  // where it is below e), just beyond it, no stretch and shrinkage; k 0.01-100 N/m plus stiffnesses
  // at and just below a 1000 N/m sensor; d 1-50 um; rho 0.01-10 um; nu 0-0.45; h 0.02-2 um; an
  // ideal sensor and a real one.
  const double sensor = 1e3;
  const std::vector<double> stiffnesses{0.01, 0.1, 0.5, 2.87, 10, 100, sensor * (1 - 1e-12), sensor, 2 * sensor};
  const std::vector<double> diameters{1 * um, 4 * um, 6.56 * um, 20 * um, 50 * um};
  const std::vector<double> thicknesses{20 * nm, 145 * nm, 2 * um};
  std::size_t swept = 0;
  for (double rho : {0.01 * um, 0.1 * um, 0.5 * um, 2 * um, 10 * um}) {
    for (double nu : {0.0, 0.2, 0.45}) {
      for (double k_sys : {inf, sensor}) {
        const std::vector<std::pair<double, SampleStatus>> stretches{
            {1 + 1e-12, SampleStatus::ok},
            {1.001, SampleStatus::ok},
            {1.02, SampleStatus::ok},
            {1.2, SampleStatus::ok},
            {1.4, SampleStatus::ok},
            {std::numbers::e * (1 - 1e-12), SampleStatus::ok},
            // nu = 0: q = ln(lambda) >= 1 is checked first, so the unstable window is empty.
            {std::numbers::e * (1 + 1e-12), nu == 0 ? SampleStatus::beyond_membrane_limit : SampleStatus::unstable_branch},
            {std::exp((1 - 1e-12) / (1 - nu * nu)), nu == 0 ? SampleStatus::ok : SampleStatus::unstable_branch},
            {std::exp(1 / (1 - nu * nu)) * (1 + 1e-12), SampleStatus::beyond_membrane_limit},
            {1.0, SampleStatus::lambda_not_above_one},
            {0.9, SampleStatus::lambda_not_above_one},
        };
        std::vector<Inverse> grid;
        for (double k : stiffnesses) {
          for (double d : diameters) {
            for (const auto& [lambda, status] : stretches) {
              for (double h : thicknesses) {
                const SampleStatus expected = k >= k_sys ? SampleStatus::stiffness_at_sensor_limit : status;
                grid.push_back({k, d, d / lambda, h, expected});
              }
            }
          }
        }
        // Inputs outside the physical domain.
        grid.push_back({not_a_number, 6 * um, 5 * um, 145 * nm, SampleStatus::invalid_input});
        grid.push_back({0, 6 * um, 5 * um, 145 * nm, SampleStatus::invalid_input});
        grid.push_back({2, -6 * um, 5 * um, 145 * nm, SampleStatus::invalid_input});
        grid.push_back({2, 6 * um, inf, 145 * nm, SampleStatus::invalid_input});
        grid.push_back({2, 6 * um, 5 * um, -1 * nm, SampleStatus::invalid_input});
        grid.push_back({2, 6 * um, 5 * um, not_a_number, SampleStatus::invalid_input});

        Instrument parameters;
        parameters.probe_radius_m = rho;
        parameters.poisson_ratio = nu;
        parameters.sensor_stiffness_N_per_m = k_sys;
        const ThinShellTurgor turgor(parameters, "sweep");
        const ThinShellModulus modulus;
        SampleBlock block(grid.size());
        std::vector<double> k, d, d0, h;
        for (const Inverse& point : grid) {
          k.push_back(point.k);
          d.push_back(point.d);
          d0.push_back(point.d0);
          h.push_back(point.h);
        }
        block.set_column("k", k);
        block.set_column("d", d);
        block.set_column("d0", d0);
        block.set_column("h", h);
        CHECK_NOTHROW(turgor.evaluate(block));
        CHECK_NOTHROW(modulus.evaluate(block));
        const std::vector<std::string> turgor_outputs{"lambda", "alpha", "phi", "p"};
        const std::vector<std::string> modulus_outputs{"E", "hoop_stress", "wall_stiffness"};
        check_outputs(block, turgor_outputs);
        check_outputs(block, modulus_outputs);
        for (SampleStatus status : {SampleStatus::lambda_not_above_one, SampleStatus::beyond_membrane_limit,
                                    SampleStatus::unstable_branch, SampleStatus::stiffness_at_sensor_limit}) {
          check_empty(block, status, {"lambda", "alpha", "phi", "p"});
        }
        // invalid_input comes from either evaluator (a bad k or a bad h); the modulus is empty.
        for (SampleStatus status : {SampleStatus::lambda_not_above_one, SampleStatus::beyond_membrane_limit,
                                    SampleStatus::unstable_branch, SampleStatus::stiffness_at_sensor_limit,
                                    SampleStatus::invalid_input}) {
          check_empty(block, status, modulus_outputs);
        }
        for (std::size_t i = 0; i < grid.size(); ++i) {
          const Inverse& point = grid[i];
          if (block.status()[i] != point.expected) {
            CAPTURE(point.k);
            CAPTURE(point.d);
            CAPTURE(point.d / point.d0);
            CAPTURE(point.h);
            CAPTURE(rho);
            CAPTURE(nu);
            CAPTURE(k_sys);
            CHECK(to_string(block.status()[i]) == to_string(point.expected));
          }
        }
        swept += grid.size();
      }
    }
  }
  CHECK(swept >= 10000);
}

TEST_CASE("forward evaluator over the envelope: a value, burst exactly when c d0 > 1/e") {
  const std::vector<double> pressures{0.01 * MPa, 0.1 * MPa, 0.3 * MPa, 0.8 * MPa, 2 * MPa};
  const std::vector<double> moduli{1 * MPa, 5 * MPa, 50 * MPa, 200 * MPa, 1000 * MPa};
  const std::vector<double> thicknesses{20 * nm, 100 * nm, 500 * nm, 2 * um};
  const std::vector<double> diameters{1 * um, 4 * um, 10 * um, 50 * um};
  std::size_t swept = 0;
  std::size_t burst = 0;
  for (double rho : {0.01 * um, 0.5 * um, 10 * um}) {
    for (double nu : {0.0, 0.2, 0.45}) {
      Instrument parameters;
      parameters.probe_radius_m = rho;
      parameters.poisson_ratio = nu;
      const ThinShellForward forward(parameters, "sweep");
      std::vector<double> p, E, h, d0;
      for (double p_i : pressures) {
        for (double E_i : moduli) {
          for (double h_i : thicknesses) {
            for (double d0_i : diameters) {
              p.push_back(p_i);
              E.push_back(E_i);
              h.push_back(h_i);
              d0.push_back(d0_i);
            }
          }
        }
      }
      // The burst limit itself, from both sides: c d0 = 1/e within 1e-12.
      for (double side : {1 - 1e-12, 1 + 1e-12}) {
        p.push_back(2 * 100 * nm * 50 * MPa / (std::numbers::e * 5 * um) * side);
        E.push_back(50 * MPa);
        h.push_back(100 * nm);
        d0.push_back(5 * um);
      }
      SampleBlock block(p.size());
      block.set_column("p", p);
      block.set_column("E", E);
      block.set_column("h", h);
      block.set_column("d0", d0);
      CHECK_NOTHROW(forward.evaluate(block));
      check_outputs(block, {"d", "k"});
      for (std::size_t i = 0; i < block.size(); ++i) {
        const double c_d0 = p[i] / (2 * h[i] * E[i]) * d0[i];
        const SampleStatus status = block.status()[i];
        if (c_d0 > 1 / std::numbers::e) {
          CHECK(status == SampleStatus::burst);
          ++burst;
        } else {
          CAPTURE(c_d0);
          CHECK(status == SampleStatus::ok);
          CHECK(block.column("d")[i] > d0[i]);
          CHECK(block.column("d")[i] <= std::numbers::e * d0[i] * (1 + 1e-15));
        }
      }
      swept += block.size();
    }
  }
  CHECK(swept >= 2000);
  CHECK(burst > 0);
}
