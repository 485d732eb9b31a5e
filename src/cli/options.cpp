#include "options.hpp"

#include <iostream>

#include "growthuq/core/error.hpp"

namespace growthuq::cli {

bool parse_arguments(const Arguments& arguments, std::string_view command, std::string_view usage,
                     std::string_view description, po::options_description options,
                     const po::positional_options_description& positional, po::variables_map& values) {
  options.add_options()("help,h", "print this help and exit");
  try {
    po::store(po::command_line_parser(arguments).options(options).positional(positional).run(), values);
    if (values.count("help")) {
      std::cout << "usage: growthuq " << command << " " << usage << "\n\n"
                << description << "\n\n"
                << options << "\n";
      return false;
    }
    po::notify(values);
  } catch (const po::error& error) {
    throw InputError("growthuq " + std::string(command), std::string(error.what()) +
                                                             " (see growthuq " + std::string(command) + " --help)");
  }
  return true;
}

}  // namespace growthuq::cli
