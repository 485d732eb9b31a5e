// "-" as the file a command writes its result to: the result then goes to standard output and
// what the command says about its work (counts, "wrote ...") to standard error, so that stdout
// holds the result alone and can be piped (`growthuq eval --in tubes.csv --out - | ...`).
// Reading "-" is standard input, for every file (io/read_text_file.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "growthuq/io/output_file.hpp"

namespace growthuq::cli {

// Whether `path` names standard output ("-").
bool is_standard_output(std::string_view path);

// check_can_write for a result file; nothing to check for "-".
void check_result_target(const std::string& path, Overwrite overwrite);

// The result written atomically to `path` (write_file_atomically), or printed on standard
// output for "-".
void write_result(const std::string& path, std::string_view content, Overwrite overwrite);

// A command's results written together: every file in full to its partial file first, then
// all renamed into place (write_files_together), so a failure (a missing folder, a full disk)
// leaves none of them, never the first without the second. One of them may be "-" (standard
// output), printed once the files are in place. In the order given: a file naming the others
// last.
void write_results_together(const std::vector<FileContent>& results, Overwrite overwrite);

// Where the command's report goes: standard error while its result takes standard output,
// standard output otherwise.
std::ostream& report_stream(std::string_view result_path);

// "wrote <path>", or "wrote the result to standard output" for "-".
std::string wrote(std::string_view path);

}  // namespace growthuq::cli
