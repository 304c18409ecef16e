// Inside the study library: reading and expanding the three designs (grid, table, Latin hypercube).
#pragma once

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/scene.hpp"
#include "study/study.hpp"

namespace maris::study::detail {

// The parameter at `raw` ("geometry.length" or "parameters.geometry.length") of `scene`, or nullptr after
// adding an error at `where` (with a did-you-mean). A table field is refused unless `whole_tables` (a
// study's "set" may replace a table; a design varies single values).
const ParamSpec* lookupParameter(const SceneDefinition& scene, const std::string& raw, const std::string& where,
                                 std::vector<FieldError>& errors, bool whole_tables = false);

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
