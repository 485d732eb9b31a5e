// Strict text <-> number conversion used by every reader and writer: a cell or option is a
// number only if the whole text is one finite number; output uses the shortest text that
// reads back to the same double.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace growthuq {

// The finite double spelled by the whole of `text` (surrounding blanks allowed), or nothing.
std::optional<double> try_parse_double(std::string_view text);

// As try_parse_double, but throws InputError("<location>", "<key> = '<text>': expected a
// number") when `text` is not one finite number.
double parse_double(std::string_view text, std::string_view location, std::string_view key);

// A whole number in [minimum, maximum] written in decimal (e.g. "1000"; also "1e6" when it is
// integral), or InputError naming location and key.
std::uint64_t parse_count(std::string_view text, std::string_view location, std::string_view key,
                          std::uint64_t minimum = 0,
                          std::uint64_t maximum = UINT64_MAX);

// Shortest decimal text that reads back to exactly `value` ("nan"/"inf" never appear in
// outputs; callers carry a status instead).
std::string format_double(double value);

// `text` without leading and trailing blanks (space, tab, CR).
std::string_view trim(std::string_view text);

}  // namespace growthuq
