// Rank correlation of (k, h, d, d0) from the forward thin-shell model (Eq. (M16),
// src/mechanics/README.md).
#include "growthuq/mechanics/mechanical_correlation.hpp"

#include <cmath>
#include <span>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/mechanics/thin_shell_evaluators.hpp"
#include "growthuq/sampling/random_stream.hpp"
#include "growthuq/stats/rank_correlation.hpp"

namespace growthuq {
namespace {

void check_range(const DrawRange& range, std::string_view location, std::string_view key, double unit) {
  if (std::isfinite(range.low) && std::isfinite(range.high) && range.low > 0 && range.low < range.high) return;
  throw_bad_value(location, key, format_double(range.low / unit) + ":" + format_double(range.high / unit),
                  "LOW:HIGH with 0 < LOW < HIGH");
}

double draw(const DrawRange& range, DrawScale scale, double u) {
  if (scale == DrawScale::log_uniform) return range.low * std::exp(u * std::log(range.high / range.low));
  return range.low + (range.high - range.low) * u;
}

}  // namespace

void validate(const MechanicalDrawOptions& options, std::string_view location) {
  check_range(options.p, location, "p_MPa", unit_factor::MPa);
  check_range(options.E, location, "E_MPa", unit_factor::MPa);
  check_range(options.h, location, "h_nm", unit_factor::nm);
  check_range(options.d0, location, "d0_um", unit_factor::um);
  if (options.samples < 3) {
    throw_bad_value(location, "samples", std::to_string(options.samples), "at least 3 samples");
  }
}

SampleBlock draw_mechanical_samples(const MechanicalDrawOptions& options) {
  const std::size_t n = options.samples;
  SampleBlock block(n);
  const std::span<double> p = block.add_column("p");
  const std::span<double> E = block.add_column("E");
  const std::span<double> h = block.add_column("h");
  const std::span<double> d0 = block.add_column("d0");
  RandomStream stream(options.seed);
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = draw(options.p, options.scale, stream.uniform());
    E[i] = draw(options.E, options.scale, stream.uniform());
    h[i] = draw(options.h, options.scale, stream.uniform());
    d0[i] = draw(options.d0, options.scale, stream.uniform());
  }
  return block;
}

MechanicalCorrelation mechanical_rank_correlation(const MechanicalDrawOptions& options,
                                                  const Instrument& shell,
                                                  std::string_view location) {
  validate(options, location);
  // The draws carry no probe radius column: a campaign's law of rho enters through its median,
  // which the instrument holds (instrument.hpp).
  Instrument one_radius = shell;
  one_radius.probe_radius_per_sample = false;
  const ThinShellForward forward(one_radius, location);
  SampleBlock block = draw_mechanical_samples(options);
  forward.evaluate(block);

  MechanicalCorrelation result;
  result.drawn = block.size();
  std::array<std::vector<double>, 4> kept;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const SampleStatus status = block.status()[i];
    if (status == SampleStatus::burst) {
      ++result.burst;
    } else if (status != SampleStatus::ok) {
      ++result.other_dropped;
    } else {
      for (std::size_t j = 0; j < kept.size(); ++j) kept[j].push_back(block.column(result.names[j])[i]);
    }
  }
  result.kept = kept[0].size();
  if (result.kept < 3) {
    throw InputError(std::string(location),
                     std::to_string(result.kept) + " of " + std::to_string(result.drawn) +
                         " drawn tubes hold their turgor (" + std::to_string(result.burst) +
                         " burst: p d0 / (2 h E) > 1/e): lower the turgor range or raise the modulus or thickness");
  }
  std::vector<std::span<const double>> columns(kept.begin(), kept.end());
  try {
    result.spearman = spearman_matrix(columns);
  } catch (const InputError& error) {
    throw InputError(std::string(location), "the kept samples give no rank correlation: " + error.problem());
  }
  // Exact symmetry and unit diagonal, whatever the rounding of the product above.
  for (Eigen::Index a = 0; a < 4; ++a) {
    result.spearman(a, a) = 1.0;
    for (Eigen::Index b = a + 1; b < 4; ++b) result.spearman(b, a) = result.spearman(a, b);
  }
  return result;
}

}  // namespace growthuq
