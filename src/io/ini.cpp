#include "io/ini.hpp"

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq {

const IniEntry* IniSection::find(std::string_view key) const {
  for (const IniEntry& entry : entries) {
    if (entry.key == key) return &entry;
  }
  return nullptr;
}

const IniSection* IniDocument::find(std::string_view name) const {
  for (const IniSection& section : sections) {
    if (section.name == name) return &section;
  }
  return nullptr;
}

std::string IniDocument::location(long line) const { return file_location(path, line); }

namespace {

// `line` up to an inline comment: a '#' or ';' after a blank (`median = 2.87  # from Fig. 3`).
// The blank is required so that a value may still hold the characters themselves ("#3", "a;b").
std::string_view without_inline_comment(std::string_view line) {
  for (std::size_t i = 1; i < line.size(); ++i) {
    if ((line[i] == '#' || line[i] == ';') && (line[i - 1] == ' ' || line[i - 1] == '\t')) {
      return trim(line.substr(0, i));
    }
  }
  return line;
}

}  // namespace

IniDocument parse_ini(std::string_view text, std::string path) {
  text = detail::without_byte_order_mark(text);
  IniDocument document{std::move(path), {}};
  document.sections.push_back(IniSection{"", 0, {}});
  long line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = without_inline_comment(trim(text.substr(start, end - start)));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#' || line.front() == ';') continue;

    const std::string location = document.location(line_number);
    if (line.front() == '[') {
      if (line.back() != ']' || trim(line.substr(1, line.size() - 2)).empty()) {
        throw InputError(location, "'" + std::string(line) + "': expected a section header [name]");
      }
      const std::string name(trim(line.substr(1, line.size() - 2)));
      if (const IniSection* previous = document.find(name)) {
        throw InputError(location, "section [" + name + "] repeats the one on line " +
                                       std::to_string(previous->line));
      }
      document.sections.push_back(IniSection{name, line_number, {}});
      continue;
    }

    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos) {
      throw InputError(location, "'" + std::string(line) + "': expected 'key = value', a [section] or a # comment");
    }
    const std::string key(trim(line.substr(0, equals)));
    if (key.empty()) throw InputError(location, "'" + std::string(line) + "': the key before '=' is empty");
    IniSection& section = document.sections.back();
    if (const IniEntry* previous = section.find(key)) {
      throw InputError(location, "key '" + key + "' repeats the one on line " +
                                     std::to_string(previous->line));
    }
    section.entries.push_back(IniEntry{key, std::string(trim(line.substr(equals + 1))), line_number});
  }
  if (document.sections.front().entries.empty()) document.sections.erase(document.sections.begin());
  return document;
}

IniDocument read_ini(const std::string& path) {
  return parse_ini(detail::read_text_file(path), detail::source_name(path));
}

}  // namespace growthuq
