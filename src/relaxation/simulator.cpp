#include "growthuq/relaxation/simulator.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_diag.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "relaxation/noise.hpp"

namespace growthuq {
namespace {

// The Maxwell modes' ODE, dF_i/dt = k_i du/dt - F_i / tau_i, with du/dt = rate during the
// ramp and 0 during the hold. States are F_i / scale so that CVODE's absolute tolerance is
// relative to the force scale of the problem. The integrator's variable is s = t /
// seconds_per_unit: the ramp-aware fit's basis runs its ramp in s = t / ramp_time from 0 to 1,
// dF_i/ds = k_i d(u / scale)/ds - F_i ramp_time / tau_i, which stays well posed as the ramp
// time goes to 0 (the step is its limit) where du/dt would not.
struct ModeEquations {
  std::vector<double> k;
  std::vector<double> tau;
  double k_inf = 0.0;
  double rate = 0.0;              // du/dt during the ramp (m/s), for the set-point root
  double scale = 1.0;
  double set_point = 0.0;         // root target during the ramp (N)
  double drive = 0.0;             // d(u / scale)/ds: rate / scale during a ramp in seconds, 0 in the hold
  double seconds_per_unit = 1.0;  // of the integrator's variable s
};

int mode_rhs(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& equations = *static_cast<const ModeEquations*>(data);
  const double* state = N_VGetArrayPointer(y);
  double* derivative = N_VGetArrayPointer(ydot);
  // tau_i / seconds_per_unit: exactly tau_i in seconds (the simulator's arithmetic), +inf
  // for a ramp of length 0 (no relaxation during it).
  for (std::size_t i = 0; i < equations.k.size(); ++i) {
    derivative[i] = equations.k[i] * equations.drive - state[i] / (equations.tau[i] / equations.seconds_per_unit);
  }
  return 0;
}

// g(t) = F(t) - set point during the ramp, u = rate t.
int set_point_root(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
  const auto& equations = *static_cast<const ModeEquations*>(data);
  const double* state = N_VGetArrayPointer(y);
  double force = equations.k_inf * equations.rate * t / equations.scale;
  for (std::size_t i = 0; i < equations.k.size(); ++i) force += state[i];
  g[0] = force - equations.set_point / equations.scale;
  return 0;
}

// Owns a CVODE integrator (BDF; CVDiag's diagonal Jacobian is exact here because the modes
// are uncoupled) for the mode equations, starting from F_i = 0 at t = 0.
class ModeIntegrator {
 public:
  explicit ModeIntegrator(ModeEquations& equations) : equations_(equations) {
    const auto n = static_cast<sunindextype>(equations.k.size());
    check(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
    state_ = N_VNew_Serial(n, context_);
    if (state_ == nullptr) throw std::runtime_error("CVODE: cannot allocate the state vector");
    N_VConst(0.0, state_);
    memory_ = CVodeCreate(CV_BDF, context_);
    if (memory_ == nullptr) throw std::runtime_error("CVODE: CVodeCreate failed");
    check(CVodeSetErrHandlerFn(memory_, keep_message, &cvode_message_), "CVodeSetErrHandlerFn");
    check(CVodeInit(memory_, mode_rhs, 0.0, state_), "CVodeInit");
    check(CVodeSetUserData(memory_, &equations_), "CVodeSetUserData");
    // rtol 1e-10 on forces of order 1 after scaling: far below the 1e-4 noise of measured curves.
    check(CVodeSStolerances(memory_, 1e-10, 1e-13), "CVodeSStolerances");
    check(CVodeSetMaxNumSteps(memory_, 1000000), "CVodeSetMaxNumSteps");
    check(CVDiag(memory_), "CVDiag");
  }
  ~ModeIntegrator() {
    CVodeFree(&memory_);
    N_VDestroy(state_);
    SUNContext_Free(&context_);
  }
  ModeIntegrator(const ModeIntegrator&) = delete;
  ModeIntegrator& operator=(const ModeIntegrator&) = delete;

  void find_set_point() { check(CVodeRootInit(memory_, 1, set_point_root), "CVodeRootInit"); }
  void stop_at(double t) {
    check(CVodeSetStopTime(memory_, t), "CVodeSetStopTime");
    stop_time_ = t;
  }

  // Switches to the hold at time t in seconds (the states are continuous; only du/dt
  // changes, and the integrator's variable is the time in seconds from here on).
  void start_hold(double t) {
    equations_.drive = 0.0;
    equations_.seconds_per_unit = 1.0;
    check(CVodeReInit(memory_, t, state_), "CVodeReInit");
    check(CVodeRootInit(memory_, 0, nullptr), "CVodeRootInit");
    // SUNDIALS 6.4 keeps a stop time across CVodeReInit and has no CVodeClearStopTime.
    check(CVodeSetStopTime(memory_, std::numeric_limits<double>::max()), "CVodeSetStopTime");
    stop_time_ = std::numeric_limits<double>::infinity();
    time_ = t;
  }

  // Advances to `until` or to an earlier root or stop time; returns CVODE's flag.
  int advance(double until) {
    if (until <= time_) return CV_SUCCESS;
    // CVODE cannot start from (re)initialization towards an output time closer than its time
    // resolution (cvHin in cvode.c: |tout - t0| < 2 uround max(|t0|, |tout|) is "tout too close
    // to t0"), e.g. a sample a few ulps after a fitted ramp end. Over such an interval every
    // F_i changes by F_i |tout - t0| / tau_i, a few ulps of t / tau_i: far below the tolerance,
    // so the state is kept.
    if (until - time_ <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(time_), std::abs(until))) {
      time_ = until;
      return CV_SUCCESS;
    }
    // With a stop time CVODE may already have stepped exactly to it while returning an earlier
    // output; asking again would be an error ("tstop behind current t"), so interpolate.
    double internal_time = 0.0;
    check(CVodeGetCurrentTime(memory_, &internal_time), "CVodeGetCurrentTime");
    if (internal_time >= stop_time_ && until <= internal_time) {
      check(CVodeGetDky(memory_, until, 0, state_), "CVodeGetDky");
      time_ = until;
      return CV_SUCCESS;
    }
    const int flag = CVode(memory_, until, state_, &time_, CV_NORMAL);
    check(flag, "CVode");
    return flag;
  }

