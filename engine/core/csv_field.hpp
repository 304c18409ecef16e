// One field of a CSV file as the engine writes it (tables, study.csv).
#pragma once

#include <string>

namespace maris {

// Appends `field`, quoted (with doubled quotes) when it holds a comma, a quote or a line break.
void appendCsvField(std::string& out, const std::string& field);

// A number as every CSV file of Maris holds it: 17 significant digits (the double reads back bit for bit),
// '.' as the decimal point whatever the process's locale (the desktop application runs in the user's locale,
// where printf would write "0,5"), "nan"/"inf" for non-finite values.
std::string csvNumber(double value);

}  // namespace maris
