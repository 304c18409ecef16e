// Text <-> JSON for parameter fields. What a user types is kept even when it is not a valid value
// (a word in a number field becomes a JSON string), so the schema's validation explains the
// problem in words next to the field instead of the editor silently refusing the keystrokes.
#pragma once

#include <QString>

#include "core/schema.hpp"

namespace maris::ui {

// Parses the text of a field of `kind` (Real, Integer, Boolean, Choice, Text; RealList as
// comma-separated numbers).
Json parseFieldText(const QString& text, ParamKind kind);
// The text a field shows for `value`.
QString fieldText(const Json& value, ParamKind kind);
// Tooltip: description, unit, allowed range, default.
QString fieldTooltip(const ParamSpec& spec);

}  // namespace maris::ui
