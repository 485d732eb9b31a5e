// growthuq fit: maximum-likelihood fits of lognormal, normal, gamma and Weibull laws to one
// column of raw per-tube measurements, a table sorted by AIC, and optionally the chosen law
// written as a line file (distribution entry) for `growthuq sample`.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/distributions/fit.hpp"
#include "growthuq/distributions/line_file.hpp"
#include "growthuq/io/csv.hpp"
#include "growthuq/io/output_file.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {
namespace {

constexpr std::array<std::string_view, 7> measured_variables{"k", "h", "d", "d0", "tau", "einf", "v_exp"};

struct FitOptions {
  std::string data;
  std::string column;
  std::string family;    // empty: every family, best AIC chosen
  std::string variable;  // empty: from the column name
  std::string unit;
  std::string write;     // empty: no file
  bool force = false;
};

struct Target {
  std::string variable;
  const Unit* unit = nullptr;
};

// The measured variable and unit a column name like "k_N_per_m" spells, if any.
std::optional<Target> target_from_column(std::string_view column) {
  for (const std::string_view name : measured_variables) {
    if (const Unit* unit = unit_of_column(*find_quantity(name), column)) return Target{std::string(name), unit};
  }
  return std::nullopt;
}

Target resolve_target(const FitOptions& options) {
  const std::string where;  // main() already prefixes "growthuq fit: error:"
  if (options.variable.empty() != options.unit.empty()) {
    throw InputError(where, "--variable and --unit go together: give both, or neither when the column is named "
                            "<variable>_<unit> (e.g. k_N_per_m)");
  }
  if (options.variable.empty()) {
    if (auto target = target_from_column(options.column)) return *target;
    throw InputError(where, "--column " + options.column +
                                ": cannot tell the variable and unit from the name (expected e.g. k_N_per_m, h_nm, "
                                "d_um, einf_pct); give --variable and --unit");
  }
  if (std::find(measured_variables.begin(), measured_variables.end(), options.variable) == measured_variables.end()) {
    throw_bad_value(where, "--variable", options.variable, "one of k, h, d, d0, tau, einf, v_exp");
  }
  const Quantity& quantity = *find_quantity(options.variable);
  const Unit& unit = find_unit(options.unit, where, "--unit");
  if (unit.dimension != quantity.dimension) {
    throw_bad_value(where, "--unit", options.unit,
                    "a unit of " + std::string(to_string(quantity.dimension)) + " for " + options.variable);
  }
  return Target{options.variable, &unit};
}

std::string number(double value) {
  if (value == HUGE_VAL) return "inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + "  " : text + std::string(width - text.size(), ' ');
}

// "mu=1.05, sigma=0.21; ..." from "lognormal(mu=1.05, ...)".
std::string parameters_of(const Distribution& distribution) {
  const std::string text = describe(distribution);
  const std::size_t open = text.find('(');
  return text.substr(open + 1, text.size() - open - 2);
}

void print_table(const std::vector<FitResult>& fits, std::ostream& report) {
  std::size_t width = 12;
  for (const FitResult& fit : fits) width = std::max(width, parameters_of(fit.distribution).size() + 2);
  report << padded("family", 11) << padded("parameters", width) << padded("logL", 12) << padded("AIC", 12)
            << padded("dAIC", 10) << padded("KS D", 10) << "AD A^2\n";
  for (const FitResult& fit : fits) {
    report << padded(std::string(to_string(fit.family)), 11) << padded(parameters_of(fit.distribution), width)
              << padded(number(fit.log_likelihood), 12) << padded(number(fit.aic), 12)
              << padded(number(fit.aic - fits.front().aic), 10) << padded(number(fit.ks_statistic), 10)
              << number(fit.ad_statistic) << "\n";
  }
}

// `data` names the table as messages do ("standard input" for -).
std::string line_file_text(const FitOptions& options, const std::string& data, const Target& target, const FitResult& fit) {
  // A line file printed on stdout has no file name to name its line after.
  const std::string stem = is_standard_output(options.write) ? "" : std::filesystem::path(options.write).stem().string();
  LineVariable variable{target.variable, target.unit, fit.distribution,
                        "maximum-likelihood " + std::string(to_string(fit.family)) + " fit to " + data +
                            ", column " + options.column + " (n = " + std::to_string(fit.sample_size) +
                            ", AIC " + number(fit.aic) + ", KS D " + number(fit.ks_statistic) + ")",
                        "", 0, fit.sample_size};  // tubes: the data interval of a campaign on it
  return "# Written by growthuq fit. Merge the variable section into a plant line's file, or use\n"
         "# this file as it is (it is a complete line file).\n[line]\nname = " +
         (stem.empty() ? std::string("fitted") : stem) + "\ndescription = " + target.variable + " fitted from " + data +
         "\n\n" + format_line_variable(variable);
}

}  // namespace

