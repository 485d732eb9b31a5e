// Missing command-line arguments, for every command that has them: one line on stderr naming
// what is missing and the usage that `--help` prints, exit status 2, nothing written. And the
// instrument flags (--rho-um, --nu), which every command that takes them parses alike.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

namespace fs = std::filesystem;

namespace {

struct Run {
  int status;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `growthuq <arguments>` in an empty scratch folder; the folder must still be empty
// afterwards except for the captured streams.
Run growthuq(const std::string& arguments) {
  const fs::path folder = fs::temp_directory_path() / ("growthuq_cli_" + std::to_string(getpid()) + "_" + std::to_string(std::rand()));
  fs::create_directories(folder);
  const std::string command = "cd '" + folder.string() + "' && '" + GROWTHUQ_CLI + "' " + arguments +
                              " >../" + folder.filename().string() + ".out 2>../" + folder.filename().string() + ".err";
  const int status = std::system(command.c_str());
  Run run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(folder.string() + ".out"), slurp(folder.string() + ".err")};
  CHECK(fs::is_empty(folder));
  fs::remove_all(folder);
  fs::remove(folder.string() + ".out");
  fs::remove(folder.string() + ".err");
  return run;
}

// "usage: growthuq run CAMPAIGN.ini [options] ..." -> "growthuq run CAMPAIGN.ini [options] ...".
// The usage the help prints first, its lines (wrapped to the help's width) joined by spaces.
std::string usage_of(const std::string& command) {
  const Run help = growthuq(command + " --help");
  REQUIRE(help.status == 0);
  const std::string paragraph = help.out.substr(0, help.out.find("\n\n"));
  REQUIRE(paragraph.rfind("usage: ", 0) == 0);
  std::string usage;
  for (std::size_t at = 7; at < paragraph.size(); ++at) {
    if (paragraph[at] != '\n') {
      usage += paragraph[at];
      continue;
    }
    usage += ' ';
    at = paragraph.find_first_not_of(' ', at + 1) - 1;
  }
  return usage;
}

}  // namespace

TEST_CASE("cli: a missing positional argument is one line naming it and the usage") {
  const struct {
    const char* arguments;
    const char* command;
    const char* missing;
  } cases[] = {
      {"run", "run", "the campaign file"},
      {"run --quiet", "run", "the campaign file"},
      {"tradeoff", "tradeoff", "the campaign file"},
      {"fit", "fit", "the CSV file of per-tube measurements"},  // before the missing --column
      {"fit-line --force", "fit-line", "the raw line file"},
      {"relax --out fits.csv", "relax", "the force curves"},
      {"synth --out data", "synth", "the line files of the TRUE distributions"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.arguments);
    const Run run = growthuq(c.arguments);
    CHECK(run.status == 2);
    CHECK(run.out.empty());
    const std::string command(c.command);
    CHECK(run.err == "growthuq " + command + ": error: missing " + c.missing + ": " + usage_of(command) +
                         " (see growthuq " + command + " --help)\n");
  }
}

TEST_CASE("cli: a missing required option is reported the same way, after the positional ones") {
  for (const auto& [arguments, command, option] : {std::tuple{"fit data.csv", "fit", "--column"},
                                                   std::tuple{"relax curves.csv", "relax", "--out"},
                                                   std::tuple{"sample --samples 10", "sample", "--line"},
                                                   std::tuple{"synth line.ini", "synth", "--out"}}) {
    CAPTURE(arguments);
    const Run run = growthuq(arguments);
    CHECK(run.status == 2);
    CHECK(run.err == std::string("growthuq ") + command + ": error: missing " + option + ": " + usage_of(command) +
                         " (see growthuq " + command + " --help)\n");
  }
}

TEST_CASE("cli: every command refuses the same bad probe radius and Poisson ratio with the same message") {
  // Each command with its other arguments valid up to the instrument, which is parsed first.
  const struct {
    const char* command;
    const char* arguments;
  } commands[] = {
      {"eval", "--k 2 --d-um 6 --d0-um 5"},
      {"correlate", ""},
      {"synth", "line.ini --out data"},
      {"relax", "curves.csv --out fits.csv"},
      {"fit-line", "raw.ini"},
  };
  const std::string nu_range = "a Poisson ratio in [0, 0.5)";
  const std::string rho_range = "a probe radius in um, > 0 and at most 1000";
  for (const auto& c : commands) {
    const std::string prefix = std::string("growthuq ") + c.command + ": error: ";
    for (const char* nu : {"0.5", "-0.1", "0.7", "nan", "inf", "abc"}) {
      CAPTURE(c.command);
      CAPTURE(nu);
      const Run run = growthuq(std::string(c.command) + " " + c.arguments + " --rho-um 0.5 --nu=" + nu);
      CHECK(run.status == 2);
      CHECK(run.err == prefix + "--nu = '" + nu + "': expected " + nu_range + "\n");
    }
    for (const char* rho : {"0", "-1", "nan", "inf", "abc", "1e300", "1000.5"}) {
      CAPTURE(c.command);
      CAPTURE(rho);
      const Run run = growthuq(std::string(c.command) + " " + c.arguments + " --rho-um=" + rho);
      CHECK(run.status == 2);
      CHECK(run.err == prefix + "--rho-um = '" + rho + "': expected " + rho_range + "\n");
    }
  }
}
