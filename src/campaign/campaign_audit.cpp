#include "growthuq/campaign/campaign_audit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <span>
#include <stdexcept>
#include <utility>

#include "campaign/chunk_values.hpp"
#include "campaign/report_text.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/io/output_file.hpp"
#include "campaign/campaign_outputs.hpp"
#include "growthuq/growth/kappa.hpp"
#include "growthuq/stats/quantity_summary.hpp"

namespace growthuq {

namespace {

std::string audit_location(const Campaign& campaign) {
  return campaign.audit.line > 0 ? file_location(campaign.path, campaign.audit.line) : campaign.path;
}

// The campaign as the audit's models see it: its outputs and E (closed_form reads h only for E,
// shell_fe always), no bootstrap, and `fe` lines at shell_fe.
Campaign audit_campaign(const Campaign& campaign, const std::vector<std::string>& fe_lines) {
  Campaign copy = campaign;
  if (std::find(copy.outputs.begin(), copy.outputs.end(), "E") == copy.outputs.end()) copy.outputs.push_back("E");
  copy.data_uncertainty.replicates = 0;
  for (CampaignLine& line : copy.lines) {
    if (std::find(fe_lines.begin(), fe_lines.end(), line.name) != fe_lines.end()) line.fidelity = Fidelity::shell_fe;
  }
  return copy;
}

std::vector<std::string> variable_names(const PreparedLine& line) {
  std::vector<std::string> names;
  for (const LineVariable& variable : line.design_variables.variables) names.push_back(variable.name);
  return names;
}

// The samples of an audited line's first `n` that `journal` holds (null: none).
std::size_t samples_held(const ChunkJournal* journal, std::size_t line, std::size_t n, std::size_t chunk_size) {
  std::size_t held = 0;
  for (std::size_t begin = 0; journal != nullptr && begin < n; begin += chunk_size) {
    const ChunkRange range{begin, std::min(n, begin + chunk_size)};
    if (journal->holds(line, range)) held += range.end - range.begin;
  }
  return held;
}

// Column `o` of `values` packed by evaluate_chunk, in the quantity's default unit.
void unpack(std::span<const double> values, std::size_t outputs, std::size_t o, double to_si, ChunkRange range,
            std::vector<double>& column) {
  const ChunkValues chunk(values, outputs);
  const std::span<const double> in = chunk.output(o);
  for (std::size_t i = 0; i < in.size(); ++i) column[range.begin + i] = in[i] / to_si;
}

}  // namespace

std::vector<std::size_t> audited_lines(const PreparedCampaign& campaign) {
  std::vector<std::size_t> lines;
  if (campaign.campaign().audit.samples == 0) return lines;
  for (std::size_t i = 0; i < campaign.lines().size(); ++i) {
    if (campaign.campaign().fidelity_of(campaign.lines()[i].campaign_line) != Fidelity::shell_fe) lines.push_back(i);
  }
  return lines;
}

std::size_t audit_fe_samples(const Campaign& campaign) {
  const auto fast = std::count_if(campaign.lines.begin(), campaign.lines.end(),
                                  [&](const CampaignLine& line) { return campaign.fidelity_of(line) != Fidelity::shell_fe; });
  return campaign.audit.samples * static_cast<std::size_t>(fast);
}

CampaignAudit::CampaignAudit(const PreparedCampaign& campaign, Pool& pool) : campaign_(campaign), lines_(audited_lines(campaign)) {
  const Campaign& c = campaign.campaign();
  const std::string where = audit_location(c);
  if (c.audit.samples > c.samples) {
    throw InputError(where, "[audit] samples = " + std::to_string(c.audit.samples) + ": expected at most the campaign's " +
                                std::to_string(c.samples) + " samples per line (the audit runs the first N of them through shell_fe)");
  }
  if (lines_.empty()) {
    throw InputError(where, "[audit] compares a fast fidelity (closed_form, corrected) with shell_fe, and every line runs at "
                            "fidelity shell_fe: remove the section, or set samples = 0");
  }
  std::vector<std::string> fe_lines;
  for (const std::size_t i : lines_) fe_lines.push_back(campaign.lines()[i].campaign_line.name);
  try {
    fast_ = std::make_unique<PreparedCampaign>(audit_campaign(c, {}), pool, ProgressMode::none, std::cerr);
    fe_ = std::make_unique<PreparedCampaign>(audit_campaign(c, fe_lines), pool, ProgressMode::none, std::cerr);
  } catch (const InputError& error) {
    throw InputError(where, "[audit]: the audit's models cannot run: " + error.location() + ": " + error.problem());
  }
  for (const std::size_t i : lines_) {
    if (variable_names(fast_->lines()[i]) != variable_names(fe_->lines()[i])) {  // both read k, d, d0, h and the outputs' own
      throw std::logic_error("campaign audit: the fast and finite-element models of a line sample different variables");
    }
  }
  for (const std::string& output : campaign.computed_outputs()) {
    // v is scaled by the kappa its own run calibrates (kappa.hpp): the audit's models leave it unscaled.
    if (output != KappaCalibration::quantity) quantities_.push_back(output);
  }
}

CampaignAudit::~CampaignAudit() = default;

const std::vector<std::string>& CampaignAudit::computed_outputs() const { return fe_->computed_outputs(); }

std::vector<AuditRow> CampaignAudit::run(Pool& pool, std::ostream* log, ChunkJournal* journal) const {
  const Campaign& c = campaign_.campaign();
  const std::size_t n = c.audit.samples, m = c.samples;
  std::vector<AuditRow> rows;
  pool.set_queued_chunks(1);  // finite-element samples, as the run hands them out (campaign_run.cpp)
  for (std::size_t audited = 0; audited < lines_.size(); ++audited) {
    const std::size_t index = lines_[audited];
    const PreparedLine& fast_line = fast_->lines()[index];
    const PreparedLine& fe_line = fe_->lines()[index];
    if (log != nullptr && pool.is_coordinator()) {
      *log << "growthuq run: audit of line " << fast_line.campaign_line.name << ": " << n << " samples through shell_fe";
      const std::size_t held = samples_held(journal, audited, n, c.shell_fe_chunk_size);
      if (held > 0) *log << ", " << held << " of them kept by the checkpoint";
      *log << "\n" << std::flush;
    }
    const LineDesign design = fe_->design(fe_line);  // = fast_->design(fast_line): same variables, seed and count
    const std::vector<std::string>& outputs = fe_->computed_outputs();  // the same in both (same campaign outputs)
    std::vector<std::vector<double>> fe_values(quantities_.size(), std::vector<double>(n));
    std::vector<std::vector<double>> fast_values(quantities_.size(), std::vector<double>(m));
    std::vector<std::size_t> column;
    std::vector<double> to_si;
    for (const std::string& quantity : quantities_) {
      column.push_back(static_cast<std::size_t>(std::find(outputs.begin(), outputs.end(), quantity) - outputs.begin()));
      to_si.push_back(find_unit(find_quantity(quantity)->default_unit, "quantity table", quantity).to_si);
    }
    const auto store = [&](std::vector<std::vector<double>>& into, ChunkRange range, std::span<const double> values) {
      for (std::size_t q = 0; q < quantities_.size(); ++q) unpack(values, outputs.size(), column[q], to_si[q], range, into[q]);
    };
    const ChunkWork work = [&](ChunkRange range) { return fe_->evaluate_chunk(fe_line, design, range); };
    const ChunkSink sink = [&](ChunkRange range, std::span<const double> values) { store(fe_values, range, values); };
    run_with_journal(pool, journal, audited, n, c.shell_fe_chunk_size, work, sink, sink);
    if (!pool.is_coordinator()) continue;
    // The fast fidelity takes microseconds a sample: all M here, in the run's chunks.
    for (std::size_t begin = 0; begin < m; begin += c.chunk_size) {
      const ChunkRange range{begin, std::min(m, begin + c.chunk_size)};
      store(fast_values, range, fast_->evaluate_chunk(fast_line, design, range));
    }
    for (std::size_t q = 0; q < quantities_.size(); ++q) {
      AuditRow row;
      row.line = fast_line.campaign_line.name;
      row.fidelity = std::string(to_string(c.fidelity_of(fast_line.campaign_line)));
      row.quantity = quantities_[q];
      row.unit = std::string(find_quantity(quantities_[q])->default_unit);
      row.audit_samples = n;
      // The pairs first, then the fast fidelity's other samples: estimate_multifidelity reads
      // the first N of its M low-fidelity values as the paired ones.
      std::vector<double> high, low;
      for (std::size_t i = 0; i < n; ++i) {
        if (holds_value(fe_values[q][i]) && holds_value(fast_values[q][i])) {
          high.push_back(fe_values[q][i]);
          low.push_back(fast_values[q][i]);
        }
      }
      std::vector<double> low_all = low;
      for (std::size_t j = n; j < m; ++j) {
        if (holds_value(fast_values[q][j])) low_all.push_back(fast_values[q][j]);
      }
      row.pairs = high.size();
      double fast_sum = 0;
      for (const double value : fast_values[q]) {
        if (!holds_value(value)) continue;
        fast_sum += value;
        ++row.fast_samples;
      }
      row.fast_mean = row.fast_samples > 0 ? fast_sum / static_cast<double>(row.fast_samples) : std::nan("");
      if (row.pairs >= 3) row.estimate = estimate_multifidelity(high, low, low_all);
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

namespace {

std::string with_interval(const IntervalEstimate& estimate) {
  return significant(estimate.estimate) + " [" + significant(estimate.low) + ", " + significant(estimate.high) + "]";
}

}  // namespace

std::string audit_table(const std::vector<AuditRow>& rows, const Campaign& campaign) {
  if (rows.empty()) return "";
  std::ostringstream out;
  out << "\naudit: the fast fidelity against shell_fe (mesh " << to_string(campaign.shell_fe.mesh) << ") on the first "
      << campaign.audit.samples << " samples of each line; bias = mean of shell_fe - fast, with 95 % intervals; shell_fe's\n"
      << "mean and median estimated from the pairs and all " << campaign.samples << " fast samples (multifidelity):\n";
  const std::size_t widths[] = {18, 12, 10, 7, 11, 30, 7, 30, 30};
  const char* headers[] = {"line", "fidelity", "output", "pairs", "fast mean", "bias [95 %]", "rho", "shell_fe mean [95 %]",
                           "shell_fe median [95 %]"};
  for (std::size_t i = 0; i < 9; ++i) out << padded(headers[i], widths[i]);
  out << "\n";
  for (const AuditRow& row : rows) {
    out << padded(row.line, widths[0]) << padded(row.fidelity, widths[1]) << padded(row.quantity + " [" + row.unit + "]", widths[2])
        << padded(std::to_string(row.pairs) + "/" + std::to_string(row.audit_samples), widths[3]) << padded(significant(row.fast_mean), widths[4]);
    if (row.estimate) {
      out << padded(with_interval(row.estimate->bias), widths[5]) << padded(significant(row.estimate->correlation), widths[6])
          << padded(with_interval(row.estimate->mean), widths[7]) << with_interval(row.estimate->quantile);
    } else {
      out << "fewer than 3 samples with both values: nothing estimated";
    }
    out << "\n";
  }
  out << "(" << audit_csv_name << ")\n";
  return out.str();
}

std::string audit_csv(const std::vector<AuditRow>& rows) {
  std::string text =
      "line,fidelity,quantity,unit,audit_samples,pairs,fast_samples,fast_mean,bias,bias_se,bias_ci_low,bias_ci_high,"
      "correlation,alpha,mean,mean_se,mean_ci_low,mean_ci_high,mean_se_shell_fe_alone,median,median_se,median_ci_low,"
      "median_ci_high\n";
  for (const AuditRow& row : rows) {
    text += row.line + "," + row.fidelity + "," + row.quantity + "," + row.unit + "," + std::to_string(row.audit_samples) + "," +
            std::to_string(row.pairs) + "," + std::to_string(row.fast_samples) + "," + number_cell(row.fast_mean);
    const auto add = [&](const IntervalEstimate& e) {
      text += "," + number_cell(e.estimate) + "," + number_cell(e.standard_error) + "," + number_cell(e.low) + "," + number_cell(e.high);
    };
    if (row.estimate) {
      const MultifidelityEstimate& e = *row.estimate;
      add(e.bias);
      text += "," + number_cell(e.correlation) + "," + number_cell(e.alpha);
      add(e.mean);
      text += "," + number_cell(e.high_only_standard_error);
      add(e.quantile);
    } else {
      text += std::string(15, ',');
    }
    text += "\n";
  }
  return text;
}

}  // namespace growthuq
