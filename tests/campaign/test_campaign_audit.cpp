// [audit] through the CLI (tests/campaign/data/audit_campaign.ini: one closed-form line of 12
// samples, the first 4 also through shell_fe on the coarse mesh): audit.csv's bias of p and E
// is the mean of `growthuq eval --fidelity shell_fe` minus the closed form over the same tubes
// (samples.csv's first 4 rows, an independent path into the finite elements), its fast mean the
// mean of samples.csv's column, and the table is printed; provenance.json, results.h5's
// /provenance/audit and the report's warnings quote the same bias. A run stopped by SIGTERM
// during the audit keeps the audit's finished samples in its checkpoint, and --resume reuses
// them and writes every result file byte for byte as the uninterrupted run does.
#include <doctest/doctest.h>

#include <hdf5.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "campaign/chunk_log.hpp"
#include "support/cli_run.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
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

// The test campaign in `directory` (its line file by absolute path), as audited.ini.
void write_campaign(const fs::path& directory) {
  const std::string source = std::string(GROWTHUQ_SOURCE_DIR);
  std::string text = slurp(source + "/tests/campaign/data/audit_campaign.ini");
  text.replace(text.find("../../../distributions/"), 23, source + "/distributions/");
  fs::create_directories(directory);
  spit(directory / "audited.ini", text);
}

// The number after `"key": ` in `text` from position `from` on (provenance.json); NaN for null.
double json_number(const std::string& text, std::size_t from, const std::string& key) {
  const std::string marker = "\"" + key + "\": ";
  const std::size_t at = text.find(marker, from);
  REQUIRE(at != std::string::npos);
  const std::string value = text.substr(at + marker.size(), 32);
  return value.rfind("null", 0) == 0 ? std::nan("") : std::stod(value);
}

// The float64 attribute `name` of the object at `path` in the HDF5 file `file`.
double h5_attribute(hid_t file, const std::string& path, const std::string& name) {
  const hid_t attribute = H5Aopen_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE_MESSAGE(attribute >= 0, path << " " << name);
  double value = std::nan("");
  CHECK(H5Aread(attribute, H5T_NATIVE_DOUBLE, &value) >= 0);
  H5Aclose(attribute);
  return value;
}

// Four significant digits, as the report prints a number (tools/reporting/tables.py).
std::string four_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

const char* const result_files[] = {"samples.csv", "summary.csv", "sensitivity.csv", "audit.csv", "provenance.json"};

}  // namespace

