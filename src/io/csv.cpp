#include "growthuq/io/csv.hpp"

#include "growthuq/core/error.hpp"
#include "growthuq/core/numbers.hpp"
#include "growthuq/io/read_text_file.hpp"

namespace growthuq {
namespace {

// Splits one CSV line into trimmed cells at `separator`, honouring double quotes ("" is a
// literal quote).
std::vector<std::string> split_cells(std::string_view line, char separator, const std::string& location) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == separator) {
      cells.emplace_back(trim(cell));
      cell.clear();
    } else {
      cell += c;
    }
  }
  if (quoted) throw InputError(location, "a quoted cell opened in this row is not closed before the end of the file");
  cells.emplace_back(trim(cell));
  return cells;
}

// How many times `c` stands outside double quotes in `line`.
// Whether `record` ends inside a quoted cell: an odd number of quotes ("" inside a cell counts
// two).
bool ends_inside_quotes(std::string_view record) {
  std::size_t quotes = 0;
  for (const char c : record) quotes += c == '"' ? 1 : 0;
  return quotes % 2 == 1;
}

std::size_t count_unquoted(std::string_view line, char c) {
  std::size_t count = 0;
  bool quoted = false;
  for (const char x : line) {
    if (x == '"') quoted = !quoted;  // "" inside a quoted cell toggles twice: no change
    if (!quoted && x == c) ++count;
  }
  return count;
}

// The separator the header line uses: ';' when it has semicolons and no commas outside quotes
// (Excel's CSV where the decimal separator is a comma), ',' otherwise. Both is ambiguous.
char header_separator(std::string_view header, const std::string& location) {
  const std::size_t commas = count_unquoted(header, ',');
  const std::size_t semicolons = count_unquoted(header, ';');
  if (commas > 0 && semicolons > 0) {
    throw InputError(location, "the header has both ',' and ';' between names: expected one separator, ',' "
                               "(decimal points) or ';' (decimal commas, as Excel writes CSV where the decimal "
                               "separator is a comma); quote a name that holds the other one");
  }
  return semicolons > 0 ? ';' : ',';
}

// A cell of a semicolon-separated file as the rest of the engine reads numbers: "-1,5E-06"
// becomes "-1.5E-06"; any other cell is kept as it is. A number written with a decimal point
// there is refused rather than guessed: in those locales "1.234" is 1234 with a thousands
// separator.
std::string decimal_point_cell(std::string cell, const std::string& location, const std::string& column) {
  const std::size_t comma = cell.find(',');
  if (comma != std::string::npos && cell.find(',', comma + 1) == std::string::npos &&
      cell.find('.') == std::string::npos) {
    std::string with_point = cell;
    with_point[comma] = '.';
    if (try_parse_double(with_point)) return with_point;
  }
  if (comma == std::string::npos && cell.find('.') != std::string::npos && try_parse_double(cell)) {
    throw_bad_value(location, "column " + column, cell,
                    "a decimal comma like every number of a ';'-separated file (1,5; a point may be a "
                    "thousands separator there)");
  }
  return cell;
}

}  // namespace

std::size_t CsvTable::column_index(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  std::string columns;
  for (const auto& column : header) columns += (columns.empty() ? "" : ", ") + column;
  throw InputError(path, "no column '" + std::string(name) + "' (the columns are: " + columns + ")");
}

bool CsvTable::has_column(std::string_view name) const {
  for (const auto& column : header) {
    if (column == name) return true;
  }
  return false;
}

std::string CsvTable::row_location(std::size_t row) const {
  return file_location(path, line_numbers.at(row));
}

std::vector<double> CsvTable::numeric_column(std::string_view name) const {
  const std::size_t column = column_index(name);
  std::vector<double> values;
  values.reserve(rows.size());
  for (std::size_t row = 0; row < rows.size(); ++row) {
    values.push_back(parse_double(rows[row][column], row_location(row), "column " + std::string(name)));
  }
  return values;
}

CsvTable read_csv(const std::string& path) {
  const std::string file = detail::read_text_file(path);
  const std::string_view text = detail::without_byte_order_mark(file);
  CsvTable table;
  table.path = detail::source_name(path);
  long line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line(trim(text.substr(start, end - start)));
    ++line_number;
    const long first_line = line_number;
    if (line.empty() || line.front() == '#') {
      start = end + 1;
      continue;
    }
    // A quoted cell may hold line breaks (a spreadsheet cell with several lines, as Excel writes
    // it; csv_cell quotes them too): a row whose quotes are open at a line's end goes on with the
    // next line, and its messages name the line it starts on.
    while (ends_inside_quotes(line) && end < text.size()) {
      start = end + 1;
      end = std::min(text.find('\n', start), text.size());
      std::string_view next = text.substr(start, end - start);
      if (!next.empty() && next.back() == '\r') next.remove_suffix(1);
      line += '\n';
      line += next;
      ++line_number;
    }
    start = end + 1;
    const std::string location = file_location(table.path, first_line);
    if (table.header.empty()) table.separator = header_separator(line, location);
    auto cells = split_cells(line, table.separator, location);
    if (table.header.empty()) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].empty()) throw InputError(location, "header column " + std::to_string(i + 1) + " has no name");
        for (std::size_t j = 0; j < i; ++j) {
          if (cells[j] == cells[i]) throw InputError(location, "header repeats column '" + cells[i] + "'");
        }
      }
      table.header = std::move(cells);
      continue;
    }
    if (cells.size() != table.header.size()) {
      throw InputError(location, "row has " + std::to_string(cells.size()) + " cells: expected " +
                                     std::to_string(table.header.size()) + " like the header");
    }
    if (table.separator == ';') {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        cells[i] = decimal_point_cell(std::move(cells[i]), location, table.header[i]);
      }
    }
    table.rows.push_back(std::move(cells));
    table.line_numbers.push_back(first_line);
  }
  if (table.header.empty()) throw InputError(table.path, "empty file: expected a header row of column names");
  return table;
}

std::string csv_cell(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

CsvWriter::CsvWriter(const std::vector<std::string>& header) : width_(header.size()) { add_row(header); }

void CsvWriter::add_row(const std::vector<std::string>& cells) {
  if (cells.size() != width_) {
    throw std::logic_error("CsvWriter: row of " + std::to_string(cells.size()) + " cells for " +
                           std::to_string(width_) + " columns");
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) text_ += ',';
    text_ += csv_cell(cells[i]);
  }
  text_ += '\n';
}

}  // namespace growthuq
