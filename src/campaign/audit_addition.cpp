#include "campaign/audit_addition.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "campaign/chunk_values.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/io/results_h5.hpp"

namespace growthuq {
namespace {

// The columns of audit.csv as results.h5's /audit table (NaN where the CSV has an empty cell).
std::vector<ExtraColumn> audit_h5_columns(const std::vector<AuditRow>& rows) {
  std::vector<ExtraColumn> columns{{"line"}, {"fidelity"}, {"quantity"}, {"unit"}};
  const std::vector<std::string> counts{"audit_samples", "pairs", "fast_samples"};
  for (const std::string& name : counts) columns.push_back({name, {}, {}, {}, "1"});
  const std::vector<std::string> reals{"fast_mean", "bias", "bias_se", "bias_ci_low", "bias_ci_high", "correlation", "alpha", "mean",
                                       "mean_se", "mean_ci_low", "mean_ci_high", "mean_se_shell_fe_alone", "median", "median_se",
                                       "median_ci_low", "median_ci_high"};
  for (const std::string& name : reals) columns.push_back({name, {}, {}, {}, name == "correlation" || name == "alpha" ? "1" : ""});
  const double none = std::nan("");
  for (const AuditRow& row : rows) {
    columns[0].text.push_back(row.line);
    columns[1].text.push_back(row.fidelity);
    columns[2].text.push_back(row.quantity);
    columns[3].text.push_back(row.unit);
    columns[4].integer.push_back(static_cast<std::int64_t>(row.audit_samples));
    columns[5].integer.push_back(static_cast<std::int64_t>(row.pairs));
    columns[6].integer.push_back(static_cast<std::int64_t>(row.fast_samples));
    const MultifidelityEstimate* e = row.estimate ? &*row.estimate : nullptr;
    const auto four = [&](const IntervalEstimate* i) {
      return std::vector<double>{i ? i->estimate : none, i ? i->standard_error : none, i ? i->low : none, i ? i->high : none};
    };
    std::vector<double> values{row.fast_mean};
    for (const double v : four(e ? &e->bias : nullptr)) values.push_back(v);
    values.push_back(e ? e->correlation : none);
    values.push_back(e ? e->alpha : none);
    for (const double v : four(e ? &e->mean : nullptr)) values.push_back(v);
    values.push_back(e ? e->high_only_standard_error : none);
    for (const double v : four(e ? &e->quantile : nullptr)) values.push_back(v);
    for (std::size_t c = 0; c < values.size(); ++c) columns[7 + c].real.push_back(values[c]);
  }
  return columns;
}

class AuditAddition final : public RunAddition {
 public:
  AuditAddition(const CampaignAudit& audit, ProgressMode progress, std::ostream& log)
      : audit_(audit), log_(progress == ProgressMode::none ? nullptr : &log) {}

  ChunkShape chunk_shape() const override {
    const Campaign& c = audit_.campaign().campaign();
    ChunkShape shape;
    shape.samples = c.audit.samples;
    shape.chunk_sizes.assign(audited_lines(audit_.campaign()).size(), c.shell_fe_chunk_size);
    shape.values_per_sample = ChunkValues::values_per_sample(audit_.computed_outputs().size());
    return shape;
  }

  void run(Pool& pool, ChunkJournal* journal) override { rows_ = audit_.run(pool, log_, journal); }

  std::string write(RunProvenance& provenance, ResultsH5Writer* h5, const std::string& staging) const override {
    const Campaign& c = audit_.campaign().campaign();
    write_file_atomically((std::filesystem::path(staging) / audit_csv_name).string(), audit_csv(rows_), Overwrite::allow);
    if (h5 != nullptr) h5->write_table("audit", audit_h5_columns(rows_));
    provenance.audit.samples_per_line = c.audit.samples;
    provenance.audit.high_fidelity = std::string(to_string(Fidelity::shell_fe));
    provenance.audit.mesh = std::string(to_string(c.shell_fe.mesh));
    for (const AuditRow& row : rows_) {
      const double none = std::nan("");
      const IntervalEstimate* bias = row.estimate ? &row.estimate->bias : nullptr;
      provenance.audit.rows.push_back({row.line, row.fidelity, row.quantity, row.unit, row.pairs, bias ? bias->estimate : none,
                                       bias ? bias->low : none, bias ? bias->high : none});
    }
    return audit_table(rows_, c);
  }

 private:
  const CampaignAudit& audit_;
  std::ostream* log_;
  std::vector<AuditRow> rows_;  // coordinator
};

}  // namespace

std::unique_ptr<RunAddition> audit_addition(const CampaignAudit& audit, ProgressMode progress, std::ostream& log) {
  return std::make_unique<AuditAddition>(audit, progress, log);
}

}  // namespace growthuq
