// Results replace only regular files. A device node, FIFO, socket or folder at an output path
// (or at its "<path>.partial") is refused with one message naming it and what was expected,
// whether or not overwriting is allowed, and is left as it was: renaming a finished file over
// /dev/null as root would replace the machine's null device with a regular file.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "growthuq/core/error.hpp"
#include "growthuq/io/output_file.hpp"
#include "growthuq/io/results_h5.hpp"
#include "support/scratch_directory.hpp"
#include "support/special_files.hpp"
#include "support/text_file.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

std::string refusal(const fs::path& path, SpecialKind kind) {
  return path.string() + ": is " + std::string(kind_name(kind)) +
         ": expected a regular file or a path that does not exist (results replace only regular files, also with --force)";
}

// A fresh special file of `kind` at `path`; false (with a note) when this process may not make one.
bool made(const fs::path& path, SpecialKind kind) {
  if (make_special_file(path, kind)) return true;
  REQUIRE_MESSAGE((kind == SpecialKind::null_device || kind == SpecialKind::full_device),
                  "could not make ", kind_name(kind), " at ", path.string());
  MESSAGE("not root: device nodes cannot be made here, so ", kind_name(kind), " is not checked");
  return false;
}

}  // namespace

TEST_CASE("every writer refuses a special file at the output path, with --force too, and leaves it alone") {
  for (const SpecialKind kind : every_special_kind()) {
    CAPTURE(kind_name(kind));
    const ScratchDirectory scratch("io_special");
    const fs::path path = scratch.root / "out.csv";
    if (!made(path, kind)) continue;
    for (const Overwrite overwrite : {Overwrite::refuse, Overwrite::allow}) {
      CHECK_THROWS_WITH_AS(check_can_write(path.string(), overwrite), refusal(path, kind).c_str(), InputError);
      CHECK_THROWS_WITH_AS(write_file_atomically(path.string(), "a\n1\n", overwrite), refusal(path, kind).c_str(),
                           InputError);
      CHECK_THROWS_WITH_AS(ResultsH5Writer(path.string(), overwrite), refusal(path, kind).c_str(), InputError);
    }
    CHECK_THROWS_WITH_AS(PartialFile(path.string()), refusal(path, kind).c_str(), InputError);
    CHECK(is_special_file(path, kind));
    CHECK_FALSE(fs::exists(path.string() + ".partial"));

    // A symbolic link to it counts as what it points to.
    const fs::path link = scratch.root / "link.csv";
    fs::create_symlink(path, link);
    CHECK_THROWS_WITH_AS(write_file_atomically(link.string(), "a\n1\n", Overwrite::allow), refusal(link, kind).c_str(),
                         InputError);
    CHECK(fs::is_symlink(link));
    CHECK(is_special_file(path, kind));
  }
}

TEST_CASE("a special file that appears while a result is written is not replaced at the commit") {
  for (const SpecialKind kind : every_special_kind()) {
    CAPTURE(kind_name(kind));
    const ScratchDirectory scratch("io_special_late");
    const fs::path csv = scratch.root / "samples.csv";
    const fs::path h5 = scratch.root / "results.h5";
    PartialFile file(csv.string());
    file.write("a\n1\n");
    ResultsH5Writer writer(h5.string(), Overwrite::allow);
    if (!made(csv, kind)) continue;
    REQUIRE(make_special_file(h5, kind));
    CHECK_THROWS_WITH_AS(file.commit(), refusal(csv, kind).c_str(), InputError);
    CHECK_THROWS_WITH_AS(writer.finish(CampaignMetadata{}), refusal(h5, kind).c_str(), InputError);
    CHECK(is_special_file(csv, kind));
    CHECK(is_special_file(h5, kind));
    CHECK_FALSE(fs::exists(csv.string() + ".partial"));
    CHECK_FALSE(fs::exists(h5.string() + ".partial"));
  }
}

TEST_CASE("the temporary <path>.partial: a stale file or link is replaced, a special file refused") {
  const ScratchDirectory scratch("io_partial");
  const fs::path path = scratch.root / "out.csv";
  const std::string partial = path.string() + ".partial";

  // What a killed run left: a regular file, or a symbolic link, which must not be written
  // through (it would overwrite its target and then become the result itself).
  spit(partial, "stale");
  write_file_atomically(path.string(), "new\n", Overwrite::refuse);
  CHECK(slurp(path) == "new\n");
  const fs::path victim = scratch.root / "victim.txt";
  spit(victim, "keep me");
  fs::create_symlink(victim, partial);
  write_file_atomically(path.string(), "newer\n", Overwrite::allow);
  CHECK(slurp(victim) == "keep me");
  CHECK(fs::symlink_status(path).type() == fs::file_type::regular);
  CHECK(slurp(path) == "newer\n");
  CHECK_FALSE(fs::exists(fs::symlink_status(partial)));

  // A device, socket or folder there (not a FIFO: the code as it was would block opening it).
  for (const SpecialKind kind : {SpecialKind::null_device, SpecialKind::socket, SpecialKind::directory}) {
    CAPTURE(kind_name(kind));
    if (!made(partial, kind)) continue;
    const std::string expected = partial + ": is " + std::string(kind_name(kind)) +
                                 ": expected no file there (the temporary file a result is written to before it is "
                                 "renamed into place)";
    CHECK_THROWS_WITH_AS(write_file_atomically(path.string(), "x\n", Overwrite::allow), expected.c_str(), InputError);
    CHECK_THROWS_WITH_AS(ResultsH5Writer((scratch.root / "out.csv").string(), Overwrite::allow), expected.c_str(),
                         InputError);
    CHECK(is_special_file(partial, kind));
    CHECK(slurp(path) == "newer\n");
    fs::remove(partial);
  }
  // A FIFO is refused before anything opens it.
  REQUIRE(make_special_file(partial, SpecialKind::fifo));
  CHECK_THROWS_AS(PartialFile(path.string()), InputError);
  CHECK(is_special_file(partial, SpecialKind::fifo));
}
