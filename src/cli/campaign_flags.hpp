// The command-line flags that change what a campaign runs (--samples, --seed, --out, --lines,
// --formats, --fidelity), shared by `growthuq run` and `growthuq check` so that a check sees the campaign
// exactly as the run with the same flags would.
#pragma once

#include <string>
#include <string_view>

#include "growthuq/campaign/campaign_file.hpp"
#include "options.hpp"

namespace growthuq::cli {

struct CampaignFlags {
  std::string samples;  // as typed, parsed strictly by overrides()
  std::string seed;
  std::string out;
  std::string lines;
  std::string formats;
  std::string fidelity;

  // Adds the six flags to `options`.
  void declare(po::options_description& options);
  // The flags given, validated (errors located at `location`, "growthuq run").
  CampaignOverrides overrides(const po::variables_map& values, std::string_view location) const;
};

// The names of the flags above, for commands that refuse them in some mode (run --resume).
inline constexpr std::string_view campaign_flag_names[] = {"samples", "seed", "out", "lines", "formats", "fidelity"};

}  // namespace growthuq::cli
