// A rank correlation of the measurements (k, h, d, d0) that comes from the mechanics rather
// than a guess (Eq. (M16), src/mechanics/README.md): draw physically plausible (p, E, h, d0), run
// the forward thin-shell model, drop tubes that burst, and take the Spearman matrix. `growthuq
// correlate` writes it for `growthuq sample --rank-correlation`.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "growthuq/evaluation/sample_block.hpp"
#include "growthuq/mechanics/thin_shell.hpp"

namespace growthuq {

// A closed interval [low, high] of one drawn quantity, SI units, 0 < low < high.
struct DrawRange {
  double low;
  double high;
};

// Uniform: low + (high - low) u. Log-uniform: low (high/low)^u, for ranges spanning decades.
enum class DrawScale { uniform, log_uniform };

struct MechanicalDrawOptions {
  // Physiological defaults (envelope of src/mechanics/README.md): turgor 0.1-0.8 MPa,
  // modulus 5-200 MPa, thickness 100-300 nm (published medians 145-199 nm), plasmolysed
  // diameter 4-8 um.
  DrawRange p{0.1e6, 0.8e6};
  DrawRange E{5e6, 200e6};
  DrawRange h{100e-9, 300e-9};
  DrawRange d0{4e-6, 8e-6};
  DrawScale scale = DrawScale::uniform;
  std::uint64_t samples = 10000;
  // Draws come from std::mt19937_64 seeded with `seed` (RandomStream), four numbers per sample
  // in the order p, E, h, d0, each u = (bits >> 11) 2^-53: identical on every standard library.
  std::uint64_t seed = 1;
};

// InputError naming `location` and the key (p_MPa, E_MPa, h_nm, d0_um, samples) when a range is
// not 0 < low < high (finite) or samples < 3.
void validate(const MechanicalDrawOptions& options, std::string_view location);

// The drawn (p, E, h, d0) columns of options.samples samples (SI), statuses all ok.
SampleBlock draw_mechanical_samples(const MechanicalDrawOptions& options);

struct MechanicalCorrelation {
  std::array<std::string, 4> names{"k", "h", "d", "d0"};
  Eigen::MatrixXd spearman;  // 4 x 4 in the order of names; exactly symmetric, unit diagonal
  std::size_t drawn = 0;
  std::size_t kept = 0;
  std::size_t burst = 0;          // c d0 > 1/e: no equilibrium diameter
  std::size_t other_dropped = 0;  // any other status (e.g. beyond_membrane_limit with nu = 0)
};

// Draws, runs ThinShellForward and correlates the kept samples. InputError (location) when
// fewer than 3 samples survive or a kept column is constant.
MechanicalCorrelation mechanical_rank_correlation(const MechanicalDrawOptions& options,
                                                  const Instrument& shell,
                                                  std::string_view location);

}  // namespace growthuq
