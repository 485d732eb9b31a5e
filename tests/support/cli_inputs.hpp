// The small input files the command-line tests hand to commands: a line file, a stiffness
// column for `fit`, and a sheet of two tubes for `eval`, written into a scratch folder.
#pragma once

#include <filesystem>

#include "support/text_file.hpp"

namespace growthuq::testing {

inline constexpr const char* cli_line_file =
    "[line]\nname = test_line\n\n"
    "[k]\nlaw = lognormal\nmedian = 2.87\niqr = 0.83\nunit = N/m\nsource = published median and IQR\n";

inline constexpr const char* cli_stiffness_csv = "k_N_per_m\n2.41\n3.12\n2.05\n2.87\n4.40\n2.66\n3.35\n1.92\n2.71\n3.80\n";

inline constexpr const char* cli_tubes_csv = "k_N_per_m,d_um,d0_um,h_nm\n2.87,6.56,5.35,145\n3.10,6.20,5.30,150\n";

// line.ini, k.csv and tubes.csv in `root`.
inline void write_cli_inputs(const std::filesystem::path& root) {
  spit(root / "line.ini", cli_line_file);
  spit(root / "k.csv", cli_stiffness_csv);
  spit(root / "tubes.csv", cli_tubes_csv);
}

}  // namespace growthuq::testing