TEST_CASE("campaign audit: the bias in audit.csv is eval --fidelity shell_fe minus the closed form on the same samples") {
  ScratchDirectory scratch("campaign_audit");
  write_campaign(scratch.root);

  const CliOutcome run = run_in(scratch.root, cli({"run", "audited.ini", "--quiet", "--summary-only", "--formats", "csv,hdf5"}));
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

  // provenance.json and results.h5 /provenance/audit hold the same bias and interval, and the
  // report's warnings quote them.
  const hid_t h5 = H5Fopen((scratch.root / "audit_out" / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(h5 >= 0);
  const std::string provenance = slurp(scratch.root / "audit_out" / "provenance.json");
  const std::size_t audit = provenance.find("\"audit\": {\"samples_per_line\": 4, \"high_fidelity\": \"shell_fe\", \"mesh\": \"coarse\"");
  REQUIRE(audit != std::string::npos);
  const CliOutcome report = run_in(scratch.root, cli({"report", "audit_out", "--out", "report.html"}));
  REQUIRE_MESSAGE(report.exit_code == 0, report.err);
  const std::string page = slurp(scratch.root / "report.html");
  CHECK(page.find("wild_type: closed_form measured against shell_fe (mesh coarse) in this run, on its first 4 samples") !=
        std::string::npos);
  for (int q = 0; q < 2; ++q) {
    const auto& row = rows[static_cast<std::size_t>(q)];
    CAPTURE(quantities[q]);
    const std::size_t at = provenance.find("\"quantity\": \"" + std::string(quantities[q]) + "\"", audit);
    REQUIRE(at != std::string::npos);
    CHECK(json_number(provenance, at, "pairs") == static_cast<double>(pairs));
    const double bias = json_number(provenance, at, "bias"), low = json_number(provenance, at, "bias_ci_low"),
                 high = json_number(provenance, at, "bias_ci_high");
    CHECK(bias == doctest::Approx(std::stod(row.at("bias"))).epsilon(1e-12));
    CHECK(low == doctest::Approx(std::stod(row.at("bias_ci_low"))).epsilon(1e-12));
    CHECK(high == doctest::Approx(std::stod(row.at("bias_ci_high"))).epsilon(1e-12));
    const std::string group = "provenance/audit/wild_type/" + std::string(quantities[q]);
    CHECK(h5_attribute(h5, group, "bias") == bias);  // provenance.json's numbers read back to the same double
    CHECK(h5_attribute(h5, group, "bias_ci_low") == low);
    CHECK(h5_attribute(h5, group, "bias_ci_high") == high);
    const std::string quoted = std::string(quantities[q]) + " " + four_digits(bias) + " MPa (95 % interval " + four_digits(low) +
                               " to " + four_digits(high) + ", " + std::to_string(pairs) + " pairs)";
    CHECK_MESSAGE(page.find(quoted) != std::string::npos, quoted);
  }
  H5Fclose(h5);
}

TEST_CASE("campaign audit: a run stopped during the audit resumes it without redoing its finished samples") {
  ScratchDirectory scratch("campaign_audit_resume");
  const std::vector<std::string> command = cli({"run", "audited.ini", "--quiet", "--summary-only"});
  const fs::path reference = scratch.root / "reference", work = scratch.root / "interrupted";
  write_campaign(reference);
  write_campaign(work);
  const CliOutcome uninterrupted = run_in(reference, command);
  REQUIRE_MESSAGE(uninterrupted.exit_code == 0, uninterrupted.err);

  // SIGTERM once the audit's log holds its first finite-element sample: the run stops after the
  // samples under way, with at least that one kept and the lines not started.
  const pid_t pid = start(command, work);
  const fs::path log = work / "audit_out" / "checkpoint" / "audit.bin";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  for (;;) {
    std::error_code error;
    if (fs::file_size(log, error) > 16 && !error && !scan_chunk_log(log.string()).records.empty()) break;
    int status = 0;
    REQUIRE_MESSAGE(waitpid(pid, &status, WNOHANG) == 0, "the run ended before it could be interrupted");
    REQUIRE_MESSAGE(std::chrono::steady_clock::now() < deadline, "no audit sample in the checkpoint after 300 s");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGTERM);
  const CliOutcome stopped = outcome_in(work, wait_for(pid));
  REQUIRE(stopped.exit_code == 143);
  std::size_t kept = 0;
  for (const ChunkRecord& record : scan_chunk_log(log.string()).records) kept += record.range.end - record.range.begin;
  REQUIRE(kept >= 1);
  REQUIRE(kept < 4);  // stopped part way: the resume has audit samples left to run
  CHECK_MESSAGE(stopped.err.find("interrupted after 0 of 12 samples (and " + std::to_string(kept) + " of the audit's 4)") !=
                    std::string::npos,
                stopped.err);
  CHECK(!fs::exists(work / "audit_out" / "audit.csv"));

  // Resumed with progress on (stderr is no terminal: a line per audited line), the audit says
  // how many of its samples the checkpoint gave it.
  const CliOutcome resumed = run_in(work, cli({"run", "--resume", "audit_out", "--summary-only"}));
  REQUIRE_MESSAGE(resumed.exit_code == 0, resumed.err);
  CHECK_MESSAGE(resumed.err.find("audit of line wild_type: 4 samples through shell_fe, " + std::to_string(kept) +
                                 " of them kept by the checkpoint") != std::string::npos,
                resumed.err);
  CHECK(resumed.out == uninterrupted.out);
  for (const char* name : result_files) {
    CAPTURE(name);
    const std::string a = slurp(work / "audit_out" / name), b = slurp(reference / "audit_out" / name);
    CHECK(!a.empty());
    CHECK_MESSAGE(a == b, "differs byte for byte from the uninterrupted run's");
  }
  CHECK(!fs::exists(work / "audit_out" / "checkpoint"));
}
