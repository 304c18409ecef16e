// maris-cli's command line (CLI11 under app/cli_conventions.hpp): --version names the project version
// of CMake's project() and the commit, --help is generated, and every usage mistake (unknown option
// or command, missing value, missing or extra argument) exits 1 with a message naming it.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "core/version.hpp"
#include "study_cli_helpers.hpp"

namespace maris {
namespace {

using test::contains;
using test::runCli;

TEST(CliUsage, VersionIsTheProjectVersionAndTheCommit) {
  const auto r = runCli({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // MARIS_TEST_PROJECT_VERSION comes from CMake's project(VERSION), independently of the generated header.
  const std::string expected = "maris-cli " MARIS_TEST_PROJECT_VERSION;
  if (MARIS_TEST_GIT_CHECKOUT) {
    // `git describe --always --dirty`: an abbreviated hash (after a tag: TAG-N-gHASH), maybe "-dirty".
    EXPECT_TRUE(std::regex_match(r.out, std::regex("maris-cli [0-9.]+ \\(git [0-9A-Za-z._+-]*[0-9a-f]{7,}(-dirty)?\\)\n")))
        << r.out;
    EXPECT_EQ(r.out, expected + " (git " + commitId() + ")\n");
  } else {
    EXPECT_EQ(r.out, expected + "\n");
  }
  EXPECT_EQ(projectVersion(), MARIS_TEST_PROJECT_VERSION);
}

TEST(CliUsage, HelpIsGeneratedForTheProgramAndEachCommand) {
  const auto top = runCli({"--help"});
  ASSERT_EQ(top.exit_code, 0) << top.err;
  for (const char* word : {"Usage: maris-cli", "--version", "list", "show", "schema", "scenes", "default", "run",
                           "Exit codes", "130", "143"})
    EXPECT_TRUE(contains(top.out, word)) << word << " not in\n" << top.out;
  EXPECT_EQ(runCli({"-h"}).out, top.out);
  const auto run = runCli({"run", "--help"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* word : {"Usage: maris-cli run", "FILE|NAME", "--set PATH=VALUE", "--out DIR", "--no-plots"})
    EXPECT_TRUE(contains(run.out, word)) << word << " not in\n" << run.out;
  EXPECT_EQ(runCli({"help", "run"}).out, run.out);  // `help COMMAND` is `COMMAND --help`
}

struct UsageCase {
  std::vector<std::string> args;
  std::vector<std::string> expected;  // pieces of stderr
};

TEST(CliUsage, EveryUsageMistakeExitsOneAndNamesIt) {
  const std::vector<UsageCase> cases = {
      {{}, {"maris-cli: a command is required (the commands: list, show, schema, scenes, default, run, validate, study)",
           "Usage:"}},
      {{"frobnicate"}, {"maris-cli: unknown command 'frobnicate'", "(see maris-cli --help)"}},
      {{"lsit"}, {"unknown command 'lsit'; did you mean list?"}},
      {{"--frobnicate"}, {"maris-cli: unknown option --frobnicate"}},
      {{"--verison"}, {"unknown option --verison; did you mean --version?"}},
      {{"run", "x.json", "--no-plot"}, {"maris-cli run: unknown option --no-plot; did you mean --no-plots?",
                                        "(see maris-cli run --help)"}},
      {{"run", "x.json", "--out"}, {"maris-cli run: --out needs a value (DIR)"}},
      {{"run", "x.json", "--set"}, {"maris-cli run: --set needs a value (PATH=VALUE)"}},
      {{"run"}, {"maris-cli run: FILE|NAME is required"}},
      {{"run", "x.json", "y.json"}, {"maris-cli run: unexpected extra argument 'y.json'"}},
      {{"show"}, {"maris-cli show: NAME is required"}},
      {{"show", "a", "b"}, {"maris-cli show: unexpected extra argument 'b'"}},
      {{"schema", "any_scene", "--yaml"}, {"maris-cli schema: unknown option --yaml"}},
      {{"list", "everything"}, {"maris-cli list: unexpected extra argument 'everything'"}},
      {{"validate"}, {"maris-cli validate: FILE is required"}},
      {{"study"}, {"maris-cli study: a command is required (the commands: run, run-cases, collect, submit)"}},
      {{"study", "rnu"}, {"maris-cli study: unknown command 'rnu'; did you mean run?"}},
      {{"study", "run"}, {"maris-cli study run: STUDY is required"}},
      {{"study", "run", "s.json", "--jobs", "0"}, {"maris-cli study run: --jobs"}},
      {{"study", "run", "s.json", "--resum"}, {"unknown option --resum; did you mean --resume?"}},
      {{"study", "run-cases", "dir"}, {"maris-cli study run-cases: --first is required"}},
      {{"study", "submit", "s.json", "--out", "d", "--engine", "pbs"}, {"maris-cli study submit: --engine"}},
      {{"study", "submit", "s.json", "--out", "d"}, {"maris-cli study submit: --engine is required"}},
  };
  for (const auto& c : cases) {
    const auto r = runCli(c.args);
    std::string label = "maris-cli";
    for (const auto& a : c.args) label += " " + a;
    EXPECT_EQ(r.exit_code, 1) << label << "\n" << r.err;
    for (const auto& piece : c.expected) EXPECT_TRUE(contains(r.err, piece)) << label << ": '" << piece << "' not in\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << label << "\n" << r.out;
  }
}

TEST(CliUsage, RepeatedSetTakesOneValueEach) {
  // Each --set takes exactly one PATH=VALUE, so the scenario may follow it; the run itself then fails on the
  // unknown scenario name (exit 2), which shows that parsing accepted the line.
  const auto r = runCli({"run", "--set", "a=1", "no_such_scenario_anywhere", "--set", "b=2", "--no-plots"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "no_such_scenario_anywhere")) << r.err;
}

}  // namespace
}  // namespace maris
