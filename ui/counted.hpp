// A count with its noun in the singular or the plural: "1 case", "5 cases". The application loads no
// translation, and only a translation gives tr("%n case(s)", nullptr, n) its plural forms, so the two forms
// are written out.
#pragma once

#include <QString>

namespace maris::ui {

inline QString counted(int n, const QString& one, const QString& many) {
  return QStringLiteral("%1 %2").arg(n).arg(n == 1 ? one : many);
}

}  // namespace maris::ui
