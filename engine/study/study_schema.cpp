#include "study/study_schema.hpp"

#include "study/study.hpp"

namespace maris::study {

namespace {

Json rangeSchema(bool with_count) {
  Json properties = {{"from", {{"type", "number"}, {"description", "first value"}}},
                     {"to", {{"type", "number"}, {"description", "last value"}}},
                     {"spacing", {{"enum", {"linear", "log"}}, {"default", "linear"},
                                  {"description", "even steps in the value, or in its logarithm (from, to > 0)"}}}};
  Json required = {"from", "to"};
  if (with_count) {
    properties["count"] = {{"type", "integer"}, {"minimum", 1}, {"maximum", StudyLimits::kCases},
                           {"description", "number of values, both ends included"}};
    required.push_back("count");
  }
  return {{"type", "object"}, {"properties", properties}, {"required", required}, {"additionalProperties", false}};
}

}  // namespace

Json studySchemaJson() {
  const Json parameter_map_note =
      "keys are parameter paths of the base scenario's scene (see `maris-cli schema SCENE`), with or without "
      "the \"parameters.\" prefix, or one cell of a table field, TABLE[ROW].COLUMN with rows from 0 "
      "(\"current.profile[1].speed\"; the row must be in the base); they are taken in alphabetical order";
  Json grid = {{"type", "object"},
               {"minProperties", 1},
               {"description", "full-factorial grid: every combination of the values; the last parameter (in "
                               "alphabetical order of path) varies fastest; " +
                                   parameter_map_note.get<std::string>()},
               {"additionalProperties", {{"oneOf", {{{"type", "array"}, {"minItems", 1}}, rangeSchema(true)}}}}};
  Json table = {{"type", "string"},
                {"description", "CSV file (relative to the study's folder): a header row of parameter paths, an "
                                "optional row of units (SI, as the schema states them), one row per case; "
                                "separators , ; or tab; lines starting with # are skipped"}};
  Json lhs = {{"type", "object"},
              {"required", {"count", "seed", "bounds"}},
              {"additionalProperties", false},
              {"description", "Latin-hypercube sample: each parameter's interval cut into count equal strata "
                              "(in the logarithm for log spacing), one case in each; the same seed gives the same "
                              "cases on every machine (std::mt19937_64)"},
              {"properties",
               {{"count", {{"type", "integer"}, {"minimum", 1}, {"maximum", StudyLimits::kCases}}},
                {"seed", {{"type", "integer"}, {"minimum", 0}}},
                {"bounds", {{"type", "object"},
                            {"minProperties", 1},
                            {"description", parameter_map_note},
                            {"additionalProperties",
                             {{"oneOf", {{{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}},
                                         rangeSchema(false)}}}}}}}}};
  Json base = {{"description", "the base scenario: a built-in scenario's name, a scenario file (relative to the "
                               "study's folder; its data paths relative to its own folder) or a scenario object"},
               {"oneOf", {{{"type", "string"}}, {{"type", "object"}}}}};
  return {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
          {"title", "Maris design study"},
          {"description", "Runs of one scene: a base scenario and what varies. Every case is checked against the "
                          "scene's schema, checks and work limits before anything runs. Relative paths (base, "
                          "table, data files) resolve against the study file's folder."},
          {"type", "object"},
          {"required", {"format", "base"}},
          {"additionalProperties", false},
          {"oneOf", {{{"required", {"grid"}}}, {{"required", {"table"}}}, {{"required", {"latin_hypercube"}}}}},
          {"properties",
           {{"format", {{"const", kStudyFormat}}},
            {"name", {{"type", "string"}}},
            {"description", {{"type", "string"}}},
            {"base", base},
            {"set", {{"type", "object"},
                     {"description", "fixed parameter values written into the base before the cases vary it"}}},
            {"grid", grid},
            {"table", table},
            {"latin_hypercube", lhs},
            {"results", {{"type", "array"},
                         {"items", {{"type", "string"}}},
                         {"uniqueItems", true},
                         {"description", "scalar results to collect into study.csv (names as in a run's "
                                         "summary.json); default: every scalar"}}},
            {"weighted_sum",
             {{"type", "object"},
              {"additionalProperties", false},
              {"required", {"weight", "results"}},
              {"description", "table studies: a column of the table (not a parameter) holding each case's weight, "
                              "e.g. a sea state's probability; `study collect` writes sum_i weight_i * result_i "
                              "of each listed scalar into study.json"},
              {"properties",
               {{"weight", {{"type", "string"}, {"description", "the weight column's name in the table's header"}}},
                {"results", {{"type", "array"}, {"items", {{"type", "string"}}}, {"uniqueItems", true},
                             {"minItems", 1}}}}}}}}}};
}

std::string describeStudySchema() {
  return std::string("study: a design study (") + kStudyFormat + R"(), a JSON file
  format           "maris-study/1"
  name, description  text (optional)
  base             a built-in scenario's name, a scenario file (relative to the study's folder) or a
                   scenario object
  set              {"path": value, ...}: fixed values written into the base (optional)
  one design:
  grid             {"path": [v1, v2, ...] | {"from": a, "to": b, "count": n, "spacing": "linear"|"log"}, ...}
                   every combination; the last path (alphabetical order) varies fastest
  table            "cases.csv": header of parameter paths, optional units row, one row per case
  latin_hypercube  {"count": n, "seed": s, "bounds": {"path": [low, high] | {"from", "to", "spacing"}, ...}}
  results          ["scalar", ...]: what study.csv collects (optional; default every scalar)
  weighted_sum     {"weight": "probability", "results": ["scalar", ...]}: a table study's column of case
                   weights (not a parameter, numbers >= 0); collect writes sum of weight * scalar
Paths are parameter paths of the base's scene (`maris-cli schema SCENE`), or one cell of a table field,
TABLE[ROW].COLUMN with rows from 0 ("current.profile[1].speed"). Relative file paths, also data
files in the base and in the values, resolve against the study file's folder. At most )" +
         std::to_string(StudyLimits::kCases) + " cases.\n";
}

}  // namespace maris::study
