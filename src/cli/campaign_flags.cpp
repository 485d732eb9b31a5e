#include "campaign_flags.hpp"

#include "growthuq/core/numbers.hpp"

namespace growthuq::cli {

void CampaignFlags::declare(po::options_description& options) {
  options.add_options()
      ("samples", po::value(&samples), "samples per line (overrides [campaign] samples)")
      ("seed", po::value(&seed), "campaign seed, 0 to 2^64 - 1 (overrides [campaign] seed)")
      ("out", po::value(&out), "output directory (overrides [campaign] output_dir)")
      ("lines", po::value(&lines), "comma-separated subset of the campaign's lines (keep the reference line)")
      ("formats", po::value(&formats), "csv, hdf5 or csv,hdf5 (summary.csv is always written)")
      ("fidelity", po::value(&fidelity), "closed_form, corrected or shell_fe: every line's model of turgor and modulus "
                                         "(overrides [campaign] fidelity and the lines' own)");
}

CampaignOverrides CampaignFlags::overrides(const po::variables_map& values, std::string_view location) const {
  CampaignOverrides overrides;
  if (values.count("samples")) overrides.samples = parse_count(samples, location, "--samples", 1, 4294967295ULL);
  if (values.count("seed")) overrides.seed = parse_count(seed, location, "--seed");
  if (values.count("out")) overrides.output_dir = out;
  if (values.count("lines")) overrides.lines = lines;
  if (values.count("formats")) overrides.formats = formats;
  if (values.count("fidelity")) {
    parse_fidelity(fidelity, location, "--fidelity");  // refused here, before anything is read
    overrides.fidelity = fidelity;
  }
  return overrides;
}

}  // namespace growthuq::cli
