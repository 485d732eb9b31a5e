// growthuq correlate: the Spearman matrix of (k, h, d, d0) from the forward thin-shell model
// over physically plausible (p, E, h, d0), written in the matrix CSV format that
// `growthuq sample --rank-correlation` reads. Ranges come from flags or a config file.
#include <iomanip>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"
#include "growthuq/correlation/matrix_file.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/io/read_text_file.hpp"
#include "growthuq/mechanics/instrument.hpp"
#include "growthuq/mechanics/mechanical_correlation.hpp"
#include "options.hpp"
#include "result_output.hpp"

namespace growthuq::cli {
namespace {

constexpr std::string_view command = "growthuq correlate";

struct CorrelateOptions {
  std::string p_MPa = "0.1:0.8";
  std::string E_MPa = "5:200";
  std::string h_nm = "100:300";
  std::string d0_um = "4:8";
  std::string scale = "uniform";
  std::string rho_um;
  std::string nu = "0.2";
  std::string samples = "10000";
  std::string seed = "1";
  std::string config;
  std::string out;
  bool force = false;
};

// Where a setting came from, for messages: the command line, or the config file and the line
// that sets it.
class Origins {
 public:
  Origins(std::set<std::string> from_command_line, std::string config)
      : from_command_line_(std::move(from_command_line)), config_(std::move(config)) {}

  std::string location(const std::string& key) const {
    const long line = config_line(key);
    return line > 0 ? file_location(config_, line) : std::string(command);
  }

  // The key as the user wrote it: "--seed" on the command line, "seed" in the config file.
  std::string label(const std::string& key) const { return config_line(key) > 0 ? key : "--" + key; }

 private:
  // The line of the config file that set `key`; 0 when it came from the command line or its
  // default.
  long config_line(const std::string& key) const {
    if (config_.empty() || from_command_line_.count(key)) return 0;
    std::istringstream file(detail::read_text_file(config_));
    std::string line;
    for (long number = 1; std::getline(file, line); ++number) {
      const std::string_view text = trim(line);
      if (text.rfind(key, 0) == 0 && trim(text.substr(key.size())).rfind('=', 0) == 0) return number;
    }
    return 0;
  }


