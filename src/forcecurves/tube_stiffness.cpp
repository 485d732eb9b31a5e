// Eq. (C10), src/forcecurves/README.md: a tube's k from its repeated curves.
#include "growthuq/forcecurves/tube_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace growthuq {
namespace {

std::string status_counts(const std::vector<std::pair<std::string, std::size_t>>& counts) {
  std::string text;
  for (const auto& [status, count] : counts) text += (text.empty() ? "" : ", ") + status + " " + std::to_string(count);
  return text;
}

}  // namespace

std::vector<TubeStiffness> tube_stiffness(const std::vector<CurveResult>& curves) {
  std::vector<TubeStiffness> tubes;
  std::map<std::string, std::size_t, std::less<>> index;
  std::vector<std::vector<const CurveResult*>> members;
  for (const CurveResult& curve : curves) {
    auto [it, inserted] = index.try_emplace(curve.tube, tubes.size());
    if (inserted) {
      tubes.push_back({});
      tubes.back().tube = curve.tube;
      members.emplace_back();
    }
    members[it->second].push_back(&curve);
  }
  for (std::size_t t = 0; t < tubes.size(); ++t) {
    TubeStiffness& tube = tubes[t];
    std::vector<std::pair<std::string, std::size_t>> counts;
    double sum = 0.0, squared_uncertainty = 0.0;
    for (const CurveResult* curve : members[t]) {
      ++tube.curves;
      const std::string status(to_string(curve->status));
      auto known = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == status; });
      if (known == counts.end()) {
        counts.emplace_back(status, 1);
      } else {
        ++known->second;
      }
      if (curve->status != CurveStatus::ok) continue;
      ++tube.ok;
      sum += curve->stiffness;
      squared_uncertainty += curve->uncertainty * curve->uncertainty;
    }
    tube.statuses = status_counts(counts);
    if (tube.ok == 0) continue;
    const auto n = static_cast<double>(tube.ok);
    tube.stiffness = sum / n;
    double squares = 0.0;
    for (const CurveResult* curve : members[t]) {
      if (curve->status == CurveStatus::ok) squares += (curve->stiffness - tube.stiffness) * (curve->stiffness - tube.stiffness);
    }
    tube.spread = tube.ok > 1 ? std::sqrt(squares / (n - 1.0)) : 0.0;
    tube.uncertainty_spread = tube.spread / std::sqrt(n);
    tube.uncertainty_measurement = std::sqrt(squared_uncertainty) / n;
    tube.uncertainty = std::max(tube.uncertainty_spread, tube.uncertainty_measurement);
  }
  return tubes;
}

}  // namespace growthuq
