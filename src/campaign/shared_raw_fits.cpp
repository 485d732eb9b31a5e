#include "campaign/shared_raw_fits.hpp"

#include <cstdint>
#include <stdexcept>
#include <utility>

namespace growthuq {
namespace {

void put_text(std::vector<double>& numbers, const std::string& text) {
  numbers.push_back(static_cast<double>(text.size()));
  for (const char c : text) numbers.push_back(static_cast<double>(static_cast<unsigned char>(c)));
}

void put_list(std::vector<double>& numbers, const std::vector<double>& values) {
  numbers.push_back(static_cast<double>(values.size()));
  numbers.insert(numbers.end(), values.begin(), values.end());
}

// Reads a curve_fit_numbers() record front to back.
class NumberReader {
 public:
  explicit NumberReader(std::span<const double> numbers) : numbers_(numbers) {}

  double number() {
    if (next_ >= numbers_.size()) throw std::invalid_argument("curve fit record ends early");
    return numbers_[next_++];
  }
  std::size_t count() { return static_cast<std::size_t>(number()); }
  std::string text() {
    std::string result(count(), '\0');
    for (char& c : result) c = static_cast<char>(static_cast<unsigned char>(number()));
    return result;
  }
  std::vector<double> list() {
    std::vector<double> result(count());
    for (double& value : result) value = number();
    return result;
  }
  bool finished() const { return next_ == numbers_.size(); }

 private:
  std::span<const double> numbers_;
  std::size_t next_ = 0;
};

}  // namespace

std::vector<double> curve_fit_numbers(const CurveFit& fit) {
  std::vector<double> numbers;
  put_text(numbers, fit.curve);
  numbers.push_back(fit.ok ? 1.0 : 0.0);
  numbers.push_back(fit.extrapolated ? 1.0 : 0.0);
  put_text(numbers, fit.reason);
  put_list(numbers, fit.tau);
  put_list(numbers, fit.amplitude);
  numbers.insert(numbers.end(), {fit.einf, fit.modulus0, fit.relaxing_modulus, fit.viscosity, fit.tau_slow_relative_se,
                                 fit.tau_slow_low, fit.tau_slow_high, fit.rms, fit.aic, fit.ramp_time, static_cast<double>(fit.points), fit.springs.k_inf});
  put_list(numbers, fit.springs.k);
  put_list(numbers, fit.springs.tau);
  return numbers;
}

CurveFit curve_fit_from_numbers(std::span<const double> numbers) {
  NumberReader read(numbers);
  CurveFit fit;
  fit.curve = read.text();
  fit.ok = read.number() != 0.0;
  fit.extrapolated = read.number() != 0.0;
  fit.reason = read.text();
  fit.tau = read.list();
  fit.amplitude = read.list();
  fit.einf = read.number();
  fit.modulus0 = read.number();
  fit.relaxing_modulus = read.number();
  fit.viscosity = read.number();
  fit.tau_slow_relative_se = read.number();
  fit.tau_slow_low = read.number();
  fit.tau_slow_high = read.number();
  fit.rms = read.number();
  fit.aic = read.number();
  fit.ramp_time = read.number();
  fit.points = read.count();
  fit.springs.k_inf = read.number();
  fit.springs.k = read.list();
  fit.springs.tau = read.list();
  if (!read.finished()) throw std::invalid_argument("curve fit record has numbers left over");
  return fit;
}

CurveFitter shared_curve_fitter(Pool& pool, std::string line, ProgressMode progress, std::ostream& log) {
  return [&pool, &log, line = std::move(line), progress](const std::vector<RelaxationCurve>& curves,
                                                         const RelaxationOptions& options) {
    const std::size_t count = curves.size();
    StepProgress shown(pool.is_coordinator() ? progress : ProgressMode::none, log,
                       "fitting relaxation curves of line " + line, "curve", count);
    // rank 0: each curve's fit as numbers
    const std::vector<std::vector<double>> records = run_items(
        pool, count, [&](std::size_t c) { return curve_fit_numbers(analyze_relaxation_curve(curves[c], options)); },
        [&] { shown.advance(1); });
    shown.finish();

    // Rank 0 sends every record to every process: first their sizes, then their numbers.
    std::vector<std::uint64_t> sizes(count);
    std::vector<double> all;
    if (pool.is_coordinator()) {
      for (std::size_t c = 0; c < count; ++c) {
        sizes[c] = records[c].size();
        all.insert(all.end(), records[c].begin(), records[c].end());
      }
    }
    pool.broadcast_vector(sizes, count, 0);
    std::size_t total = 0;
    for (const std::uint64_t size : sizes) total += size;
    pool.broadcast_vector(all, total, 0);

    std::vector<CurveFit> fits;
    fits.reserve(count);
    std::size_t at = 0;
    for (const std::uint64_t size : sizes) {
      fits.push_back(curve_fit_from_numbers(std::span<const double>(all).subspan(at, size)));
      at += size;
    }
    return fits;
  };
}

}  // namespace growthuq
