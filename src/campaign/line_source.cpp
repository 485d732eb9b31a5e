#include "campaign/line_source.hpp"

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

}  // namespace growthuq
