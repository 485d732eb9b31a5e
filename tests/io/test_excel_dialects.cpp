// CSV and INI files as Excel and Windows editors write them: a UTF-8 byte-order mark, CRLF line
// ends, quoted cells, semicolons with decimal commas where the decimal separator is a comma,
// and inline comments in INI files.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "growthuq/core/error.hpp"
#include "growthuq/io/csv.hpp"
#include "io/ini.hpp"
#include "support/scratch_directory.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using growthuq::testing::ScratchDirectory;
using growthuq::testing::spit;

namespace {

// The UTF-8 byte-order mark Excel's "CSV UTF-8" and Notepad put first (its own literal, so that
// a hex digit after it cannot join the escape).
const std::string bom = "\xEF\xBB\xBF";

}  // namespace

TEST_CASE("Excel's CSV UTF-8: the byte-order mark is skipped, CRLF and quoted cells are read") {
  ScratchDirectory scratch("excel_comma");
  const std::string path = (scratch.root / "tubes.csv").string();
  // As Excel writes it: BOM, CRLF, a cell quoted because it holds a comma, "" for a quote.
  spit(path, bom + "tube,d_um,remark\r\nT1,12.5,\"bent, short\"\r\nT2,-1.5E-06,\"says \"\"ok\"\"\"\r\n");
  const CsvTable table = read_csv(path);
  CHECK(table.separator == ',');
  CHECK(table.header == std::vector<std::string>{"tube", "d_um", "remark"});
  CHECK(table.column_index("tube") == 0);  // the first column is found by its name
  CHECK(table.numeric_column("d_um") == std::vector<double>{12.5, -1.5e-6});
  CHECK(table.rows[0][2] == "bent, short");
  CHECK(table.rows[1][2] == "says \"ok\"");
  CHECK(table.line_numbers == std::vector<long>{2, 3});
}

TEST_CASE("a spreadsheet cell of several lines: the row goes on to its closing quote, named by its first line") {
  ScratchDirectory scratch("excel_multiline");
  const std::string path = (scratch.root / "tubes.csv").string();
  // As Excel writes a cell with Alt+Enter in it: LF inside the quotes, CRLF between rows.
  spit(path, bom + "tube,d_um,remark\r\nT1,12.5,\"bent\nthen \"\"fixed\"\"\"\r\n# a comment \"\r\nT2,13,\r\n");
  const CsvTable table = read_csv(path);
  REQUIRE(table.rows.size() == 2);
  CHECK(table.rows[0][2] == "bent\nthen \"fixed\"");
  CHECK(table.rows[1][0] == "T2");
  CHECK(table.line_numbers == std::vector<long>{2, 5});
  // What the engine's own writer makes of such a cell reads back the same.
  CsvWriter writer({"remark", "n"});
  writer.add_row({"two\nlines, \"quoted\"", "1"});
  spit(path, writer.text());
  CHECK(read_csv(path).rows.at(0).at(0) == "two\nlines, \"quoted\"");
  // A quote never closed: one error naming the row's first line.
  spit(path, "tube,remark\nT1,ok\nT2,\"open\nT3,x\n");
  CHECK_THROWS_WITH_AS(read_csv(path), (path + ":3: a quoted cell opened in this row is not closed before the end of the file").c_str(),
                       InputError);
}

TEST_CASE("Excel's CSV where the decimal separator is a comma: ';' between cells, decimal commas") {
  ScratchDirectory scratch("excel_semicolon");
  const std::string path = (scratch.root / "tubes.csv").string();
  // As a German Excel writes "CSV UTF-8": quoted where a cell holds a ';'. "1,5 mm" is text.
  spit(path, bom + "tube;d_um;v_exp_um_per_min;remark\r\n"
                   "T1;12,5;0,3;\"bent; short\"\r\n"
                   "T2;-1,5E-06;12;1,5 mm\r\n"
                   "T3;7;;\r\n");
  const CsvTable table = read_csv(path);
  CHECK(table.separator == ';');
  CHECK(table.header == std::vector<std::string>{"tube", "d_um", "v_exp_um_per_min", "remark"});
  CHECK(table.numeric_column("d_um") == std::vector<double>{12.5, -1.5e-6, 7.0});
  CHECK(table.rows[0][2] == "0.3");   // stored with a point: every reader parses it alike
  CHECK(table.rows[1][2] == "12");
  CHECK(table.rows[2][2].empty());     // a blank cell stays blank (not measured)
  CHECK(table.rows[0][3] == "bent; short");
  CHECK(table.rows[1][3] == "1,5 mm");  // not a number: kept as written

  // The same numbers with decimal points read identically from a comma file (a second path).
  const std::string comma_path = (scratch.root / "tubes_comma.csv").string();
  spit(comma_path, "tube,d_um\nT1,12.5\nT2,-1.5E-06\nT3,7\n");
  CHECK(read_csv(comma_path).numeric_column("d_um") == table.numeric_column("d_um"));
}

TEST_CASE("a ';' file with a decimal point, or a header with both separators, is one clear error") {
  ScratchDirectory scratch("excel_ambiguous");
  const std::string path = (scratch.root / "tubes.csv").string();
  spit(path, "tube;d_um\r\nT1;12,5\r\nT2;1.234\r\n");
  CHECK_THROWS_WITH_AS(read_csv(path),
                       (path + ":3: column d_um = '1.234': expected a decimal comma like every number of a "
                               "';'-separated file (1,5; a point may be a thousands separator there)")
                           .c_str(),
                       InputError);
  spit(path, "tube;d_um,h_nm\n");
  CHECK_THROWS_WITH_AS(read_csv(path), doctest::Contains((path + ":1: the header has both ',' and ';' between names").c_str()),
                       InputError);
  // A separator inside a quoted name does not count.
  spit(path, "tube;\"d, um\"\nT1;2,5\n");
  CHECK(read_csv(path).numeric_column("d, um") == std::vector<double>{2.5});
}

TEST_CASE("INI as a Windows editor saves it: byte-order mark, CRLF and inline comments") {
  const IniDocument document = parse_ini(bom +
                                             "[line] ; the header\r\n"
                                             "name = wild type   # Col-0\r\n"
                                             "[k]\r\n"
                                             "median = 2.87\t; Fig. 3\r\n"
                                             "note = sample#3;a\r\n",
                                         "w.ini");
  REQUIRE(document.sections.size() == 2);
  CHECK(document.sections[0].name == "line");  // no BOM in the first section's name
  CHECK(document.sections[0].find("name")->value == "wild type");
  CHECK(document.sections[1].find("median")->value == "2.87");
  CHECK(document.sections[1].find("median")->line == 4);
  // '#' and ';' without a blank before them are part of the value.
  CHECK(document.sections[1].find("note")->value == "sample#3;a");
  // A key whose value is only a comment is an empty value.
  CHECK(parse_ini("[a]\nx = # none\n", "w.ini").sections[0].find("x")->value.empty());
}
