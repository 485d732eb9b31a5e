// Campaign files as text for the parser's tests: a folder holding a campaign's neighbours (line
// files and matrices that only need to exist), one key's text swapped for another, and the
// message parse_campaign gives.
#pragma once

#include <doctest/doctest.h>

#include <fstream>
#include <initializer_list>
#include <string>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/core/error.hpp"
#include "support/scratch_directory.hpp"

namespace growthuq::testing {

// A scratch folder with `files` (paths relative to it, each holding "x") and the campaign's own
// path c.ini in it.
struct CampaignFolder : ScratchDirectory {
  CampaignFolder(const std::string& name, std::initializer_list<const char*> files) : ScratchDirectory(name) {
    for (const char* file : files) {
      std::filesystem::create_directories((root / file).parent_path());
      std::ofstream(root / file) << "x\n";
    }
  }
  std::string path() const { return (root / "c.ini").string(); }
};

// `text` with its first `from` replaced by `to` (which must be there).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// The message parse_campaign gives for `text` read as `file`, or "no error".
inline std::string parse_error(const std::string& text, const std::string& file) {
  try {
    parse_campaign(text, file);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace growthuq::testing
