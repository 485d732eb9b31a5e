// A campaign run in this process (serially), keeping only each line's summaries of the
// campaign's outputs: what the campaign tests compare with a reference.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/pool/pool.hpp"
#include "growthuq/stats/quantity_summary.hpp"

namespace growthuq::testing {

// Summaries keyed by (line, quantity).
using LineSummaries = std::map<std::pair<std::string, std::string>, QuantitySummary>;

// Keeps each finished line's summaries of the campaign's outputs.
class SummaryObserver final : public RunObserver {
 public:
  explicit SummaryObserver(const Campaign& campaign) : campaign_(campaign) {}
  void line_started(const PreparedLine&, std::size_t) override {}
  void chunk_done(ChunkRange) override {}
  void line_done(const LineResult& result, const std::vector<std::string>&) override {
    for (const ResultColumn& column : result.columns) {
      for (const std::string& output : campaign_.outputs) {
        if (column.quantity == output) summaries[{result.name, output}] = summarize_quantity(result.name, column);
      }
    }
  }
  LineSummaries summaries;

 private:
  const Campaign& campaign_;
};

inline LineSummaries run_summaries(const PreparedCampaign& prepared) {
  SummaryObserver observer(prepared.campaign());
  const std::unique_ptr<Pool> pool = make_serial_pool();
  run_campaign_lines(prepared, *pool, observer);
  return observer.summaries;
}

}  // namespace growthuq::testing
