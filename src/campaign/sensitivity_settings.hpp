// A campaign's [sensitivity] section: which indices beyond the first-order ones (always made, from
// the samples) and what the Shapley effects may cost (src/sensitivity/README.md, Eqs. (S3)-(S5)):
//   [sensitivity]
//   method = shapley            # first_order (default), shapley or sobol (each with first-order;
//                               # sobol only for lines without a rank correlation)
//   outer = 200                 # N_o: draws of the other inputs per subset (exact permutations)
//   inner = 3                   # N_i: conditional draws per outer draw (Song et al. 2016: 3)
//   permutations = 1000         # random permutations, used beyond 6 inputs
//   variance_samples = 1000     # N_v: joint draws for Var(output)
//   sobol_samples = 1000        # N of the two Sobol designs: N (d + 2) runs
// Read when the campaign is read (an error names file:line, key, value and what was expected)
// and again from the campaign's text when the run needs it, so that the Campaign type and the
// many files built on it need not carry it.
#pragma once

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/sensitivity/shapley.hpp"
#include "growthuq/sensitivity/sobol.hpp"
#include "io/ini.hpp"

namespace growthuq {

struct SensitivitySettings {
  bool shapley = false;
  bool sobol = false;
  ShapleySettings cost;      // key set per line by the run
  SobolSettings sobol_cost;  // the same
};

// The section `section` of `document` ([sensitivity]); InputError for an unknown key or a bad value.
SensitivitySettings read_sensitivity_section(const IniDocument& document, const IniSection& section);

// The settings of `campaign` (its text parsed again); defaults when it has no [sensitivity].
SensitivitySettings sensitivity_settings(const Campaign& campaign);

}  // namespace growthuq
