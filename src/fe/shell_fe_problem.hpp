// The bridge from the SI public API (growthuq/fe/indentation.hpp) to the dimensionless solver
// (fe/forward.hpp): the problem from options and a sample, the inflated state's unstressed
// thickness, and a result's curve and field in SI.
#pragma once

#include <string_view>

#include "fe/far_field.hpp"
#include "fe/forward.hpp"
#include "growthuq/fe/indentation.hpp"

namespace growthuq::fe {

// Everything of the problem but pressure, thickness and depth, lengths over d0.
ForwardProblem make_problem(const ShellFeOptions& options, double plasmolysed_diameter, double probe_radius,
                            double poisson);

// The shell's laws need nu in [0, 0.5) (an isotropic solid thinning under tension); InputError
// naming key nu otherwise.
void check_shell_poisson(double poisson, std::string_view location);

// h0/d0 for a turgid h/d0 at p/E in the far field (far_field_inflation_to_turgid_thickness: a
// bracketed root on the rising branch of the pressure group); 0 when the wall bursts.
double far_field_unstressed_thickness(ShellFeLaw law, double pressure_over_young, double turgid_thickness,
                                      double poisson);

// The solver's curve in SI (depth and contact radius times d0, force times E d0^2).
void curve_in_si(const ForwardResult& result, double d0, double young, IndentationCurve& curve);
ShellFeField field_in_si(const ForwardResult& result, double d0, double young);

}  // namespace growthuq::fe
