// The fit window as a user writes it: "a,b" in uN (growthuq curves' --window-uN, raw.ini's
// window_uN), for both conventions of Eq. (C6), src/forcecurves/README.md.
#pragma once

#include <string_view>

#include "growthuq/forcecurves/curve_processing.hpp"

namespace growthuq {

// The window of `convention` with the two forces of `text` (uN) in N; InputError
// "<location>: <key> = '<text>': expected two forces in uN separated by a comma (4,0.5)" when
// `text` is not two numbers. Their order and signs are checked by
// CurveProcessingOptions::invalid_reason.
FitWindow window_of(WindowConvention convention, std::string_view text, std::string_view location, std::string_view key);

}  // namespace growthuq
