// The one gate every outside text passes before it is parsed: scenario files, `--set` values and the
// data files scenarios name. It refuses, with an InputError naming the file (and field or row) and the
// limit, anything that could crash, exhaust or fool the parsers behind it: files that are not regular
// (FIFOs, devices such as /dev/zero, folders, symbolic-link loops), oversized files, JSON nested too
// deeply, over-long strings and arrays, duplicate keys, numbers that overflow a double, data files with
// too many rows or columns. Depth is checked by a SAX handler that builds the document itself, so no
// limit depends on the size of the stack.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/results.hpp"
#include "core/schema.hpp"

namespace maris {

struct InputLimits {
  static constexpr std::uintmax_t kScenarioFileBytes = 16u << 20;  // 16 MiB
  static constexpr std::uintmax_t kDataFileBytes = 256u << 20;     // 256 MiB
  static constexpr std::size_t kJsonDepth = 64;                    // nested arrays/objects
  static constexpr std::size_t kStringLength = 100000;             // characters in one JSON string
  static constexpr std::size_t kArrayLength = 1000000;             // elements in one JSON array
  static constexpr std::size_t kDataRows = 5000000;                // lines of a data file
  static constexpr std::size_t kDataColumns = 1000;                // fields in one line of a data file
  static constexpr std::size_t kSetPathComponents = 16;            // dotted components of a --set path
};

// Echoed input is cut after kEchoLimit characters (the full length is stated): FieldError::str() does it
// for every error, so a 5 MB value prints as 80 characters; describeErrors() lists the first
// kReportedErrorLimit errors, then how many more there are.
inline constexpr std::size_t kEchoLimit = 80;
inline constexpr std::size_t kReportedErrorLimit = 20;

// `text` cut to `limit` characters (at a UTF-8 character boundary), stating the full length when cut.
std::string echoText(const std::string& text, std::size_t limit = kEchoLimit);

// Throws SolverError naming the first scalar, table value or error estimate of `results` that is not
// finite: runScenario calls it after every run, so no run reports NaN or infinity. A scene that cannot
// compute a value for some input (e.g. a regression outside its range) leaves it out with a warning.
void requireFiniteResults(const Results& results);

// A JSON syntax error (as opposed to a limit, a duplicate key or an overflow): `--set` falls back to
// taking the value as text only for this one.
class JsonSyntaxError : public InputError {
 public:
  using InputError::InputError;
};

// The bytes of a regular file of at most `max_bytes`. `what` names it in errors (a field such as
// "parameters.hull.offsets_file", or the file itself).
std::string readInputFile(const std::filesystem::path& file, const std::string& what, std::uintmax_t max_bytes);

// Parses JSON under the limits above. `origin` names the text in errors (a file, "--set x"); error
// paths start with `path_prefix` ("" for a whole scenario, "parameters.geometry.length" for --set).
Json parseJsonLimited(const std::string& text, const std::string& origin, const std::string& path_prefix = "");

// Checks a data file's text against kDataRows and kDataColumns (fields split at commas, semicolons,
// tabs or spaces); throws InputError(field, file, "row N has M columns; the limit is ...").
void checkDataShape(const std::string& text, const std::string& field, const std::string& file);

}  // namespace maris
