#include "growthuq/growth/ortega.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cvode_handles.hpp"
#include "finite_checks.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"

namespace growthuq {
namespace {

constexpr std::string_view location = "ortega";

// What the CVODE callbacks see. The state is Y = L / (kappa d^2 / (4 h)), the tip length in
// units of the tube's geometric length scale: dY/dt = (p - p0)_+ / eta + (1/E) dp/dt is then
// of order (turgor / viscosity) whatever the tube's size.
struct Problem {
  const Waveform* turgor;
  const Waveform* viscosity;
  double p0;
  double modulus;
  std::string last_error;  // CVODE's message for the exception, instead of stderr
};

double scaled_rate(const Problem& problem, double t) {
  const double overpressure = std::max(problem.turgor->value(t) - problem.p0, 0.0);
  return overpressure / problem.viscosity->value(t) + problem.turgor->rate(t) / problem.modulus;
}

int right_hand_side(sunrealtype t, N_Vector, N_Vector derivative, void* data) {
  NV_Ith_S(derivative, 0) = scaled_rate(*static_cast<const Problem*>(data), t);
  return 0;
}

// p(t) - p0: its zeros are the kinks of (p - p0)_+, where the integrator restarts.
int yield_crossing(sunrealtype t, N_Vector, sunrealtype* g, void* data) {
  const auto& problem = *static_cast<const Problem*>(data);
  g[0] = problem.turgor->value(t) - problem.p0;
  return 0;
}

void keep_message(int, const char* module, const char* function, char* message, void* data) {
  static_cast<Problem*>(data)->last_error =
      std::string(module) + "/" + function + ": " + message;
}

void validate_inputs(const OrtegaTube& tube, const Waveform& turgor, const Waveform& viscosity,
                     std::span<const double> times, const OrtegaOptions& options) {
  using growth_detail::positive_finite;
  if (!positive_finite(tube.d)) throw_bad_value(location, "d", format_double(tube.d), "a positive finite diameter in m");
  if (!positive_finite(tube.h)) throw_bad_value(location, "h", format_double(tube.h), "a positive finite thickness in m");
  if (!positive_finite(tube.E)) throw_bad_value(location, "E", format_double(tube.E), "a positive finite modulus in Pa");
  validate(tube.growth, location);
  if (!(viscosity.minimum() > 0.0)) {
    throw_bad_value(location, "minimum of the viscosity history", format_double(viscosity.minimum()),
                    "a viscosity > 0 Pa s at all times");
  }
  if (!(turgor.minimum() >= 0.0)) {
    throw_bad_value(location, "minimum of the turgor history", format_double(turgor.minimum()),
                    "a turgor >= 0 Pa at all times");
  }
  if (times.size() < 2) {
    throw_bad_value(location, "number of output times", std::to_string(times.size()), "at least 2");
  }
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
      throw_bad_value(location, "times[" + std::to_string(k) + "]", format_double(times[k]),
                      "finite times in increasing order");
    }
  }
  if (!positive_finite(options.relative_tolerance) || !positive_finite(options.absolute_tolerance) ||
      options.max_steps <= 0) {
    throw InputError(std::string(location), "tolerances and max_steps must be positive and finite");
  }
}

}  // namespace

OrtegaTrajectory simulate_ortega(const OrtegaTube& tube, const Waveform& turgor,
                                 const Waveform& viscosity, std::span<const double> times,
                                 const OrtegaOptions& options) {
  validate_inputs(tube, turgor, viscosity, times, options);
  const double length_scale = tube.growth.kappa * tube.d * tube.d / (4.0 * tube.h);
  Problem problem{&turgor, &viscosity, tube.growth.p0, tube.E, {}};

  // Breakpoints of either history strictly inside the integration interval, in order.
  std::vector<double> stops;
  for (const Waveform* history : {&turgor, &viscosity}) {
    for (double t : history->breakpoints()) {
      if (t > times.front() && t < times.back()) stops.push_back(t);
    }
  }
  std::sort(stops.begin(), stops.end());

  // Adams (non-stiff): the right-hand side does not even depend on L.
  growth_detail::CvodeHandles cvode(1, CV_ADAMS);
  void* memory = cvode.memory();
  N_Vector state = cvode.state();
  // Set-up calls fail only on a programming error (null memory, bad argument already excluded
  // by validate_inputs), so their failure is a logic_error, not an InputError.
  auto setup = [&](int flag, const char* call) {
    if (flag != CV_SUCCESS) {
      throw std::logic_error(std::string("simulate_ortega: ") + call + " returned " + std::to_string(flag));
    }
  };
  setup(CVodeInit(memory, right_hand_side, times.front(), state), "CVodeInit");
  setup(CVodeSetUserData(memory, &problem), "CVodeSetUserData");
  setup(CVodeSetErrHandlerFn(memory, keep_message, &problem), "CVodeSetErrHandlerFn");
  cvode.use_fixed_point_solver();
  setup(CVodeSStolerances(memory, options.relative_tolerance, options.absolute_tolerance / length_scale),
        "CVodeSStolerances");
  setup(CVodeSetMaxNumSteps(memory, options.max_steps), "CVodeSetMaxNumSteps");
  const double period = std::min(turgor.period(), viscosity.period());
  if (std::isfinite(period)) setup(CVodeSetMaxStep(memory, period / 10.0), "CVodeSetMaxStep");
  // The yield kink matters only when p(t) can cross p0.
  if (turgor.minimum() < tube.growth.p0 && turgor.maximum() > tube.growth.p0) {
    setup(CVodeRootInit(memory, 1, yield_crossing), "CVodeRootInit");
  }

  OrtegaTrajectory trajectory;
  auto record = [&](double t, double scaled_length) {
    trajectory.time.push_back(t);
    trajectory.length.push_back(length_scale * scaled_length);
    trajectory.velocity.push_back(length_scale * scaled_rate(problem, t));
  };
  record(times.front(), 0.0);

  double t = times.front();
  auto next_stop = stops.begin();
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double target = times[k];
    while (t < target) {
      while (next_stop != stops.end() && *next_stop <= t) ++next_stop;
      const bool at_breakpoint = next_stop != stops.end() && *next_stop <= target;
      const double stop = at_breakpoint ? *next_stop : target;
      // The stop time keeps CVODE from stepping past a breakpoint (it could otherwise jump
      // over a whole fast step) and makes it land exactly on the output time.
      setup(CVodeSetStopTime(memory, stop), "CVodeSetStopTime");
      const int flag = CVode(memory, stop, state, &t, CV_NORMAL);
      if (flag < 0) {
        throw InputError(std::string(location),
                         "CVODE failed at t = " + format_double(t) + " s (flag " + std::to_string(flag) +
                             "): " + problem.last_error +
                             "; shorten the time span or raise max_steps or the tolerances");
      }
      // Restart after a kink (root) or a breakpoint: the multistep history is not smooth there.
      if (flag == CV_ROOT_RETURN || (at_breakpoint && t >= stop)) setup(CVodeReInit(memory, t, state), "CVodeReInit");
    }
    record(target, NV_Ith_S(state, 0));
  }
  return trajectory;
}

}  // namespace growthuq
