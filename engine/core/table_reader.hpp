// The one reader of numeric tables that scenarios and the GUI name (offsets, measured points, records, reference
// data). What it accepts:
//   - '#' comment lines and blank lines anywhere, a UTF-8 byte-order mark, CRLF line ends;
//   - a names row (required or optional, per table); a name may carry its unit: "time [s]", "time (s)";
//   - an optional units row right after the names (a row in which no cell is a number: "s,m" or "-,m");
//   - cells separated by commas, semicolons or tabs (the names row decides), or by blanks when the row has
//     none of them (whitespace-separated text, as solvers and loggers write it);
//   - numbers in C syntax ("1e-3", "+42"), read without locale; "inf" only where a table allows it.
// Every problem is an InputError naming the field, the file, the line, the column (number and name) and what
// was expected. Files go through the input gate (core/input_limits: size, rows, columns) first, and a file in
// a format Maris knows but the field does not take (a PEER .AT2 record, WAMIT or Nemoh output) is named as such.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.hpp"

namespace maris {

struct TableSpec {
  std::string field;     // the scenario field (or GUI action) the file comes from: "parameters.hull.offsets_file"
  std::string file;      // the file or built-in data set, as the user gave it
  std::string expected;  // what the file should hold, for messages: "columns time [s], acceleration [m/s^2]"
  enum class Names { required, optional, none } names = Names::required;
  bool empty_cells = false;   // an empty cell (or a short row) means "no value"; else it is an error
  bool infinity = false;      // "inf" is a value (e.g. no free surface); NaN never is
  std::size_t min_columns = 1;
};

struct TextTable {
  struct Row {
    int line = 0;                                // line in the file (1-based)
    std::vector<std::optional<double>> cells;    // one per column; nullopt = empty cell
  };
  std::vector<std::string> names;  // column names, units cut off ("column_3" where the row has none)
  std::vector<std::string> units;  // one per column, "" where none is given
  std::vector<Row> rows;
  std::vector<FieldError> errors;  // cell problems (kept only with parseTable(..., keep_errors = true))

  int column(const std::string& name) const;  // -1 if absent
  std::size_t columns() const { return names.size(); }
};

// The error for `line` (0: the whole file) and, when `column` ≥ 0, that column of `table`, in the shared
// wording: field = "file": line L, column C (name): message.
FieldError tableError(const TableSpec& spec, int line, const std::string& message, const TextTable* table = nullptr,
                      int column = -1);

// Parses `text`. Throws InputError listing the cell problems (at most kReportedErrorLimit), unless
// `keep_errors`, when they are returned in TextTable::errors (bad cells read as nullopt) so that a caller can
// add its own checks and report everything at once.
TextTable parseTable(std::string_view text, const TableSpec& spec, bool keep_errors = false);

// The text behind `path` (readDataText: "builtin:NAME" or a file through the input gate), refused with the
// format's name when it is a known non-table format, then parsed.
TextTable readTable(std::string_view path, std::string_view scene, const TableSpec& spec);

// Throws InputError when `text` is in a format Maris recognises (formats/format_detect.hpp) other than a table:
// "looks like a PEER NGA .AT2 accelerogram; this field does not read that format; expected ...".
void refuseForeignFormat(std::string_view text, const TableSpec& spec);

}  // namespace maris