  double time() const { return time_; }
  // Sum of the mode forces, in N.
  double mode_force() const {
    const double* state = N_VGetArrayPointer(state_);
    double sum = 0.0;
    for (std::size_t i = 0; i < equations_.k.size(); ++i) sum += state[i];
    return sum * equations_.scale;
  }
  double mode(std::size_t i) const { return N_VGetArrayPointer(state_)[i] * equations_.scale; }

 private:
  // CVODE's own messages would go to stderr as several lines; they go into the exception.
  static void keep_message(int, const char*, const char*, char* message, void* data) {
    *static_cast<std::string*>(data) = message;
  }
  void check(int flag, const char* call) const {
    if (flag >= 0) return;
    throw std::runtime_error(std::string("CVODE: ") + call + " failed with flag " + std::to_string(flag) +
                             (cvode_message_.empty() ? std::string() : " (" + cvode_message_ + ")"));
  }

  ModeEquations& equations_;
  SUNContext context_ = nullptr;
  N_Vector state_ = nullptr;
  void* memory_ = nullptr;
  double time_ = 0.0;
  double stop_time_ = std::numeric_limits<double>::infinity();
  std::string cvode_message_;
};

void require_positive(double value, const char* key) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw_bad_value("simulate_ramp_hold", key, format_double(value), "a positive finite number");
  }
}

}  // namespace

