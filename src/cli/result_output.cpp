#include "result_output.hpp"

#include <iostream>

namespace growthuq::cli {

bool is_standard_output(std::string_view path) { return path == "-"; }

void check_result_target(const std::string& path, Overwrite overwrite) {
  if (!is_standard_output(path)) check_can_write(path, overwrite);
}

void write_result(const std::string& path, std::string_view content, Overwrite overwrite) {
  if (is_standard_output(path)) {
    // A failed write shows when main flushes stdout (finish_stdout), with the exit status.
    std::cout.write(content.data(), static_cast<std::streamsize>(content.size()));
    return;
  }
  write_file_atomically(path, content, overwrite);
}

void write_results_together(const std::vector<FileContent>& results, Overwrite overwrite) {
  std::vector<FileContent> files;
  const FileContent* printed = nullptr;
  for (const FileContent& result : results) {
    if (is_standard_output(result.path)) {
      printed = &result;
    } else {
      files.push_back(result);
    }
  }
  write_files_together(files, overwrite);
  if (printed) write_result(printed->path, printed->content, overwrite);
}

std::ostream& report_stream(std::string_view result_path) {
  return is_standard_output(result_path) ? std::cerr : std::cout;
}

std::string wrote(std::string_view path) {
  return is_standard_output(path) ? "wrote the result to standard output" : "wrote " + std::string(path);
}

}  // namespace growthuq::cli
