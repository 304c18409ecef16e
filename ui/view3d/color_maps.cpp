#include "view3d/color_maps.hpp"

#include <algorithm>
#include <array>

#include <QObject>
#include <QSettings>
#include <QUrl>

#include <vtkColorTransferFunction.h>

#include "plots/viridis.hpp"

namespace maris::ui {

namespace {

constexpr std::array<ColorMap, 4> kMaps{ColorMap::CoolWarm, ColorMap::Viridis, ColorMap::Rainbow, ColorMap::Greyscale};

// A quantity's name may hold '/', which QSettings reads as a group separator.
QString settingsGroup(const std::string& quantity) {
  return QStringLiteral("colorMaps/") + QString::fromLatin1(QUrl::toPercentEncoding(QString::fromStdString(quantity)));
}

}  // namespace

std::optional<ColorSettings> loadColorSettings(const std::string& quantity) {
  QSettings settings;
  settings.beginGroup(settingsGroup(quantity));
  // "coolwarm": the name settings files held before the maps had one name each.
  const QString key = settings.value(QStringLiteral("map")).toString();
  const std::optional<ColorMap> map = key == QLatin1String("coolwarm") ? ColorMap::CoolWarm : colorMapFromKey(key);
  if (!map) return std::nullopt;  // none saved, or a map this version lacks
  ColorSettings out;
  out.map = *map;
  out.automatic = settings.value(QStringLiteral("automatic"), true).toBool();
  out.per_frame = settings.value(QStringLiteral("per_frame"), false).toBool();
  bool min_ok = false, max_ok = false;
  out.min = settings.value(QStringLiteral("min")).toDouble(&min_ok);
  out.max = settings.value(QStringLiteral("max")).toDouble(&max_ok);
  if (!min_ok || !max_ok || !(out.max > out.min)) {  // a damaged range falls back to automatic
    out.automatic = true;
    out.min = ColorSettings{}.min;
    out.max = ColorSettings{}.max;
  }
  return out;
}

void saveColorSettings(const std::string& quantity, const ColorSettings& settings) {
  QSettings store;
  store.beginGroup(settingsGroup(quantity));
  store.setValue(QStringLiteral("map"), colorMapKey(settings.map));
  store.setValue(QStringLiteral("automatic"), settings.automatic);
  store.setValue(QStringLiteral("per_frame"), settings.per_frame);
  store.setValue(QStringLiteral("min"), settings.min);
  store.setValue(QStringLiteral("max"), settings.max);
}

QString colorMapKey(ColorMap map) {
  switch (map) {
    case ColorMap::CoolWarm: return QStringLiteral("cool-warm");
    case ColorMap::Viridis: return QStringLiteral("viridis");
    case ColorMap::Rainbow: return QStringLiteral("rainbow");
    case ColorMap::Greyscale: return QStringLiteral("greyscale");
  }
  return {};
}

QStringList colorMapKeys() {
  QStringList keys;
  for (ColorMap map : kMaps) keys << colorMapKey(map);
  return keys;
}

std::optional<ColorMap> colorMapFromKey(const QString& key) {
  for (ColorMap map : kMaps)
    if (key == colorMapKey(map)) return map;
  return std::nullopt;
}

QStringList colorMapNames() {
  return {QObject::tr("Cool to warm"), QObject::tr("Viridis"), QObject::tr("Rainbow"), QObject::tr("Greyscale")};
}

void fillColorMap(vtkColorTransferFunction* colors, ColorMap map, double lo, double hi) {
  colors->RemoveAllPoints();
  switch (map) {
    case ColorMap::CoolWarm:
      // Moreland's end colours; the diverging space puts a neutral light grey in the middle.
      colors->SetColorSpaceToDiverging();
      colors->AddRGBPoint(lo, 0.230, 0.299, 0.754);
      colors->AddRGBPoint(hi, 0.706, 0.016, 0.150);
      break;
    case ColorMap::Viridis:
      colors->SetColorSpaceToRGB();
      for (std::size_t i = 0; i < kViridis.size(); ++i) {
        const double x = lo + (hi - lo) * static_cast<double>(i) / (kViridis.size() - 1);
        colors->AddRGBPoint(x, kViridis[i][0] / 255.0, kViridis[i][1] / 255.0, kViridis[i][2] / 255.0);
      }
      break;
    case ColorMap::Rainbow:
      // Hue 2/3 (blue) down to 0 (red) the short way, through cyan, green and yellow.
      colors->SetColorSpaceToHSV();
      colors->HSVWrapOff();
      colors->AddHSVPoint(lo, 0.667, 1.0, 1.0);
      colors->AddHSVPoint(hi, 0.0, 1.0, 1.0);
      break;
    case ColorMap::Greyscale:
      // Not black: the dark theme's background is nearly black.
      colors->SetColorSpaceToRGB();
      colors->AddRGBPoint(lo, 0.15, 0.15, 0.15);
      colors->AddRGBPoint(hi, 0.95, 0.95, 0.95);
      break;
  }
  colors->ClampingOn();
  colors->Build();
}

}  // namespace maris::ui
