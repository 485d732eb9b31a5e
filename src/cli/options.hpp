// Shared command-line plumbing: Boost.Program_options parsing that turns every option error
// into an InputError naming the option, and --help text in one format for all subcommands.
#pragma once

#include <boost/program_options.hpp>
#include <string>
#include <string_view>

#include "commands.hpp"

namespace growthuq::cli {

namespace po = boost::program_options;

// Parses `arguments` against `options` (plus --help, added here) and `positional`. Returns
// false after printing "usage: growthuq <command> <usage>", `description` and the options when
// --help was given. Unknown options, missing values and bad conversions become InputErrors.
bool parse_arguments(const Arguments& arguments, std::string_view command, std::string_view usage,
                     std::string_view description, po::options_description options,
                     const po::positional_options_description& positional, po::variables_map& values);

}  // namespace growthuq::cli
