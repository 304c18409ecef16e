// Numbers in the study editors' tables and fields: 12 significant digits, so that a value read back from
// its cell is the value written.
#pragma once

#include <QString>

namespace maris::ui {

inline QString cellText(double v) { return QString::number(v, 'g', 12); }

}  // namespace maris::ui
