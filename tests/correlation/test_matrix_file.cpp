// The rank correlation CSV: round trip through format and read, and errors naming file and line.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "growthuq/core/error.hpp"
#include "growthuq/correlation/matrix_file.hpp"

using namespace growthuq;

namespace {

std::string write_temporary(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / ("growthuq_test_matrix_" + name)).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("format and read back a rank correlation matrix") {
  Eigen::MatrixXd s(3, 3);
  s << 1, 0.1, 1.0 / 3.0, 0.1, 1, -0.25, 1.0 / 3.0, -0.25, 1;
  const std::string text = format_rank_correlation_csv({"k", "h", "d"}, s);
  CHECK(text.substr(0, 6) == "k,h,d\n");
  const std::string path = write_temporary("roundtrip.csv", "# from growthuq correlate\n" + text);
  const RankCorrelationFile file = read_rank_correlation_csv(path);
  CHECK(file.names == std::vector<std::string>{"k", "h", "d"});
  CHECK(file.spearman == s);  // shortest round-trip text: exact
  std::filesystem::remove(path);
}

TEST_CASE("bad matrix files name the file and line") {
  std::string path = write_temporary("bad.csv", "k,h\n1,0.2\n0.3,1\n");
  CHECK_THROWS_WITH_AS(read_rank_correlation_csv(path),
                       (path + ":3: entry (h, k) = '0.3': expected a symmetric matrix: entry (k, h) on line 2 is 0.2").c_str(),
                       InputError);
  path = write_temporary("bad.csv", "k,h\n1,x\nx,1\n");
  CHECK_THROWS_WITH_AS(read_rank_correlation_csv(path), (path + ":2: entry (k, h) = 'x': expected a finite number").c_str(), InputError);
  path = write_temporary("bad.csv", "k,h\n1,0.2\n0.2,1.5\n");
  CHECK_THROWS_WITH_AS(read_rank_correlation_csv(path),
                       (path + ":3: entry (h, h) = '1.5': expected a number in [-1, 1]").c_str(), InputError);
  path = write_temporary("bad.csv", "k,h\n1,0.2\n0.2,0.9\n");
  CHECK_THROWS_AS(read_rank_correlation_csv(path), InputError);
  path = write_temporary("bad.csv", "k,h,d\n1,0.2,0\n0.2,1,0\n");
  CHECK_THROWS_WITH_AS(read_rank_correlation_csv(path),
                       (path + ": has 2 matrix rows below the header of 3 names: expected one row per variable, in the header's order").c_str(),
                       InputError);
  std::filesystem::remove(path);
}
