#include "plots/display_units.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <QSettings>
#include <QString>

#include "view3d/color_bar_scale.hpp"

namespace maris::ui {

namespace {

std::map<std::string, std::string>& chosenUnits() {
  static std::map<std::string, std::string> chosen;
  return chosen;
}

QString settingsKey(const std::string& si_unit) { return QStringLiteral("units/") + QString::fromStdString(si_unit); }

}  // namespace

DisplayUnit displayUnit(const std::string& si_unit) {
  const auto it = chosenUnits().find(si_unit);
  if (it != chosenUnits().end())
    for (const UnitPrefix& p : unitPrefixes(si_unit))
      if (p.symbol + si_unit == it->second) return {std::pow(10.0, -p.exponent), it->second};
  return {1.0, si_unit};
}

bool displayUnitChosen(const std::string& si_unit) {
  const auto it = chosenUnits().find(si_unit);
  if (it == chosenUnits().end()) return false;
  const auto choices = displayUnitChoices(si_unit);
  return std::find(choices.begin(), choices.end(), it->second) != choices.end();
}

std::vector<std::string> displayUnitChoices(const std::string& si_unit) {
  std::vector<std::string> choices;
  for (const UnitPrefix& p : unitPrefixes(si_unit)) choices.push_back(p.symbol + si_unit);
  return choices;
}

void setDisplayUnit(const std::string& si_unit, const std::string& shown) {
  chosenUnits()[si_unit] = shown;
  QSettings().setValue(settingsKey(si_unit), QString::fromStdString(shown));
}

QString unitText(const std::string& unit) {
  if (unit.empty() || unit == "-") return {};
  if (unit == "deg") return QStringLiteral("°");
  if (unit == "degC") return QStringLiteral("°C");
  QString text = QString::fromStdString(unit);
  text.replace(QStringLiteral("^-1"), QStringLiteral("⁻¹"));
  text.replace(QStringLiteral("^2"), QStringLiteral("²"));
  text.replace(QStringLiteral("^3"), QStringLiteral("³"));
  text.replace(QStringLiteral("^4"), QStringLiteral("⁴"));
  text.replace(QLatin1Char('*'), QStringLiteral("·"));
  return text;
}

void loadDisplayUnits() {
  QSettings settings;
  for (const char* si_unit : {"N", "Pa", "m"})
    if (settings.contains(settingsKey(si_unit)))
      chosenUnits()[si_unit] = settings.value(settingsKey(si_unit)).toString().toStdString();
}

}  // namespace maris::ui
