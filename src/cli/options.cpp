#include "options.hpp"

#include <algorithm>
#include <iostream>
#include <vector>

#include "growthuq/core/error.hpp"

namespace growthuq::cli {
namespace {

// The names of the positional arguments, in order (an unlimited last one once).
std::vector<std::string> positional_names(const po::positional_options_description& positional) {
  std::vector<std::string> names;
  for (unsigned position = 0; position < positional.max_total_count(); ++position) {
    const std::string& name = positional.name_for_position(position);
    if (std::find(names.begin(), names.end(), name) != names.end()) break;  // the repeated last one
    names.push_back(name);
  }
  return names;
}

// "campaign file (INI; ...)" -> "campaign file": what the argument is, without the details.
std::string_view first_clause(std::string_view description) {
  return description.substr(0, std::min({description.find(" ("), description.find(':'), description.find(';')}));
}

// A positional argument declared required() that the command line does not give.
const po::option_description* missing_positional(const po::options_description& options,
                                                 const po::positional_options_description& positional,
                                                 const po::variables_map& values) {
  for (const std::string& name : positional_names(positional)) {
    const po::option_description* option = options.find_nothrow(name, false);
    if (option != nullptr && option->semantic()->is_required() && !values.count(name)) return option;
  }
  return nullptr;
}

// Boost takes the word after an option that needs a value as that value, even when the word
// is the next option: `--samples --seed 1` sets samples to "--seed" and leaves 1 over, which it
// reports as "too many positional options". Refused first, naming both.
void refuse_option_as_value(const Arguments& arguments, std::string_view command, const po::options_description& options) {
  const auto option_named = [&](const std::string& word) -> const po::option_description* {
    if (!word.starts_with("--") || word.size() == 2) return nullptr;
    return options.find_nothrow(word.substr(2, word.find('=') - 2), false);
  };
  for (std::size_t i = 0; i + 1 < arguments.size(); ++i) {
    const po::option_description* option = option_named(arguments[i]);
    if (option == nullptr || arguments[i].find('=') != std::string::npos || option->semantic()->max_tokens() == 0) continue;
    if (option_named(arguments[i + 1]) == nullptr) continue;
    throw InputError("growthuq " + std::string(command),
                     arguments[i] + " needs a value, but the next word is the option " + arguments[i + 1] +
                         " (see growthuq " + std::string(command) + " --help)");
  }
}

// An empty word ('' on the command line) names no file, number or list: refused naming the
// option, rather than failing later as "No such file or directory" with no name.
void refuse_empty_values(const po::variables_map& values, std::string_view command, const po::options_description& options,
                         const po::positional_options_description& positional) {
  const std::vector<std::string> positionals = positional_names(positional);
  for (const auto& [name, value] : values) {
    if (value.defaulted()) continue;
    const auto* text = boost::any_cast<std::string>(&value.value());
    const auto* texts = boost::any_cast<std::vector<std::string>>(&value.value());
    const bool empty = (text != nullptr && text->empty()) ||
                       (texts != nullptr && std::find(texts->begin(), texts->end(), "") != texts->end());
    const po::option_description* option = options.find_nothrow(name, false);
    // A switch without a value (`--force` declared without a type) holds an empty word too.
    if (!empty || (option != nullptr && option->semantic()->max_tokens() == 0)) continue;
    const bool is_positional = std::find(positionals.begin(), positionals.end(), name) != positionals.end();
    const std::string label = is_positional && option != nullptr ? std::string(first_clause(option->description())) : "--" + name;
    throw_bad_value("growthuq " + std::string(command), label, "", "a non-empty value");
  }
}

}  // namespace

// Every help text is this wide: Boost.Program_options' default for the option list, and a
// terminal's default width.
const std::size_t help_width = po::options_description::m_default_line_length;

std::string wrapped_help(std::string_view text, std::string_view first, std::string_view indent) {
  std::string out(first);
  std::size_t column = first.size();
  bool line_has_words = false;
  std::size_t at = 0;
  while (at < text.size()) {
    if (text.compare(at, 2, "\n\n") == 0) {  // a paragraph ends
      out += "\n\n" + std::string(indent);
      column = indent.size();
      line_has_words = false;
      at = text.find_first_not_of('\n', at);
      continue;
    }
    if (text[at] == ' ' || text[at] == '\n') {
      ++at;
      continue;
    }
    const std::size_t end = std::min(text.find_first_of(" \n", at), text.size());
    const std::string_view word = text.substr(at, end - at);
    if (line_has_words && column + 1 + word.size() > help_width) {
      out += "\n" + std::string(indent);
      column = indent.size();
      line_has_words = false;
    }
    if (line_has_words) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    line_has_words = true;
    at = end;
  }
  return out;
}

void print_version(std::ostream& out) { out << "growthuq " << GROWTHUQ_VERSION << "\n"; }

InputError missing_argument(std::string_view command, std::string_view usage, std::string_view what) {
  const std::string name(command);
  return InputError("growthuq " + name, "missing " + std::string(what) + ": growthuq " + name + " " + std::string(usage) +
                                            " (see growthuq " + name + " --help)");
}

InputError missing_argument(std::string_view command, std::string_view usage, const po::option_description& argument) {
  return missing_argument(command, usage, "the " + std::string(first_clause(argument.description())));
}

bool parse_arguments(const Arguments& arguments, std::string_view command, std::string_view usage,
                     std::string_view description, po::options_description options,
                     const po::positional_options_description& positional, po::variables_map& values) {
  options.add_options()("help,h", "print this help and exit")("version", "print the version and exit");
  refuse_option_as_value(arguments, command, options);
  try {
    // Boost's default style takes an unambiguous prefix for the whole option (`--sam 10` as
    // --samples, `tradeoff --samples` as --samples-list): a typo then runs something else. Off, so
    // only full names (and the declared one-letter forms) are accepted.
    const int style = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
    po::store(po::command_line_parser(arguments).options(options).positional(positional).style(style).run(), values);
    if (values.count("help")) {
      const std::string usage_start = "usage: growthuq " + std::string(command) + " ";
      std::cout << wrapped_help(usage, usage_start, std::string(usage_start.size(), ' ')) << "\n\n"
                << wrapped_help(description, "", "") << "\n\n"
                << options << "\n";
      return false;
    }
    if (values.count("version")) {
      print_version(std::cout);
      return false;
    }
    // Before notify(), whose "the option '--campaign' is required but missing" names an option
    // the user never types and comes in alphabetical order, not the order of the usage.
    if (const po::option_description* argument = missing_positional(options, positional, values)) {
      throw missing_argument(command, usage, *argument);
    }
    refuse_empty_values(values, command, options, positional);
    po::notify(values);
  } catch (const po::required_option& error) {
    throw missing_argument(command, usage, error.get_option_name());
  } catch (const po::error& error) {
    throw InputError("growthuq " + std::string(command), std::string(error.what()) +
                                                             " (see growthuq " + std::string(command) + " --help)");
  }
  return true;
}

}  // namespace growthuq::cli
