// Small helpers shared by the UI tests.
#pragma once

#include <QCoreApplication>
#include <QFileInfo>
#include <QImage>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace maris::test {

// Keeps QSettings (recent files, theme, colour maps) of tests away from the user's own and from each other:
// one settings file per test program, emptied at its start. A shared file let ui.view3d's greyscale choice
// reach ui.main_window's report check when ctest ran both at once.
inline void isolateSettings() {
  QStandardPaths::setTestModeEnabled(true);
  const QString program = QFileInfo(QCoreApplication::applicationFilePath()).baseName();
  QCoreApplication::setOrganizationName(QStringLiteral("MarisTests"));
  QCoreApplication::setApplicationName(QStringLiteral("maris-ui-test-") + program);
  QSettings().clear();
}

// Fraction of pixels whose colour is saturated (not a grey or near-white background).
inline double saturatedFraction(const QImage& image, QRect area = {}) {
  if (area.isNull()) area = image.rect();
  long saturated = 0, total = 0;
  for (int y = area.top(); y <= area.bottom(); ++y)
    for (int x = area.left(); x <= area.right(); ++x) {
      const QColor c = image.pixelColor(x, y);
      ++total;
      if (c.hsvSaturationF() > 0.45 && c.valueF() > 0.2) ++saturated;
    }
  return total ? static_cast<double>(saturated) / total : 0.0;
}

// Number of distinct colours (a blank image has one).
inline int distinctColours(const QImage& image, int limit = 64) {
  QSet<QRgb> colours;
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2) {
      colours.insert(image.pixel(x, y));
      if (colours.size() >= limit) return limit;
    }
  return static_cast<int>(colours.size());
}

// The cells of a CSV file without quoted fields, row by row (split at every comma).
inline std::vector<std::vector<std::string>> readCsv(const QString& file) {
  std::ifstream in(file.toStdString());
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// Saves `image` under $MARIS_UI_SCREENSHOT_DIR (if set) for people to look at.
inline void keepScreenshot(const QImage& image, const QString& name) {
  const QByteArray dir = qgetenv("MARIS_UI_SCREENSHOT_DIR");
  if (!dir.isEmpty()) image.save(QString::fromLocal8Bit(dir) + "/" + name + ".png");
}

}  // namespace maris::test
