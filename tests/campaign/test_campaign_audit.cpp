// [audit] through the CLI (tests/campaign/data/audit_campaign.ini: one closed-form line of 12
// samples, the first 4 also through shell_fe on the coarse mesh): audit.csv's bias of p and E
// is the mean of `growthuq eval --fidelity shell_fe` minus the closed form over the same tubes
// (samples.csv's first 4 rows, an independent path into the finite elements), its fast mean the
// mean of samples.csv's column, and the table is printed.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

// audit.csv's rows as maps from header to cell.
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  const std::vector<std::string> lines = split_text(text, '\n');
  const std::vector<std::string> header = split_text(lines.at(0), ',');
  std::vector<std::map<std::string, std::string>> rows;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    std::vector<std::string> cells = split_text(lines[r], ',');
    cells.resize(header.size());
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < header.size(); ++c) row[header[c]] = cells[c];
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("campaign audit: the bias in audit.csv is eval --fidelity shell_fe minus the closed form on the same samples") {
  ScratchDirectory scratch("campaign_audit");
  const std::string source = std::string(GROWTHUQ_SOURCE_DIR);
  std::string text = slurp(source + "/tests/campaign/data/audit_campaign.ini");
  text.replace(text.find("../../../distributions/"), 23, source + "/distributions/");
  spit(scratch.root / "audited.ini", text);

  const CliOutcome run = run_in(scratch.root, cli({"run", "audited.ini", "--quiet", "--summary-only"}));
  REQUIRE_MESSAGE(run.exit_code == 0, run.err);
  CHECK(run.out.find("audit: the fast fidelity against shell_fe (mesh coarse) on the first 4 samples") != std::string::npos);
  CHECK(run.err.find("4 of the samples are the audit's") != std::string::npos);  // the time estimate

  const std::vector<std::string> samples = split_text(slurp(scratch.root / "audit_out" / "samples.csv"), '\n');
  REQUIRE(samples.size() == 13);
  REQUIRE(samples[0] == "line,sample,k_N_per_m,h_nm,d_um,d0_um,p_MPa,E_MPa,status");
  double fast_sum[2] = {0, 0}, difference_sum[2] = {0, 0};
  std::size_t pairs = 0;
  for (std::size_t r = 1; r <= 12; ++r) {
    const std::vector<std::string> cells = split_text(samples[r], ',');
    REQUIRE(cells.size() == 9);
    REQUIRE(cells[8] == "ok");
    for (int q = 0; q < 2; ++q) fast_sum[q] += std::stod(cells[6 + q]);
    if (r > 4) continue;
    const CliOutcome eval = run_in(scratch.root, cli({"eval", "--fidelity", "shell_fe", "--mesh", "coarse", "--rho-um", "0.5", "--k",
                                                      cells[2], "--h-nm", cells[3], "--d-um", cells[4], "--d0-um", cells[5]}));
    const double p = printed_value(eval.out, "p"), E = printed_value(eval.out, "E");
    if (eval.exit_code != 0 || !std::isfinite(p) || !std::isfinite(E)) continue;  // a sample shell_fe flags is no pair
    difference_sum[0] += p - std::stod(cells[6]);
    difference_sum[1] += E - std::stod(cells[7]);
    ++pairs;
  }
  REQUIRE(pairs >= 3);

  const auto rows = csv_rows(slurp(scratch.root / "audit_out" / "audit.csv"));
  REQUIRE(rows.size() == 2);
  const char* quantities[] = {"p", "E"};
  for (int q = 0; q < 2; ++q) {
    const auto& row = rows[static_cast<std::size_t>(q)];
    CAPTURE(quantities[q]);
    CHECK(row.at("line") == "wild_type");
    CHECK(row.at("fidelity") == "closed_form");
    CHECK(row.at("quantity") == quantities[q]);
    CHECK(row.at("unit") == "MPa");
    CHECK(std::stoul(row.at("pairs")) == pairs);
    CHECK(std::stod(row.at("fast_mean")) == doctest::Approx(fast_sum[q] / 12).epsilon(1e-12));
    // eval's inverse stops at 1e-4 relative (src/fe/README.md), the bias is about half of p.
    const double bias = difference_sum[q] / static_cast<double>(pairs);
    CHECK(std::stod(row.at("bias")) == doctest::Approx(bias).epsilon(2e-3));
    CHECK(std::stod(row.at("bias_ci_low")) < std::stod(row.at("bias")));
    CHECK(std::stod(row.at("bias_ci_high")) > std::stod(row.at("bias")));
    // The multifidelity estimates inside their own intervals.
    CHECK(std::stod(row.at("mean_ci_low")) <= std::stod(row.at("mean")));
    CHECK(std::stod(row.at("mean")) <= std::stod(row.at("mean_ci_high")));
    CHECK(std::stod(row.at("median_ci_low")) <= std::stod(row.at("median")));
    CHECK(std::stod(row.at("median")) <= std::stod(row.at("median_ci_high")));
  }
}
