// Inside the study library: reading and expanding the three designs (grid, table, Latin hypercube).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/scene.hpp"
#include "study/study.hpp"

namespace maris::study::detail {

// The parameter at `raw` ("geometry.length" or "parameters.geometry.length") of `scene`, or nothing after
// adding an error at `where` (with a did-you-mean). A table field is refused unless `whole_tables` (a
// study's "set" may replace a table; a design varies single values). A cell of a table, "current.profile[1].speed"
// (rows from 0), is its column's spec with that path as `path`; its row must be in `base` (the base's parameters).
std::optional<ParamSpec> lookupParameter(const SceneDefinition& scene, const Json& base, const std::string& raw,
                                         const std::string& where, std::vector<FieldError>& errors,
                                         bool whole_tables = false);
// The cell part of lookupParameter (study_cell_paths.cpp): `is_cell` tells whether `path` names a cell at all.
std::optional<ParamSpec> lookupTableCell(const SceneDefinition& scene, const Json& base, const std::string& path,
                                         const std::string& where, std::vector<FieldError>& errors, bool& is_cell);
// Splits "TABLE[ROW].COLUMN"; nothing when `path` has no '[' (a plain field) or is malformed (`malformed` set).
std::optional<TableCell> splitTableCell(const std::string& path, bool& malformed);
// "Speed of current profile row 2": the label for people of a cell (`row` counted from 0, as in its path).
std::string cellLabel(const ParamSpec& table, const ParamSpec& column, std::size_t row);
// Writes `value` at `path` of a scenario's parameters: a dotted path, or a cell whose row lookupParameter checked.
void setParameter(Json& parameters, const std::string& path, Json value);

// The parameter of `spec` as a study varies it.
StudyParameter studyParameter(const ParamSpec& spec);

// Fill study.parameters and the design's data from the document's "grid", "table" or "latin_hypercube".
void readGrid(const Json& grid, const SceneDefinition& scene, Study& study, std::vector<FieldError>& errors);
void readTable(const Json& table, const SceneDefinition& scene, Study& study, std::vector<FieldError>& errors);
void readLatinHypercube(const Json& design, const SceneDefinition& scene, Study& study,
                        std::vector<FieldError>& errors);

// The values of every case of a Latin hypercube, one row per case (deterministic for a seed).
std::vector<std::vector<Json>> latinHypercubeRows(const Study& study);

// A number as the parameter's kind stores it: integers rounded to whole numbers.
Json numberValue(double value, ParamKind kind);

}  // namespace maris::study::detail
