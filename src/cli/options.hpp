// Shared command-line plumbing: Boost.Program_options parsing that turns every option error
// into an InputError naming the option, and --help text in one format for all subcommands.
#pragma once

#include <boost/program_options.hpp>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

namespace po = boost::program_options;

// Parses `arguments` against `options` (plus --help, added here) and `positional`. Returns
// false after printing "usage: growthuq <command> <usage>", `description` and the options when
// --help was given. Unknown options, missing values and bad conversions become InputErrors.
// A missing required argument, positional ones first, becomes missing_argument's one line,
// what is missing named by the first clause of the argument's description ("campaign file
// (INI; ...)" -> "the campaign file") or by its option name (--column).
bool parse_arguments(const Arguments& arguments, std::string_view command, std::string_view usage,
                     std::string_view description, po::options_description options,
                     const po::positional_options_description& positional, po::variables_map& values);

// "missing <what>: growthuq <command> <usage> (see growthuq <command> --help)", located at
// "growthuq <command>" (main prints it once), for commands that check an argument themselves.
InputError missing_argument(std::string_view command, std::string_view usage, std::string_view what);
InputError missing_argument(std::string_view command, std::string_view usage, const po::option_description& argument);

}  // namespace growthuq::cli
