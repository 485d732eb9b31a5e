// Shared command-line plumbing: Boost.Program_options parsing that turns every option error
// into an InputError naming the option, and --help text in one format for all subcommands.
#pragma once

#include <boost/program_options.hpp>
#include <iosfwd>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "growthuq/core/error.hpp"

namespace growthuq::cli {

namespace po = boost::program_options;

// Parses `arguments` against `options` (plus --help and --version, added here) and
// `positional`. Returns false after printing "usage: growthuq <command> <usage>", `description`
// and the options when --help was given, or the version for --version. The help is 80 columns
// wide for every command: usage and description are re-wrapped to it (a blank line in
// `description` separates paragraphs; its other line breaks are only spaces). Unknown options, missing values and bad conversions become InputErrors.
// A missing required argument, positional ones first, becomes missing_argument's one line,
// what is missing named by the first clause of the argument's description ("campaign file
// (INI; ...)" -> "the campaign file") or by its option name (--column).
bool parse_arguments(const Arguments& arguments, std::string_view command, std::string_view usage,
                     std::string_view description, po::options_description options,
                     const po::positional_options_description& positional, po::variables_map& values);

// `text` re-wrapped to the help's width (80 columns), the first line after `first`, the others
// after `indent`: paragraphs (separated by a blank line) stay apart, the line breaks within one
// are spaces, and a line breaks at the last space that fits (a longer word stands alone).
std::string wrapped_help(std::string_view text, std::string_view first, std::string_view indent);

// "growthuq <version>", as --version prints it for every command and at the top level.
void print_version(std::ostream& out);

// "missing <what>: growthuq <command> <usage> (see growthuq <command> --help)", located at
// "growthuq <command>" (main prints it once), for commands that check an argument themselves.
InputError missing_argument(std::string_view command, std::string_view usage, std::string_view what);
InputError missing_argument(std::string_view command, std::string_view usage, const po::option_description& argument);

}  // namespace growthuq::cli
