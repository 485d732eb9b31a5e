#include "growthuq/forcecurves/window_text.hpp"

#include <optional>

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/core/units.hpp"

namespace growthuq {

FitWindow window_of(WindowConvention convention, std::string_view text, std::string_view location, std::string_view key) {
  const std::size_t comma = text.find(',');
  const std::optional<double> low = try_parse_double(text.substr(0, comma));
  const std::optional<double> high = comma == std::string_view::npos ? std::nullopt : try_parse_double(text.substr(comma + 1));
  if (!low || !high) throw_bad_value(location, key, text, "two forces in uN separated by a comma (4,0.5)");
  return {convention, from_uN(*low), from_uN(*high)};
}

}  // namespace growthuq
