// A simulated relaxation experiment as the record a lab file gives (relaxation/curves.hpp),
// for tests that fit simulated curves with the analysis a measured one goes through.
#pragma once

#include <string>
#include <utility>

#include "growthuq/relaxation/curves.hpp"
#include "growthuq/relaxation/simulator.hpp"

namespace growthuq::testing {

// `simulated`'s record with the tube's geometry; `Tube` is any type with turgor, diameter,
// thickness and instrument (probe radius) in SI units (ShellGeometry, RelaxationTube).
template <class Tube>
RelaxationCurve as_curve(const SimulatedCurve& simulated, const Tube& tube, std::string name) {
  return RelaxationCurve{.name = std::move(name),
                         .location = {},  // simulated, not read from a file
                         .t = simulated.t,
                         .force = simulated.force,
                         .indentation = simulated.indentation,
                         .turgor = tube.turgor,
                         .diameter = tube.diameter,
                         .thickness = tube.thickness,
                         .probe_radius_m = tube.instrument.probe_radius_m};
}

}  // namespace growthuq::testing
