#include "curve_fit_progress.hpp"

#include <iostream>

#include "growthuq/campaign/progress.hpp"

namespace growthuq::cli {

std::vector<CurveFit> fit_curves_showing_progress(const std::vector<RelaxationCurve>& curves,
                                                  const RelaxationOptions& options, ProgressMode mode) {
  StepProgress shown(mode, std::cerr, "fitting relaxation curves", "curve", curves.size());
  std::vector<CurveFit> fits;
  fits.reserve(curves.size());
  for (const RelaxationCurve& curve : curves) {
    fits.push_back(analyze_relaxation_curve(curve, options));
    shown.advance(1);
  }
  shown.finish();
  return fits;
}

}  // namespace growthuq::cli