int run_fit(const Arguments& arguments) {
  FitOptions options;
  po::options_description described("options");
  described.add_options()
      ("data", po::value(&options.data)->required(), "CSV file of per-tube measurements (header row of column names)")
      ("column", po::value(&options.column)->required(), "column to fit, e.g. k_N_per_m")
      ("family", po::value(&options.family), "fit and write only this family: lognormal, normal, gamma or weibull")
      ("variable", po::value(&options.variable), "measured variable of the column (k, h, d, d0, tau, einf, v_exp) "
                                                 "when its name does not say")
      ("unit", po::value(&options.unit), "unit of the column's values (e.g. N/m) when its name does not say")
      ("write", po::value(&options.write), "write the best-AIC family (or --family) as a line file; - writes it to "
                                           "standard output (the table then goes to standard error)")
      ("force", po::bool_switch(&options.force), "overwrite --write if it exists");
  po::positional_options_description positional;
  positional.add("data", 1);
  po::variables_map values;
  if (!parse_arguments(arguments, "fit", "DATA.csv --column NAME [--family F] [--variable V --unit U] [--write FILE] [--force]",
                       "Fits lognormal, normal, gamma and Weibull laws by maximum likelihood to one column of\n"
                       "per-tube measurements and prints them sorted by AIC (lower is better), with the\n"
                       "Kolmogorov-Smirnov D and Anderson-Darling A^2 of each fitted law (smaller is closer;\n"
                       "the parameters are estimated from the same data, so compare, do not test).",
                       described, positional, values)) {
    return 0;
  }

  std::optional<FitFamily> requested;
  if (!options.family.empty()) {
    requested = parse_fit_family(options.family);
    // The beta law of einf is fitted from raw data (fit-line, campaigns), not here yet.
    if (!requested || *requested == FitFamily::beta) {
      throw_bad_value("", "--family", options.family, "lognormal, normal, gamma or weibull");
    }
  }
  const Target target = resolve_target(options);
  if (!options.write.empty()) check_result_target(options.write, options.force ? Overwrite::allow : Overwrite::refuse);

  const CsvTable table = read_csv(options.data);
  const std::vector<double> data = table.numeric_column(options.column);  // row-numbered errors
  if (data.size() < 2) {
    throw InputError(table.path, "column " + options.column + (data.empty() ? " is empty (no data rows)" : " has one value") +
                                     ": expected at least two measurements");
  }

  // A fraction (einf) outside [0, 1) is no tube's: refused as a raw-data line refuses it
  // (rawdata/raw_line_fit.cpp), before any law is fitted to it.
  if (const Quantity* quantity = find_quantity(target.variable); quantity && quantity->dimension == Dimension::fraction) {
    for (std::size_t row = 0; row < data.size(); ++row) {
      const double si = data[row] * target.unit->to_si;
      if (!(si >= 0.0 && si < 1.0)) {
        throw_bad_value(table.row_location(row), "column " + options.column, table.rows[row][table.column_index(options.column)],
                        "a rescaled equilibrium modulus in [0, 1) (as a fraction; [0, 100) in %)");
      }
    }
  }

  // The first non-positive value rules out the positive laws: an error if one was asked for,
  // otherwise those laws are skipped with a note.
  std::optional<std::size_t> non_positive;
  for (std::size_t row = 0; row < data.size() && !non_positive; ++row) {
    if (!(data[row] > 0.0)) non_positive = row;
  }
  std::vector<FitFamily> families;
  std::vector<std::string> skipped;
  for (const FitFamily family : all_fit_families) {
    if (requested && family != *requested) continue;
    if (non_positive && needs_positive_data(family)) {
      if (requested) {
        throw_bad_value(table.row_location(*non_positive), "column " + options.column,
                        table.rows[*non_positive][table.column_index(options.column)],
                        "a positive number: the " + std::string(to_string(family)) + " law lives on x > 0");
      }
      skipped.emplace_back(to_string(family));
      continue;
    }
    families.push_back(family);
  }

  std::vector<FitResult> fits;
  for (const FitFamily family : families) {
    try {
      fits.push_back(fit_distribution(family, data));
    } catch (const InputError& error) {
      throw InputError(table.path + ", column " + options.column, error.what());
    }
  }
  std::stable_sort(fits.begin(), fits.end(), [](const FitResult& a, const FitResult& b) { return a.aic < b.aic; });

  std::ostream& report = report_stream(options.write);
  report << "n = " << data.size() << " values of " << options.column << " (" << target.variable << " in "
            << target.unit->symbol << ") from " << table.path << "\n\n";
  print_table(fits, report);
  if (!skipped.empty()) {
    std::string list;
    for (const std::string& name : skipped) list += (list.empty() ? "" : ", ") + name;
    report << "\nnote: skipped " << list << " (they need values > 0): " << table.row_location(*non_positive)
              << " has " << options.column << " = " << table.rows[*non_positive][table.column_index(options.column)]
              << "\n";
  }
  if (!options.write.empty()) {
    write_result(options.write, line_file_text(options, table.path, target, fits.front()),
                 options.force ? Overwrite::allow : Overwrite::refuse);
    report << "\nwrote " << to_string(fits.front().family) << " law of " << target.variable << " to "
           << (is_standard_output(options.write) ? "standard output" : options.write) << "\n";
  }
  return 0;
}

}  // namespace growthuq::cli
