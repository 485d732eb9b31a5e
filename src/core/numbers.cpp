#include "growthuq/core/numbers.hpp"

#include <array>
#include <charconv>
#include <cmath>

#include "growthuq/core/error.hpp"

namespace growthuq {

std::string_view trim(std::string_view text) {
  constexpr std::string_view blanks = " \t\r\n";
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(blanks);
  return text.substr(first, last - first + 1);
}

std::optional<double> try_parse_double(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

double parse_double(std::string_view text, std::string_view location, std::string_view key) {
  if (auto value = try_parse_double(text)) return *value;
  throw_bad_value(location, key, text, "a finite number");
}

std::uint64_t parse_count(std::string_view text, std::string_view location, std::string_view key,
                          std::uint64_t minimum, std::uint64_t maximum) {
  const std::string expected = "a whole number from " + std::to_string(minimum) + " to " +
                               std::to_string(maximum);
  // Plain digits are read exactly: through a double, seeds above 2^53 would silently change.
  const std::string_view digits = trim(text);
  if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos) {
    std::uint64_t count = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
    if (error != std::errc() || end != digits.data() + digits.size() || count < minimum || count > maximum) {
      throw_bad_value(location, key, text, expected);
    }
    return count;
  }
  const auto value = try_parse_double(text);
  // 2^64 is exactly representable; anything at or above it cannot be a uint64.
  if (!value || *value < 0.0 || *value != std::floor(*value) || *value >= 18446744073709551616.0) {
    throw_bad_value(location, key, text, expected);
  }
  const auto count = static_cast<std::uint64_t>(*value);
  if (count < minimum || count > maximum) throw_bad_value(location, key, text, expected);
  return count;
}

std::string format_double(double value) {
  std::array<char, 32> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return error == std::errc() ? std::string(buffer.data(), end) : std::string("nan");
}

}  // namespace growthuq
