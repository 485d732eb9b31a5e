// A small INI reader that keeps line numbers, so strict validators (distribution files,
// campaign files) can name the exact line of a bad entry. Boost.Program_options parses INI
// too but forgets where a value came from, which users need in error messages.
//
// Format: `[section]` headers, `key = value` entries, full-line comments starting with '#'
// or ';', inline comments (a '#' or ';' after a blank, to the end of the line), blank lines.
// A UTF-8 byte-order mark at the start is skipped; CRLF line ends are read like LF. Entries
// before the first section belong to section "".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace growthuq {

struct IniEntry {
  std::string key;
  std::string value;
  long line = 0;
};

struct IniSection {
  std::string name;
  long line = 0;
  std::vector<IniEntry> entries;

  // The entry `key`, or nullptr.
  const IniEntry* find(std::string_view key) const;
};

struct IniDocument {
  std::string path;
  std::vector<IniSection> sections;

  const IniSection* find(std::string_view name) const;
  std::string location(long line) const;  // "<path>:<line>"
};

// Parses INI text; `path` is used in messages only. InputError for a line that is neither a
// section, an entry nor a comment, an empty key, a repeated section or a repeated key.
IniDocument parse_ini(std::string_view text, std::string path);

// Reads and parses the file at `path`.
IniDocument read_ini(const std::string& path);

}  // namespace growthuq
