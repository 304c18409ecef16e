// The study file format as a JSON Schema (draft 2020-12) and as text: `maris-cli schema study [--json]`.
#pragma once

#include <string>

#include "core/schema.hpp"

namespace maris::study {

Json studySchemaJson();
std::string describeStudySchema();

}  // namespace maris::study
