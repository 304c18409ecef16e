// The minimal study model the desktop application builds on: a full-factorial grid over one base
// scenario, in the versioned study file
//
//   {"format": "maris-study/1", "name": "...", "description": "...",
//    "base": {"scenario": {...inline scenario...}} | {"builtin": "riser_default"} | {"file": "base.json"},
//    "grid": {"geometry.length": [50, 100, 150],
//             "geometry.radius": {"from": 0.2, "to": 0.8, "count": 4, "spacing": "linear" | "log"}},
//    "results": ["max_deflection"]}           (optional; default: every scalar)
//
// its expansion into validated cases and study.csv. Only grids: tables and Latin-hypercube
// samples are not read here. A file path of the base is relative to the study file's folder.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/results.hpp"
#include "core/scene.hpp"

namespace maris::study {

inline constexpr const char* kStudyFormat = "maris-study/1";

// One varied parameter: explicit values, or `count` values from `from` to `to` (evenly spaced, or
// evenly in the logarithm).
struct GridParameter {
  std::string path;            // below "parameters"
  std::vector<double> values;  // explicit values (then from/to/count are unused)
  double from = 0.0, to = 0.0;
  int count = 0;
  bool log = false;
  bool operator==(const GridParameter&) const = default;
};

struct StudyDefinition {
  std::string name;
  std::string description;
  Scenario base;
  std::vector<GridParameter> grid;   // the first parameter varies slowest (a file reads back sorted by path)
  std::vector<std::string> results;  // scalars in study.csv; empty: every scalar of the cases
};

// The values of one grid parameter, in order. Throws InputError (path "grid.<path>") for a count
// below 1 or above 100 000, non-finite ends, or a log spacing with an end <= 0.
std::vector<double> gridValues(const GridParameter& parameter);

Json studyToJson(const StudyDefinition& study);
// `builtin` finds a built-in scenario by id (nullptr if none); `folder` is where a base file path
// is resolved. Throws InputError naming every problem of the envelope.
StudyDefinition studyFromJson(const Json& document, const std::function<const Scenario*(const std::string&)>& builtin,
                              const std::filesystem::path& folder);
StudyDefinition loadStudyFile(const std::filesystem::path& file,
                              const std::function<const Scenario*(const std::string&)>& builtin);
// Atomic (writeFileAtomic).
void saveStudyFile(const StudyDefinition& study, const std::filesystem::path& file);

struct StudyCase {
  std::string id;             // "0001", "0002", … (four digits at least)
  Scenario scenario;          // the base with this case's values
  std::vector<double> values; // one per grid parameter
};

// Every case of the grid (the product of the parameters' values; the last varies fastest), each
// validated against `scene` (schema and cross-field checks). Throws InputError listing every bad
// case's problems ("case 0003: parameters.geometry.radius = 60: ..."), so nothing runs then.
std::vector<StudyCase> expandStudy(const StudyDefinition& study, const SceneDefinition& scene);

// One case's outcome for study.csv.
struct CaseResult {
  std::string status;                // "ok", "failed", "cancelled", "pending"
  const Results* results = nullptr;  // when status is "ok"
};

// study.csv: names row (case, status, every grid parameter, every collected scalar), units row,
// then one row per case (numbers at 17 significant digits; empty cells for a case without results).
// The scalars are `study.results`, or else every scalar of the finished cases in order of appearance.
std::string studyCsv(const StudyDefinition& study, const SceneDefinition& scene, const std::vector<StudyCase>& cases,
                     const std::vector<CaseResult>& outcomes);

}  // namespace maris::study
