#include "campaign/line_source.hpp"

#include <cmath>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"

namespace growthuq {

LineDistributions load_line_distributions(const CampaignLine& line, const Instrument& instrument,
                                          std::shared_ptr<const RawLineFit>& raw_fit, const CurveFitter& fit_curves) {
  raw_fit.reset();
  if (line.raw_path.empty()) return read_line_file(line.distributions_path);
  RawFitSettings settings;
  settings.instrument = instrument;
  settings.fit_curves = fit_curves;
  auto fit = std::make_shared<RawLineFit>(fit_raw_line(read_raw_line_file(line.raw_path), settings));
  LineDistributions distributions = fit->distributions;
  raw_fit = std::move(fit);
  return distributions;
}

namespace {

// A force in uN as written in files and flags: rounded to 1e-9 uN, so 0.4e-6 N reads "0.4".
std::string uN(double force_N) { return format_double(std::round(to_uN(force_N) * 1e9) / 1e9); }

}  // namespace

void require_force_curves_match(const RawLineFit& fit, const Campaign& campaign, Fidelity fidelity,
                                const std::string& location) {
  if (!fit.raw.has_force_curves) return;
  const std::string section = fit.raw.path + ":" + std::to_string(fit.raw.force_curves.line) + " [force_curves]";
  if (std::isfinite(campaign.instrument.sensor_stiffness_N_per_m)) {
    throw InputError(location, "[instrument] sensor_stiffness_N_per_m = " +
                                   format_double(campaign.instrument.sensor_stiffness_N_per_m) + " and k from force curves (" +
                                   section + "), already corrected for each curve's k_sys in its sheet: expected "
                                   "sensor_stiffness_N_per_m = inf (or left out), so k is not corrected twice");
  }
  if (fidelity != Fidelity::shell_fe && fidelity != Fidelity::corrected) return;
  const FitWindow& data = fit.raw.force_curves.options.window;
  const std::array<double, 2>& model = campaign.shell_fe.force_window;
  const bool same = data.convention == WindowConvention::absolute && std::abs(data.low_N - model[0]) <= 1e-9 * model[1] &&
                    std::abs(data.high_N - model[1]) <= 1e-9 * model[1];
  if (!same) {
    const std::string data_window =
        data.convention == WindowConvention::absolute
            ? "[" + uN(data.low_N) + ", " + uN(data.high_N) + "] uN from contact"
            : "[F_max - " + uN(data.low_N) + ", F_max - " + uN(data.high_N) + "] uN";
    throw InputError(location, "fidelity " + std::string(to_string(fidelity)) + " fits the model's k over [" +
                                   uN(model[0]) + ", " + uN(model[1]) +
                                   "] uN from contact ([shell_fe] force_window_uN) but " + section + " fits the data's over " +
                                   data_window + ": expected window = absolute, window_uN = " +
                                   uN(model[0]) + "," + uN(model[1]) +
                                   " (the same window for the measured and the model's k)");
  }
}

}  // namespace growthuq
