// The input gate (core/input_limits, core/checked_count, requireFiniteResults): every limit refuses
// with an InputError naming where and the limit, without recursion and without reading past the limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

#include "core/checked_count.hpp"
#include "core/input_limits.hpp"
#include "core/results.hpp"
#include "core/scenario.hpp"

namespace maris {
namespace {

namespace fs = std::filesystem;

// The text of the single error an InputError carries from `f`, or "" when nothing was thrown.
template <class F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string nested(std::size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("maris_limits_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(InputLimits, DepthAtTheLimitParsesOneBeyondIsRefusedWithItsPath) {
  EXPECT_NO_THROW(parseJsonLimited(nested(InputLimits::kJsonDepth), "t"));
  const std::string message = inputErrorOf([] { parseJsonLimited("{\"a\": " + nested(64) + "}", "file.json"); });
  EXPECT_NE(message.find("a[0]"), std::string::npos) << message;
  EXPECT_NE(message.find("deeper than 64"), std::string::npos) << message;
  EXPECT_NE(message.find("file.json"), std::string::npos) << message;
}

TEST(InputLimits, SixtyThousandLevelsAreRefusedWithoutRecursion) {
  // The fuzz campaign's stack overflow: 60 000 nested arrays and objects.
  EXPECT_NE(inputErrorOf([] { parseJsonLimited(nested(60000), "deep.json"); }).find("deeper than"), std::string::npos);
  std::string objects;
  for (int i = 0; i < 60000; ++i) objects += "{\"k\":";
  objects += "1" + std::string(60000, '}');
  EXPECT_NE(inputErrorOf([&] { parseJsonLimited(objects, "deep.json"); }).find("k.k.k"), std::string::npos);
}

TEST(InputLimits, LongStringsLongArraysAndDuplicateKeysAreNamed) {
  const std::string long_name = "{\"name\": \"" + std::string(InputLimits::kStringLength + 1, 'x') + "\"}";
  const std::string m1 = inputErrorOf([&] { parseJsonLimited(long_name, "s.json"); });
  EXPECT_NE(m1.find("name: text of 100001 characters; the limit is 100000"), std::string::npos) << m1;
  EXPECT_LT(m1.size(), 300u);  // the value itself is not echoed

  std::string array = "{\"p\": {\"list\": [0";
  for (std::size_t i = 0; i < InputLimits::kArrayLength; ++i) array += ",0";
  array += "]}}";
  const std::string m2 = inputErrorOf([&] { parseJsonLimited(array, "a.json"); });
  EXPECT_NE(m2.find("p.list[1000000]: array longer than 1000000 elements"), std::string::npos) << m2;

  const std::string m3 =
      inputErrorOf([] { parseJsonLimited(R"({"parameters": {"geometry": {"length": 1, "length": 2}}})", "d.json"); });
  EXPECT_NE(m3.find("parameters.geometry.length: duplicate key"), std::string::npos) << m3;
}

TEST(InputLimits, OverflowingNumbersNameTheirPathSyntaxErrorsTheirLine) {
  const std::string m = inputErrorOf([] { parseJsonLimited("{\"a\": {\"b\": [1, 1e400]}}", "n.json"); });
  EXPECT_NE(m.find("a.b[1] = 1e400: number is out of the range of a double"), std::string::npos) << m;
  EXPECT_THROW(parseJsonLimited("{\n  \"a\": [1,\n  2,,]\n}", "x.json"), JsonSyntaxError);
  const std::string s = inputErrorOf([] { parseJsonLimited("{\n  \"a\": [1,\n  2,,]\n}", "x.json"); });
  EXPECT_NE(s.find("x.json: is not valid JSON (line 3, column 5)"), std::string::npos) << s;
}

TEST(InputLimits, OnlyRegularFilesWithinTheSizeLimitAreRead) {
  const auto dir = scratch("files");
  const auto fifo = dir / "fifo", loop = dir / "loop", big = dir / "big.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("loop", loop);
  std::ofstream(big) << std::string(11, ' ');
  const auto expect = [](const fs::path& f, const char* fragment, std::uintmax_t limit = 1000) {
    const std::string m = inputErrorOf([&] { readInputFile(f, f.string(), limit); });
    EXPECT_NE(m.find(f.string()), std::string::npos) << m;
    EXPECT_NE(m.find(fragment), std::string::npos) << m;
  };
  expect(fifo, "not a regular file");
  expect("/dev/zero", "not a regular file");
  expect(dir, "is a folder");
  expect(loop, "loop of symbolic links");
  expect(dir / "missing.json", "does not exist");
  expect(big, "is 11 bytes; the limit is 10 bytes", 10);
  EXPECT_EQ(readInputFile(big, "big", 11), std::string(11, ' '));
  // Scenario loading goes through the same gate.
  EXPECT_NE(inputErrorOf([&] { loadScenarioFile(fifo); }).find("not a regular file"), std::string::npos);
  fs::remove_all(dir);
}

TEST(InputLimits, DataFileRowsAndColumnsAreBounded) {
  std::string wide = "a,b\n1,2\n";
  for (std::size_t i = 0; i < InputLimits::kDataColumns; ++i) wide += "1,";
  wide += "1\n";
  const std::string m = inputErrorOf([&] { checkDataShape(wide, "parameters.x.file", "w.csv"); });
  EXPECT_NE(m.find("parameters.x.file = \"w.csv\": row 3 has 1001 columns; the limit is 1000"), std::string::npos) << m;
  EXPECT_NO_THROW(checkDataShape("t a\n0 1\n1\t2\n", "f", "ok.txt"));
  const std::string rows(InputLimits::kDataRows + 1, '\n');
  EXPECT_NE(inputErrorOf([&] { checkDataShape(rows, "f", "r.csv"); }).find("more than 5000000 rows"), std::string::npos);
}

TEST(InputLimits, SetPathsAndValuesGoThroughTheSameGate) {
  Scenario s;
  std::string deep_path;
  for (int i = 0; i < 60000; ++i) deep_path += "a.";
  const std::string m1 = inputErrorOf([&] { applyOverride(s, deep_path + "b=1"); });
  EXPECT_NE(m1.find("60001 path components; the limit is 16"), std::string::npos) << m1.substr(0, 300);
  const std::string m2 = inputErrorOf([&] { applyOverride(s, "solver.time_step=1e400"); });
  EXPECT_NE(m2.find("parameters.solver.time_step = 1e400"), std::string::npos) << m2;
  EXPECT_NE(inputErrorOf([&] { applyOverride(s, "x=" + nested(1000)); }).find("deeper than"), std::string::npos);
  EXPECT_NE(inputErrorOf([&] { applyOverride(s, "x=\xff\xfe"); }).find("not valid UTF-8"), std::string::npos);
  applyOverride(s, "group.label=plain text");  // not JSON: kept as text
  EXPECT_EQ(s.parameters["group"]["label"], "plain text");
}

TEST(InputLimits, EchoedValuesAreCutAndLongErrorListsCapped) {
  const std::string cut = echoText(std::string(5'000'000, 'n'));
  EXPECT_EQ(cut, std::string(77, 'n') + "... (5000000 characters)");
  std::vector<FieldError> errors;
  for (int i = 0; i < 100; ++i) errors.push_back({"row" + std::to_string(i), "", "bad"});
  const std::string text = describeErrors(errors);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 20);  // 20 errors, then one summary line
  EXPECT_NE(text.find("... and 80 more errors (100 in all)"), std::string::npos) << text;
  Json big = Json::array();
  for (int i = 0; i < 1000000; ++i) big.push_back(i);
  EXPECT_LE(jsonSnippet(big).size(), 60u);
}

TEST(CheckedCount, RoundsUpAndRefusesCountsBeyondTheLimit) {
  EXPECT_EQ(checkedCount(10.0, 100, "f", "steps"), 10);
  EXPECT_EQ(checkedCount(10.0 + 1e-12, 100, "f", "steps"), 10);  // remainder below 1e-9 absorbed
  EXPECT_EQ(checkedCount(10.5, 100, "f", "steps"), 11);
  // riser_default at solver.time_step = 1e-20: 1e21 steps overflowed a long and ran "1 step".
  const std::string m = inputErrorOf([] { checkedCount(1e21, kMaxTimeSteps, "parameters.solver.time_step", "time steps"); });
  EXPECT_NE(m.find("parameters.solver.time_step: gives 1e+21 time steps; the limit is 2e+10"), std::string::npos) << m;
  EXPECT_THROW(checkedCount(std::nan(""), 100, "f", "steps"), InputError);
  EXPECT_THROW(checkedCount(-5.0, 100, "f", "steps"), InputError);
}

TEST(FiniteResults, ANonFiniteScalarOrTableValueFailsTheRunNamingIt) {
  Results r;
  r.addScalar("tip", 1.0, "m", "");
  EXPECT_NO_THROW(requireFiniteResults(r));
  r.addScalar("cost", std::nan(""), "-", "");
  try {
    requireFiniteResults(r);
    FAIL() << "no SolverError";
  } catch (const SolverError& e) {
    EXPECT_EQ(e.quantity(), "result cost");
    EXPECT_EQ(std::string(e.what()), "solver failed: result cost is not finite");
  }
  r.scalars.pop_back();
  Table t;
  t.name = "history";
  t.add("x", "m", {1.0, 2.0, INFINITY});
  r.tables.push_back(t);
  try {
    requireFiniteResults(r);
    FAIL() << "no SolverError";
  } catch (const SolverError& e) {
    EXPECT_EQ(e.quantity(), "result table history, column x, row 3");
  }
}

}  // namespace
}  // namespace maris
