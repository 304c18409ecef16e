#include "editor/field_text.hpp"

#include <QLocale>
#include <QStringList>

#include "document/scenario_document.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

Json parseNumber(const QString& text, bool integer) {
  const QString t = text.trimmed();
  bool ok = false;
  if (integer) {
    const qlonglong n = t.toLongLong(&ok);
    if (ok) return Json(static_cast<long long>(n));
  }
  // Numbers are read in the C locale ("1.5e3"), whatever the desktop's locale.
  const double x = QLocale::c().toDouble(t, &ok);
  if (ok) return Json(x);
  return Json(t.toStdString());
}

}  // namespace

Json parseFieldText(const QString& text, ParamKind kind) {
  switch (kind) {
    case ParamKind::Real:
      return parseNumber(text, false);
    case ParamKind::Integer:
      return parseNumber(text, true);
    case ParamKind::Boolean: {
      const QString t = text.trimmed().toLower();
      if (t == "true" || t == "yes" || t == "1") return Json(true);
      if (t == "false" || t == "no" || t == "0") return Json(false);
      return Json(text.trimmed().toStdString());
    }
    case ParamKind::RealList: {
      Json list = Json::array();
      const QString t = text.trimmed();
      if (t.isEmpty()) return list;
      for (const QString& part : t.split(QLatin1Char(','))) list.push_back(parseNumber(part, false));
      return list;
    }
    case ParamKind::Choice:
    case ParamKind::Text:
    case ParamKind::Table:
      break;
  }
  return Json(text.toStdString());
}

QString fieldText(const Json& value, ParamKind kind) {
  if (kind == ParamKind::RealList && value.is_array()) {
    QStringList parts;
    for (const auto& v : value) parts << displayValue(v);
    return parts.join(QStringLiteral(", "));
  }
  if (value.is_null()) return {};
  return displayValue(value);
}

QString fieldTooltip(const ParamSpec& spec) {
  QString tip = QStringLiteral("<b>%1</b><br>%2").arg(QString::fromStdString(spec.path).toHtmlEscaped(),
                                                       QString::fromStdString(spec.description).toHtmlEscaped());
  if (const QString unit = unitText(spec.unit); !unit.isEmpty()) tip += QStringLiteral("<br>Unit: %1").arg(unit);
  if (spec.kind == ParamKind::Real || spec.kind == ParamKind::Integer || spec.kind == ParamKind::RealList)
    tip += QStringLiteral("<br>Range: %1").arg(QString::fromStdString(spec.range.str()).toHtmlEscaped());
  if (spec.kind == ParamKind::Choice) {
    QStringList choices;
    for (const auto& c : spec.choices) choices << QString::fromStdString(c);
    tip += QStringLiteral("<br>Choices: %1").arg(choices.join(QStringLiteral(", ")).toHtmlEscaped());
  }
  if (spec.kind == ParamKind::RealList || spec.kind == ParamKind::Table)
    tip += QStringLiteral("<br>Items: %1 to %2").arg(spec.min_items).arg(spec.max_items);
  if (spec.kind != ParamKind::Table)
    tip += QStringLiteral("<br>Default: %1").arg(fieldText(spec.default_value, spec.kind).toHtmlEscaped());
  return tip;
}

}  // namespace maris::ui
