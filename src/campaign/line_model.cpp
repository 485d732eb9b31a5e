#include "campaign/line_model.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "campaign/chunk_values.hpp"
#include "growthuq/distributions/distribution.hpp"

namespace growthuq {

const PreparedLine& prepared_line(const PreparedCampaign& campaign, const std::string& name) {
  const auto line = std::find_if(campaign.lines().begin(), campaign.lines().end(),
                                 [&](const PreparedLine& l) { return l.campaign_line.name == name; });
  if (line == campaign.lines().end()) throw std::logic_error("prepared_line: no line " + name);
  return *line;
}

BatchModel line_model(const PreparedCampaign& campaign, const PreparedLine& line) {
  return [&campaign, &line](const Eigen::MatrixXd& x) {
    const auto n = static_cast<std::size_t>(x.rows());
    const std::size_t outputs = campaign.computed_outputs().size();
    LineDesign design;
    for (const LineVariable& variable : line.design_variables.variables) design.names.push_back(variable.name);
    for (Eigen::Index j = 0; j < x.cols(); ++j) {
      LargeVector<double> column(n);
      for (std::size_t s = 0; s < n; ++s) column[s] = x(static_cast<Eigen::Index>(s), j);
      design.values.push_back(std::move(column));
    }
    const std::vector<double> packed = campaign.evaluate_chunk(line, design, {0, n});
    const ChunkValues values(packed, outputs);
    Eigen::MatrixXd y(x.rows(), static_cast<Eigen::Index>(outputs));
    for (std::size_t o = 0; o < outputs; ++o) {
      const std::span<const double> column = values.output(o);
      for (std::size_t s = 0; s < n; ++s) {
        y(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(o)) =
            values.status(s) == SampleStatus::ok ? column[s] : std::numeric_limits<double>::quiet_NaN();
      }
    }
    return y;
  };
}

std::vector<Quantile> line_marginals(const PreparedLine& line) {
  std::vector<Quantile> marginals;
  for (const LineVariable& variable : line.design_variables.variables) {
    marginals.push_back([&distribution = variable.distribution](std::span<const double> u, std::span<double> x) {
      quantiles(distribution, u, x);
    });
  }
  return marginals;
}

}  // namespace growthuq
