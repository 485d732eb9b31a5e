// campaigns/arabidopsis_2022.ini reproduces what the study's text says of its results, with its
// calibrated probe radius and the line files' illustrative entries (distributions/README.md):
// xeg113 and the triple mutant have higher turgor and modulus than the wild type, pme48 lower
// turgor, xxt1 xxt2 and pme48 lower moduli, and the turgor and modulus IQRs of xeg113 and the
// triple mutant are about twice the wild type's. The shipped campaign as it is (1000 samples per
// line, seed 2022), run in this process (0.1 s).
#include <doctest/doctest.h>

#include <string>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "support/campaign_summaries.hpp"

using namespace growthuq;

namespace {

const std::string study_path = std::string(GROWTHUQ_SOURCE_DIR) + "/campaigns/arabidopsis_2022.ini";

// "Higher" as a comparison of medians can claim: the two 95 % confidence intervals of the medians
// do not overlap (Monte Carlo only: these lines are given by laws, not by data).
bool clearly_above(const QuantitySummary& high, const QuantitySummary& low) { return high.median_ci_low > low.median_ci_high; }

}  // namespace

TEST_CASE("the shipped study: the lines' turgor and moduli compare as the study's text says") {
  const Campaign campaign = read_campaign(study_path);
  CHECK(campaign.instrument.probe_radius_m == doctest::Approx(0.25e-6).epsilon(1e-12));  // calibrated on the wild type
  const PreparedCampaign prepared(campaign);
  const testing::LineSummaries summaries = testing::run_summaries(prepared);
  const auto at = [&](const char* line, const char* quantity) { return summaries.at({line, quantity}); };
  for (const char* quantity : {"p", "E"}) {
    CAPTURE(quantity);
    const QuantitySummary wild_type = at("wild_type", quantity);
    for (const char* elevated : {"xeg113", "xxt1_xxt2_xeg113"}) {
      CAPTURE(elevated);
      const QuantitySummary mutant = at(elevated, quantity);
      MESSAGE(std::string(elevated) << " " << std::string(quantity) << ": median " << mutant.median << " [" << mutant.median_ci_low << ", "
                       << mutant.median_ci_high << "], IQR " << mutant.iqr << "; wild type " << wild_type.median << " ["
                       << wild_type.median_ci_low << ", " << wild_type.median_ci_high << "], IQR " << wild_type.iqr);
      CHECK(clearly_above(mutant, wild_type));
      // "About twice": between 1.5 and 3.5 times the wild type's IQR.
      CHECK(mutant.iqr > 1.5 * wild_type.iqr);
      CHECK(mutant.iqr < 3.5 * wild_type.iqr);
    }
  }
  CHECK(clearly_above(at("wild_type", "p"), at("pme48", "p")));
  CHECK(clearly_above(at("wild_type", "E"), at("xxt1_xxt2", "E")));
  CHECK(clearly_above(at("wild_type", "E"), at("pme48", "E")));
}
