// A raw-data line as a lab exports it from Excel where the decimal separator is a comma: raw.ini
// and the table with byte-order marks and CRLF, the unit written "µm/min", numbers with decimal
// commas. It fits exactly as the same data in the plain dialect does.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/rawdata/raw_line_file.hpp"
#include "growthuq/rawdata/raw_line_fit.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using growthuq::testing::ScratchDirectory;
using growthuq::testing::spit;

namespace {

const std::string bom = "\xEF\xBB\xBF";

// Growth rates in um/min, as written with a decimal comma and with a decimal point.
const std::vector<std::string> rates_comma{"0,31", "0,42", "0,27", "0,55", "0,38", "0,46", "0,29", "0,35"};
const std::vector<std::string> rates_point{"0.31", "0.42", "0.27", "0.55", "0.38", "0.46", "0.29", "0.35"};

RawLineFit fit_folder(const ScratchDirectory& scratch, const std::string& raw_ini, const std::string& table) {
  spit(scratch.root / "growth.csv", table);
  spit(scratch.root / "raw.ini", raw_ini);
  return fit_raw_line(read_raw_line_file((scratch.root / "raw.ini").string()), RawFitSettings{});
}

}  // namespace

TEST_CASE("raw data from Excel (BOM, CRLF, ';' and decimal commas, µm/min) fits as the plain file does") {
  ScratchDirectory excel("excel_raw_line");
  std::string table = bom + "Tube;Growth rate (\xC2\xB5m/min)\r\n";
  for (std::size_t i = 0; i < rates_comma.size(); ++i) table += "T" + std::to_string(i + 1) + ";" + rates_comma[i] + "\r\n";
  const RawLineFit fit = fit_folder(excel,
                                    bom + "[line]\r\nname = excel  # exported 2026-11-30\r\n\r\n"
                                          "[measurement v_exp]\r\nfile = growth.csv\r\n"
                                          "column = Growth rate (\xC2\xB5m/min)\r\n"
                                          "unit = \xC2\xB5m/min ; as the lab's software writes it\r\n"
                                          "families = lognormal, gamma\r\n",
                                    table);
  REQUIRE(fit.variables.size() == 1);
  CHECK(fit.variables[0].values == std::vector<double>{0.31, 0.42, 0.27, 0.55, 0.38, 0.46, 0.29, 0.35});
  const LineVariable* v_exp = fit.distributions.find("v_exp");
  REQUIRE(v_exp != nullptr);
  CHECK(v_exp->unit == &find_unit("um/min", "", "unit"));

  ScratchDirectory plain("plain_raw_line");
  std::string plain_table = "tube,v_exp_um_per_min\n";
  for (std::size_t i = 0; i < rates_point.size(); ++i) plain_table += "T" + std::to_string(i + 1) + "," + rates_point[i] + "\n";
  const RawLineFit reference = fit_folder(plain,
                                          "[line]\nname = excel\n[measurement v_exp]\nfile = growth.csv\n"
                                          "column = v_exp_um_per_min\nunit = um/min\nfamilies = lognormal, gamma\n",
                                          plain_table);
  // The same family and the same law, bit for bit.
  CHECK(fit.variables[0].best().family == reference.variables[0].best().family);
  for (const double u : {0.05, 0.5, 0.95}) {
    CHECK(quantile(v_exp->distribution, u) == quantile(reference.distributions.find("v_exp")->distribution, u));
  }
  // The fitted line file names the unit in ASCII and reads back.
  spit(excel.root / "fitted.ini", fitted_line_file_text(fit));
  const LineDistributions back = read_line_file((excel.root / "fitted.ini").string());
  CHECK(back.name == "excel");
  CHECK(back.find("v_exp")->unit->symbol == "um/min");
}
