// A scene's parameter schema: every field's path, kind, unit, default, allowed range and
// description, declared in one place (next to the scene's parameter struct, see schema_binder.hpp).
// Scenario files, the CLI's `schema` command and the GUI's parameter editor are all built from it.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"

namespace maris {

using Json = nlohmann::json;

enum class ParamKind {
  Real,      // a finite double
  Integer,   // a whole number
  Boolean,   // true/false
  Choice,    // one string out of `choices`
  Text,      // free text (names, file paths)
  RealList,  // array of doubles, each within `range`
  Table,     // array of objects (rows) whose fields are `columns`
};

const char* toString(ParamKind kind);

// Closed or open interval; infinite ends mean "no bound".
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // true: value must be > min
  bool max_open = false;  // true: value must be < max

  static Range any() { return {}; }
  static Range positive(double max = std::numeric_limits<double>::infinity()) { return {0.0, max, true, false}; }
  static Range nonNegative(double max = std::numeric_limits<double>::infinity()) { return {0.0, max, false, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }

  bool contains(double v) const;
  std::string str() const;  // "(0, 1e+05]", "[2, 5000]", "any number"
};

struct ParamSpec {
  std::string path;         // dotted path below "parameters", e.g. "geometry.length"; for table columns the column key
  ParamKind kind = ParamKind::Real;
  std::string unit;         // SI unit ("m", "N/m^2", "kg/m^3", "s", "rad"); "-" for dimensionless; "" for text
  std::string description;  // one line
  std::string label;        // short name for people with the symbol, as plots and tables show it ("Length L");
                            // empty: parameterLabel falls back to the key made readable
  Json default_value;       // default as JSON
  Range range;              // Real, Integer, RealList elements
  std::vector<std::string> choices;  // Choice
  std::vector<ParamSpec> columns;    // Table
  std::size_t min_items = 0;         // RealList / Table length bounds
  std::size_t max_items = 100000;
  bool data_path = false;            // Text naming a data file or folder: a relative path resolves against the
                                     // folder of the scenario or study file that holds it (resolveDataPaths)

  std::string group() const;  // first path component ("geometry")
  std::string key() const;    // last path component ("length")
};

// What people read for a field or column: its label, or where the scene declared none, its key made readable
// ("Segment count" from "discretisation.segment_count"). Scenario files and study paths keep the paths.
std::string parameterLabel(const ParamSpec& spec);

// The label for people of a table's cell, `row` counted from 0 as in its path ("current.profile[1].speed") and
// from 1 for people, as the parameter editor's table numbers its rows: "Speed of current profile row 2".
std::string tableCellLabel(const ParamSpec& table, const ParamSpec& column, std::size_t row);

struct Schema {
  std::vector<ParamSpec> fields;
  const ParamSpec* find(const std::string& path) const;
  Json defaults() const;  // nested JSON object with every default
};

// Validates `parameters` (the object under "parameters" in a scenario) against the schema and
// returns every problem: wrong types, values out of range, NaN/inf, missing fields, unknown fields
// (with a did-you-mean), bad rows in tables. Paths are prefixed with `prefix` ("parameters").
std::vector<FieldError> validateAgainstSchema(const Schema& schema, const Json& parameters,
                                              const std::string& prefix = "parameters");

// Reads/writes a value at a dotted path ("geometry.length") inside a nested JSON object.
const Json* findAtPath(const Json& root, const std::string& dotted_path);
void setAtPath(Json& root, const std::string& dotted_path, Json value);

// Closest candidate by edit distance, or "" if none is close enough to suggest.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

// Human-readable schema listing for `maris-cli schema SCENE`; and a JSON form.
std::string describeSchema(const Schema& schema);
Json schemaToJson(const Schema& schema);

// Short JSON text of a value for error messages (long values are abbreviated).
std::string jsonSnippet(const Json& value);

}  // namespace maris
