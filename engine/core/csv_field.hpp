// One field of a CSV file as the engine writes it (tables, study.csv).
#pragma once

#include <string>

namespace maris {

// Appends `field`, quoted (with doubled quotes) when it holds a comma, a quote or a line break.
void appendCsvField(std::string& out, const std::string& field);

}  // namespace maris
