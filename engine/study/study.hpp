// Design studies: many runs of one scene, each a copy of a base scenario with some parameters varied.
//
//   {"format": "maris-study/1", "name": "...", "description": "...",
//    "base": "riser_default" | "base.json" | {scenario object},
//    "set": {"path": value, ...},                              fixed changes to the base (optional)
//    and exactly one design:
//    "grid": {"path": [v1, v2, ...] | {"from": a, "to": b, "count": n, "spacing": "linear"|"log"}, ...}
//    "table": "cases.csv"                                      one column per parameter path, one row per case
//    "latin_hypercube": {"count": n, "seed": s, "bounds": {"path": [low, high] | {"from", "to", "spacing"}}}
//    "results": ["scalar", ...]                                what to collect (optional; default all scalars)
//    "weighted_sum": {"weight": "column", "results": [...]}     table only: a column of case weights (optional)}
//
// A study knows no scene by name: it reaches the scene of its base scenario through the catalog
// (catalog.hpp) and checks every case with the scene's schema, checks and work estimate, as `maris-cli
// run` does, before anything runs. Paths in a study (base file, table, data files of the scenarios)
// are relative to the study file's folder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scenario.hpp"
#include "core/scene.hpp"
#include "core/schema.hpp"

namespace maris::study {

inline constexpr const char* kStudyFormat = "maris-study/1";

struct StudyLimits {
  static constexpr std::size_t kCases = 100000;  // cases of one study (a grid's product, a table's rows, a sample)
};

enum class DesignKind { Grid, Table, LatinHypercube };
const char* toString(DesignKind kind);  // "grid", "table", "latin_hypercube"

enum class Spacing { Linear, Log };

// A varied parameter, as the scene's schema declares it.
struct StudyParameter {
  std::string path;  // below "parameters": "geometry.length"
  std::string unit;  // SI unit ("m"), "-" dimensionless, "" for text
  ParamKind kind = ParamKind::Real;
  // For people (plots, legends, tables): the schema's label ("Length L"), for a cell its column's with the table
  // and row ("Speed of current profile row 2"); empty for a study folder whose scene this program lacks.
  std::string label;
};
// The parameter's label, or its path where it has none.
std::string displayLabel(const StudyParameter& parameter);

// Latin hypercube: the interval of one parameter.
struct SampleBounds {
  double low = 0.0, high = 1.0;
  Spacing spacing = Spacing::Linear;  // Log: uniform in log(value)
};

// Where a study finds its base scenario's scene and built-in scenarios: the program's catalog
// (catalogSource), or a caller's own set (the desktop application's scene library).
struct SceneSource {
  std::function<const SceneDefinition*(const std::string&)> scene;  // by scene name; nullptr if none
  std::function<const Scenario*(const std::string&)> builtin;       // by built-in scenario id; nullptr if none
  std::function<std::vector<std::string>()> builtin_ids;            // for "did you mean"
};
SceneSource catalogSource();

struct Study {
  const SceneDefinition* scene = nullptr;  // the base scenario's scene, from the SceneSource (outlives the study)
  std::string name;
  std::string description;
  std::filesystem::path folder;  // absolute: the study file's folder (relative paths resolve against it)
  Json document;                 // the study document as read
  Scenario base;                 // with "set" applied, upgraded, data paths absolute
  std::string base_origin;       // "built-in riser_default", "file /abs/base.json" or "inline"
  std::vector<std::string> notes;  // upgrades of old field names in the base
  DesignKind kind = DesignKind::Grid;
  std::vector<StudyParameter> parameters;    // in alphabetical order of path (JSON objects are unordered)
  std::vector<std::vector<Json>> grid;       // Grid: the values of each parameter
  std::vector<std::vector<Json>> rows;       // Table: per case, one value per parameter
  std::filesystem::path table_file;          // Table: absolute
  std::size_t sample_count = 0;              // LatinHypercube
  std::uint64_t seed = 0;                    // LatinHypercube
  std::vector<SampleBounds> bounds;          // LatinHypercube: one per parameter
  std::vector<std::string> results;          // scalars to collect; empty: every scalar of summary.json
  // Table: a column of the table that is no parameter but each case's weight (a sea state's probability);
  // collecting writes the weighted sum of each of `weighted_results` over the cases.
  std::string weight_column;                 // empty: none
  std::vector<double> weights;               // one per row (case), finite and >= 0
  std::vector<std::string> weighted_results;
};

// One case: the base with the case's values set.
struct StudyCase {
  std::string id;            // "0001": 1-based, at least four digits
  std::vector<Json> values;  // one per Study::parameters
  Scenario scenario;
};

// True when `document` says it is a study ("format": "maris-study/..."), so `validate` can tell
// studies from scenarios.
bool isStudyDocument(const Json& document);

// Reads and checks a study file (every problem at once): the envelope, the base scenario, the parameter
// paths against the scene's schema, the design. Throws InputError.
Study loadStudyFile(const std::filesystem::path& file, const SceneSource& source = catalogSource());
// The same for a parsed document; `folder` resolves relative paths, `origin` names the study in errors.
Study studyFromJson(const Json& document, const std::filesystem::path& folder,
                    const SceneSource& source = catalogSource());

// The number of cases; throws InputError beyond StudyLimits::kCases.
std::size_t caseCount(const Study& study);
// Every case, in order: a grid varies its last parameter fastest; a table's cases are its data rows;
// a Latin hypercube's are its samples in the order drawn.
std::vector<StudyCase> expandStudy(const Study& study);

// Every problem of every case (schema, the scene's cross-field checks and, unless `allow_large`, the work
// limits), each named "case 0003: parameters.x", led by one line listing all bad cases. Empty: all can run.
std::vector<FieldError> caseErrors(const Study& study, const std::vector<StudyCase>& cases, bool allow_large);

// The column names of a table study's CSV file (its header row, read as "table" reads it): a front end offers
// those that are no parameter as the weight column of a "weighted_sum". Throws InputError.
std::vector<std::string> tableColumns(const std::filesystem::path& file);

// A cell of a table field as a varied parameter, "TABLE[ROW].COLUMN": "current.profile[1].speed" is the speed of
// the current profile's second row (rows counted from 0, as the schema's messages count them).
struct TableCell {
  std::string table;  // "current.profile"
  std::size_t row = 0;
  std::string column;  // "speed"
};
// The cell `path` names; nothing for a plain field or a malformed cell path.
std::optional<TableCell> tableCell(const std::string& path);
// "current.profile[1].speed" from its parts.
std::string tableCellPath(const std::string& table, std::size_t row, const std::string& column);

// What a study may vary at `path` ("geometry.length", "current.profile[1].speed", with or without
// "parameters.") of `scene` over a base scenario's `parameters` (a cell's row must be in them): the field's
// spec, or for a cell its column's spec with the cell's path as `path`. Nothing, with the reason in `why`
// (if given), for anything else — the check a study file's parameters get.
std::optional<ParamSpec> findStudyParameter(const SceneDefinition& scene, const Json& parameters,
                                            const std::string& path, std::string* why = nullptr);
// The label for people of the field or cell `path` of `schema` (StudyParameter::label), or "" when the schema
// has no such field or column.
std::string studyParameterLabel(const Schema& schema, const std::string& path);
// The value at `path` (a dotted path or a cell) of a scenario's parameters; nullptr if there is none.
const Json* findParameterValue(const Json& parameters, const std::string& path);

// "0001" for index 0 of up to 9999 cases; more digits for larger studies.
std::string caseId(std::size_t index, std::size_t count);
// "0003, 0007, 0012-0020": case ids with runs of consecutive ones shortened.
std::string caseRanges(const std::vector<std::size_t>& indices, std::size_t count);

}  // namespace maris::study