  std::set<std::string> from_command_line_;
  std::string config_;
};

DrawRange parse_range(const std::string& text, const Origins& origins, const std::string& key, double unit) {
  const std::string location = origins.location(key);
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw_bad_value(location, origins.label(key), text, "LOW:HIGH, e.g. 0.1:0.8");
  const auto low = try_parse_double(std::string_view(text).substr(0, colon));
  const auto high = try_parse_double(std::string_view(text).substr(colon + 1));
  if (!low || !high || !(*low > 0) || !(*low < *high)) {
    throw_bad_value(location, origins.label(key), text, "LOW:HIGH with numbers 0 < LOW < HIGH");
  }
  return {*low * unit, *high * unit};
}

void print_matrix(const MechanicalCorrelation& result, std::ostream& report) {
  report << std::left << std::setw(6) << "";
  for (const std::string& name : result.names) report << std::right << std::setw(10) << name;
  report << "\n";
  for (Eigen::Index a = 0; a < 4; ++a) {
    report << std::left << std::setw(6) << result.names[static_cast<std::size_t>(a)];
    for (Eigen::Index b = 0; b < 4; ++b) {
      std::ostringstream cell;
      cell << std::fixed << std::setprecision(4) << result.spearman(a, b);
      report << std::right << std::setw(10) << cell.str();
    }
    report << "\n";
  }
}

}  // namespace

int run_correlate(const Arguments& arguments) {
  CorrelateOptions options;
  po::options_description ranges("ranges and model (command line or --config file, same keys)");
  ranges.add_options()
      ("p-MPa", po::value(&options.p_MPa), "turgor range LOW:HIGH [MPa] (default 0.1:0.8)")
      ("E-MPa", po::value(&options.E_MPa), "wall modulus range [MPa] (default 5:200)")
      ("h-nm", po::value(&options.h_nm), "wall thickness range [nm] (default 100:300)")
      ("d0-um", po::value(&options.d0_um), "plasmolysed diameter range [um] (default 4:8)")
      ("scale", po::value(&options.scale), "uniform (default) or log: draw each quantity uniformly or log-uniformly")
      ("rho-um", po::value(&options.rho_um), "probe radius [um] (required)")
      ("nu", po::value(&options.nu), "Poisson ratio of the wall (default 0.2)")
      ("samples", po::value(&options.samples), "number of drawn tubes (default 10000)")
      ("seed", po::value(&options.seed), "seed of the draws (default 1)");
  po::options_description described("options");
  described.add(ranges);
  described.add_options()
      ("config", po::value(&options.config), "INI-style file of the keys above (key = value); flags override it")
      ("out", po::value(&options.out), "matrix CSV to write (header k,h,d,d0, one row per variable); - writes it to "
                                       "standard output (the report then goes to standard error)")
      ("force", po::bool_switch(&options.force), "overwrite --out if it exists");
  po::variables_map values;
  if (!parse_arguments(arguments, "correlate", "--rho-um R [--p-MPa LOW:HIGH ...] [--config FILE] [--out matrix.csv]",
                       "Draws tubes with turgor p, modulus E, thickness h and plasmolysed diameter d0 in the given\n"
                       "ranges, solves the forward thin-shell model for the turgid diameter d and the stiffness k\n"
                       "(Lambert W; tubes with p d0 / (2 h E) > 1/e burst and are dropped), and prints and writes\n"
                       "the Spearman rank correlation of (k, h, d, d0). Draws: std::mt19937_64 seeded with --seed,\n"
                       "p, E, h, d0 per tube in that order, 53 bits per number: the same on every platform.",
                       described, {}, values)) {
    return 0;
  }
  std::set<std::string> from_command_line;
  for (const auto& [key, value] : values) {
    if (!value.defaulted()) from_command_line.insert(key);
  }
  if (!options.config.empty()) {
    std::istringstream file(detail::read_text_file(options.config));
    try {
      po::store(po::parse_config_file(file, ranges), values);
      po::notify(values);
    } catch (const po::error& error) {
      throw InputError(options.config, std::string(error.what()) + " (keys: p-MPa, E-MPa, h-nm, d0-um, scale, "
                                                                   "rho-um, nu, samples, seed)");
    }
  }
  const Origins origins(from_command_line, options.config);

  MechanicalDrawOptions draws;
  draws.p = parse_range(options.p_MPa, origins, "p-MPa", unit_factor::MPa);
  draws.E = parse_range(options.E_MPa, origins, "E-MPa", unit_factor::MPa);
  draws.h = parse_range(options.h_nm, origins, "h-nm", unit_factor::nm);
  draws.d0 = parse_range(options.d0_um, origins, "d0-um", unit_factor::um);
  if (options.scale == "uniform") {
    draws.scale = DrawScale::uniform;
  } else if (options.scale == "log") {
    draws.scale = DrawScale::log_uniform;
  } else {
    throw_bad_value(origins.location("scale"), origins.label("scale"), options.scale, "uniform or log");
  }
  draws.samples = parse_count(options.samples, origins.location("samples"), origins.label("samples"), 3, 100000000);
  draws.seed = parse_count(options.seed, origins.location("seed"), origins.label("seed"));

  // The instrument through the parser every command and the campaign file use, each setting
  // located where it was written (flag or config line).
  const auto entry = [&origins](const std::string& text, const std::string& key) {
    return InstrumentEntry{text.empty() ? std::nullopt : std::optional<std::string>(text), origins.location(key),
                           origins.label(key)};
  };
  const Instrument shell = parse_instrument({entry(options.rho_um, "rho-um"), entry(options.nu, "nu"), {}},
                                            ProbeRadius::required);
  const Overwrite overwrite = options.force ? Overwrite::allow : Overwrite::refuse;
  if (!options.out.empty()) check_result_target(options.out, overwrite);

  const MechanicalCorrelation result = mechanical_rank_correlation(draws, shell, command);
  const std::vector<std::string> names(result.names.begin(), result.names.end());
  if (!options.out.empty()) {
    write_result(options.out, format_rank_correlation_csv(names, result.spearman), overwrite);
  }

  std::ostream& report = report_stream(options.out);
  report << "forward thin-shell model: " << result.drawn << " tubes drawn "
            << (draws.scale == DrawScale::uniform ? "uniformly" : "log-uniformly") << " (p " << options.p_MPa
            << " MPa, E " << options.E_MPa << " MPa, h " << options.h_nm << " nm, d0 " << options.d0_um
            << " um; rho = " << options.rho_um << " um, nu = " << options.nu << ", seed " << draws.seed << ")\n"
            << "  burst (p d0 / (2 h E) > 1/e), dropped: " << result.burst << "\n";
  if (result.other_dropped > 0) report << "  dropped for another status: " << result.other_dropped << "\n";
  report << "  kept: " << result.kept << "\n\nSpearman rank correlation\n";
  print_matrix(result, report);
  if (!options.out.empty()) report << "\n" << wrote(options.out) << "\n";
  return 0;
}

}  // namespace growthuq::cli
