// Why a sample has no value. Every evaluator writes a status per sample instead of throwing or
// leaving a silent NaN; the first non-ok status a sample gets is the one it keeps.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace growthuq {

enum class SampleStatus : std::uint8_t {
  ok = 0,
  invalid_input = 1,          // an input is NaN, infinite, or outside its physical domain (e.g. h <= 0)
  lambda_not_above_one = 2,   // d <= d0: no stretch, the hoop relation gives no modulus
  beyond_membrane_limit = 3,  // q = (1 - nu^2) ln(lambda) >= 1: alpha and p are not finite
  burst = 4,                  // forward model: c d0 > 1/e, the wall cannot hold the pressure
  no_growth = 5,              // p <= p0: below the yield pressure the tube does not grow
  fit_failed = 6,             // a relaxation fit did not converge or was ill-conditioned
  stiffness_at_sensor_limit = 7,  // measured k >= sensor stiffness: the series correction diverges
  out_of_range = 8,           // a result overflows or underflows double precision
  unstable_branch = 9,        // e < lambda, q < 1: past the hoop relation's pressure maximum; the
                              // forward model gives the other (smaller) diameter for that p, E, h
  // The finite-element inverse's own (fidelity shell_fe; growthuq/fe/indentation.hpp):
  not_converged = 10,         // Newton's method did not converge, even with the load step cut
  contact_lost = 11,          // the probe lost contact with the wall
  probe_beyond_mesh = 12,     // the contact left the meshed region
  window_not_reached = 13,    // the force curve never reached the force window's top
  no_inflation_state = 14,    // no pressure gives the measured turgid diameter and thickness
  no_modulus_root = 15,       // no modulus gives the measured k over the force window
  // Fidelity corrected: the measurement lies outside the region the correction was fitted on.
  outside_correction = 16,
  // The finite-element model's, appended (results.h5 stores the codes):
  probe_engulfed = 17,        // the load steps stall with the wall wrapped round the probe to its
                              // equator (fe::engulfed_contact_fraction, src/fe/forward.hpp)
};

// The largest code: names and counts run over 0 .. last_sample_status (HDF5 "names" attribute).
inline constexpr SampleStatus last_sample_status = SampleStatus::probe_engulfed;

// A set of statuses, one bit each.
class StatusSet {
 public:
  constexpr StatusSet() = default;
  constexpr StatusSet(std::initializer_list<SampleStatus> statuses) {
    for (const SampleStatus status : statuses) bits_ |= bit(status);
  }
  constexpr bool contains(SampleStatus status) const noexcept { return (bits_ & bit(status)) != 0; }
  constexpr bool empty() const noexcept { return bits_ == 0; }
  constexpr bool operator==(const StatusSet&) const = default;

 private:
  static constexpr std::uint32_t bit(SampleStatus status) noexcept { return std::uint32_t{1} << static_cast<unsigned>(status); }
  std::uint32_t bits_ = 0;
};

// Short name used in CSV/HDF5 ("ok", "lambda_not_above_one", ...).
std::string_view to_string(SampleStatus status);

// One sentence for users (README table, summaries).
std::string_view describe(SampleStatus status);

}  // namespace growthuq
