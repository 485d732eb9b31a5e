// A plant line's distribution file (distributions/<line>.ini): one section per measured
// variable with its law, parameters, unit and source. The format is documented in
// distributions/README.md and validated strictly; every error names the file and line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/core/units.hpp"
#include "growthuq/distributions/distribution.hpp"

namespace growthuq {

struct LineVariable {
  std::string name;           // quantity name: k, h, d, d0, tau, einf, v_exp
  const Unit* unit = nullptr; // the unit the distribution's values are in (as written in the file)
  Distribution distribution;  // in `unit`, not SI
  std::string source;         // citation, or "illustrative"
  std::string note;           // required when source = illustrative: why this value
  long line = 0;              // line of the section header, for messages
  // tubes = N: how many tubes the law was fitted to; 0 when the file does not say. A campaign's
  // data-uncertainty bootstrap redraws N values from the law and refits its family in each
  // replicate (campaign/stated_law_bootstrap.hpp); a law without it stays fixed there.
  std::size_t tubes = 0;
};

struct LineDistributions {
  std::string name;         // [line] name = ...
  std::string description;  // [line] description = ... (optional)
  std::string path;         // file it was read from
  std::vector<LineVariable> variables;  // in file order

  // The variable `name`, or nullptr.
  const LineVariable* find(std::string_view name) const;
};

// Reads and validates a line file; InputError naming file and line on any problem.
LineDistributions read_line_file(const std::string& path);

// The INI text of one variable section, as `growthuq fit --write` appends it.
std::string format_line_variable(const LineVariable& variable);

}  // namespace growthuq
