// CSV and INI readers: content, line numbers in errors, atomic writes that refuse to overwrite.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "growthuq/core/error.hpp"
#include "growthuq/io/csv.hpp"
#include "io/ini.hpp"
#include "growthuq/io/read_text_file.hpp"
#include "growthuq/io/output_file.hpp"

using namespace growthuq;

namespace {

std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("growthuq_test_io_" + name)).string();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("INI sections, entries and line numbers") {
  const auto document = parse_ini("# comment\n[line]\nname = wild type\n\n[k]\nlaw = lognormal\n median= 2.87 \n", "w.ini");
  REQUIRE(document.sections.size() == 2);
  CHECK(document.sections[0].name == "line");
  CHECK(document.sections[1].find("median")->value == "2.87");
  CHECK(document.sections[1].find("median")->line == 7);
  CHECK(document.find("k")->line == 5);
  CHECK_THROWS_WITH_AS(parse_ini("[a]\nx = 1\nx = 2\n", "w.ini"), "w.ini:3: key 'x' repeats the one on line 2", InputError);
  CHECK_THROWS_WITH_AS(parse_ini("[a]\njunk\n", "w.ini"),
                       "w.ini:2: 'junk': expected 'key = value', a [section] or a # comment", InputError);
  CHECK_THROWS_AS(parse_ini("[a]\n[a]\n", "w.ini"), InputError);
  CHECK_THROWS_AS(parse_ini("[a\n", "w.ini"), InputError);
}

TEST_CASE("CSV reading with quotes, comments and row errors") {
  const std::string path = temporary_path("read.csv");
  write_text(path, "# synthetic\nname,k\n\"a,b\",1.5\nc,2\n");
  const CsvTable table = read_csv(path);
  CHECK(table.header == std::vector<std::string>{"name", "k"});
  CHECK(table.rows[0][0] == "a,b");
  CHECK(table.numeric_column("k") == std::vector<double>{1.5, 2.0});
  CHECK(table.line_numbers[1] == 4);

  write_text(path, "k\n1\nx\n");
  CHECK_THROWS_WITH_AS(read_csv(path).numeric_column("k"), (path + ":3: column k = 'x': expected a finite number").c_str(), InputError);
  write_text(path, "k,h\n1\n");
  CHECK_THROWS_AS(read_csv(path), InputError);
  CHECK_THROWS_AS(read_csv(temporary_path("missing.csv")), InputError);
  std::filesystem::remove(path);
}

TEST_CASE("atomic writes refuse to overwrite unless allowed") {
  const std::string path = temporary_path("out.csv");
  std::filesystem::remove(path);
  CsvWriter writer({"a", "b"});
  writer.add_row({"1", "x,y"});
  write_file_atomically(path, writer.text(), Overwrite::refuse);
  CHECK(read_csv(path).rows[0][1] == "x,y");
  CHECK_THROWS_AS(write_file_atomically(path, "new", Overwrite::refuse), InputError);
  write_file_atomically(path, "a\n2\n", Overwrite::allow);
  CHECK(read_csv(path).rows[0][0] == "2");
  CHECK_FALSE(std::filesystem::exists(path + ".partial"));
  std::filesystem::remove(path);
}

TEST_CASE("an input file that is a directory or too large is refused by name, before it is read") {
  namespace fs = std::filesystem;
  const fs::path folder = temporary_path("input_folder");
  fs::remove_all(folder);
  fs::create_directories(folder);
  const auto error_of = [](const std::string& path) -> std::string {
    try {
      read_csv(path);
    } catch (const InputError& error) {
      return error.what();
    }
    return "no error";
  };
  CHECK(error_of(folder.string()) == folder.string() + ": is a directory: expected a file");
  // A sparse file one byte over the limit: refused from its size, without reading 256 MiB.
  const fs::path large = folder / "large.csv";
  std::ofstream(large) << "a\n1\n";
  fs::resize_file(large, detail::max_input_file_bytes + 1);
  CHECK(error_of(large.string()) == large.string() +
                                        ": is larger than 256 MiB, the limit of an input file: expected a text file (is it "
                                        "the file you meant?)");
  // Cut back to its text, the same file reads.
  fs::resize_file(large, 4);
  CHECK(read_csv(large.string()).rows.at(0).at(0) == "1");
  fs::remove_all(folder);
}