SimulatedCurve simulate_ramp_hold(const MaxwellModel& model, const RampHoldProtocol& protocol,
                                  const MeasurementNoise& noise) {
  if (model.k.empty() || model.k.size() != model.tau.size()) {
    throw InputError("simulate_ramp_hold", "a Maxwell model needs as many stiffnesses k_i as times tau_i, at least one");
  }
  if (!(model.k_inf >= 0.0) || !std::isfinite(model.k_inf)) {
    throw_bad_value("simulate_ramp_hold", "k_inf", format_double(model.k_inf), "a finite number >= 0");
  }
  for (std::size_t i = 0; i < model.k.size(); ++i) {
    require_positive(model.k[i], "k_i");
    require_positive(model.tau[i], "tau_i");
  }
  require_positive(protocol.rate, "rate");
  require_positive(protocol.set_point, "set_point");
  require_positive(protocol.hold, "hold");
  require_positive(protocol.sample_interval, "sample_interval");
  if (!(noise.relative_sd >= 0.0) || !std::isfinite(noise.relative_sd) || !std::isfinite(noise.drift)) {
    throw InputError("simulate_ramp_hold", "noise: relative_sd must be >= 0 and drift finite");
  }

  // The set point is reached by t = F / (k_inf rate) when k_inf > 0; with k_inf = 0 the
  // force saturates at rate sum k_i tau_i, which must exceed the set point.
  double saturation = 0.0;
  double instantaneous = model.k_inf;
  double slowest = 0.0;
  for (std::size_t i = 0; i < model.k.size(); ++i) {
    saturation += model.k[i] * model.tau[i] * protocol.rate;
    instantaneous += model.k[i];
    slowest = std::max(slowest, model.tau[i]);
  }
  if (model.k_inf == 0.0 && saturation <= protocol.set_point) {
    throw InputError("simulate_ramp_hold", "the set point " + format_double(protocol.set_point) +
                                               " N is above the force the ramp can reach (" +
                                               format_double(saturation) + " N)");
  }
  const double ramp_limit = model.k_inf > 0.0 ? 1.01 * protocol.set_point / (model.k_inf * protocol.rate)
                                              : 100.0 * slowest + protocol.set_point / (instantaneous * protocol.rate);
  if (ramp_limit / protocol.sample_interval > 1e8) {
    throw InputError("simulate_ramp_hold", "the ramp would need more than 1e8 samples at this sampling interval");
  }

  ModeEquations equations{model.k,           model.tau,          model.k_inf,
                          protocol.rate,     protocol.set_point, protocol.set_point,
                          protocol.rate / protocol.set_point, 1.0};
  ModeIntegrator integrator(equations);
  integrator.find_set_point();

  SimulatedCurve curve;
  auto record = [&](double t, double u) {
    curve.t.push_back(t);
    curve.displacement.push_back(u);
    curve.force.push_back(model.k_inf * u + integrator.mode_force());
  };
  record(0.0, 0.0);
  std::size_t j = 1;
  bool holding = false;
  for (;; ++j) {
    const double t = static_cast<double>(j) * protocol.sample_interval;
    if (!holding) {
      if (integrator.advance(t) == CV_ROOT_RETURN) {
        curve.ramp_end = integrator.time();
        curve.indentation = protocol.rate * curve.ramp_end;
        integrator.start_hold(curve.ramp_end);
        holding = true;
      } else {
        record(t, protocol.rate * t);
        if (t > ramp_limit) throw std::runtime_error("CVODE missed the force set point of the ramp");
        continue;
      }
    }
    // Half a sample of slack so that rounding in j dt does not drop the last sample.
    if (t > curve.ramp_end + protocol.hold + 1e-9 * protocol.sample_interval) break;
    integrator.advance(t);
    record(t, curve.indentation);
  }

  if (noise.relative_sd > 0.0 || noise.drift != 0.0) {
    GaussianNoise gaussian(noise.seed);
    for (std::size_t i = 0; i < curve.t.size(); ++i) {
      curve.force[i] += noise.relative_sd * protocol.set_point * gaussian.normal() + noise.drift * curve.t[i];
    }
  }
  return curve;
}

Eigen::MatrixXd maxwell_mode_responses(std::span<const double> tau, double ramp_time,
                                       double indentation, std::span<const double> t) {
  const auto rows = static_cast<Eigen::Index>(t.size());
  const auto modes = static_cast<Eigen::Index>(tau.size());
  Eigen::MatrixXd basis(rows, modes + 1);
  // u = indentation min(t / ramp_time, 1), and u(0) = 0 also for ramp_time = 0 (contact), the
  // limit of ever shorter ramps.
  auto ramp_fraction = [ramp_time](double time) { return time < ramp_time ? time / ramp_time : (time > 0.0 ? 1.0 : 0.0); };
  for (Eigen::Index r = 0; r < rows; ++r) basis(r, 0) = indentation * ramp_fraction(t[static_cast<std::size_t>(r)]);
  if (tau.empty()) return basis;
  // The ramp in s = t / ramp_time from 0 to 1 (see ModeEquations), with u / indentation = s.
  ModeEquations equations{std::vector<double>(tau.size(), 1.0), std::vector<double>(tau.begin(), tau.end()),
                          0.0, 0.0, indentation, 0.0, 1.0, ramp_time};
  ModeIntegrator integrator(equations);
  integrator.stop_at(1.0);
  bool holding = false;
  for (Eigen::Index r = 0; r < rows; ++r) {
    const double time = t[static_cast<std::size_t>(r)];
    if (!holding && time > ramp_time) {
      integrator.advance(1.0);
      integrator.start_hold(ramp_time);
      holding = true;
    }
    integrator.advance(holding ? time : ramp_fraction(time));
    for (Eigen::Index i = 0; i < modes; ++i) basis(r, i + 1) = integrator.mode(static_cast<std::size_t>(i));
  }
  return basis;
}

}  // namespace growthuq
