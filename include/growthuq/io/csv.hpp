// Comma-separated tables as labs keep them: a header row of column names, then one row per
// record. Reading is strict (every row as wide as the header, errors name file, line and
// column); writing goes to a temporary file that is renamed into place only when complete.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace growthuq {

struct CsvTable {
  std::string path;                            // as given, for messages
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // cells, blanks trimmed
  std::vector<long> line_numbers;              // file line of each row (1-based)
  char separator = ',';                        // ';' for a file with decimal commas (read_csv)

  // Index of column `name`, or InputError naming the file and the columns it has.
  std::size_t column_index(std::string_view name) const;
  bool has_column(std::string_view name) const;

  // Every cell of column `name` as a finite number; an empty or non-numeric cell is an
  // InputError naming "<path>:<line>" and the column.
  std::vector<double> numeric_column(std::string_view name) const;

  // "<path>:<line of row>" for messages about a row.
  std::string row_location(std::size_t row) const;
};

// Reads `path`. Lines starting with '#' and blank lines are skipped (headers of synthetic
// data say so in '#' lines). Cells may be double-quoted ("a,b"), and a quoted cell may span
// lines (a spreadsheet cell of several lines; messages name the row's first line). A UTF-8 byte-order mark is
// skipped and CRLF line ends are read like LF (Excel's "CSV UTF-8").
// The separator is the header's: a header with ';' and no ',' outside quotes makes a
// semicolon-separated file with decimal commas (Excel's CSV where the decimal separator is a
// comma), whose number cells are stored with a decimal point ("1,5" -> "1.5"), so rows read
// alike whatever the dialect; a number there written with a point ("1.5") is an InputError, as
// is a header with both separators.
// InputError when the file cannot be opened, has no header, repeats a column name or has a row
// of the wrong width.
CsvTable read_csv(const std::string& path);

// Builds CSV text row by row; numbers use format_double.
class CsvWriter {
 public:
  explicit CsvWriter(const std::vector<std::string>& header);
  void add_row(const std::vector<std::string>& cells);
  const std::string& text() const { return text_; }

 private:
  std::size_t width_;
  std::string text_;
};

// A cell quoted when it holds a comma, a quote or a line break.
std::string csv_cell(std::string_view text);

}  // namespace growthuq
