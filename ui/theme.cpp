#include "theme.hpp"

#include <QApplication>
#include <QStyle>
#include <QStyleFactory>

namespace maris::ui {

namespace {

// The platform's style and palette as the application started, for Theme::System.
struct PlatformLook {
  QString style;
  QPalette palette;
};

const PlatformLook& platformLook() {
  static const PlatformLook look{QApplication::style()->name(), QApplication::palette()};
  return look;
}

QPalette darkPalette() {
  const QColor window(0x2d, 0x2f, 0x33), base(0x1f, 0x21, 0x24), text(0xe6, 0xe6, 0xe6);
  const QColor disabled(0x80, 0x84, 0x8c), highlight(0x2f, 0x6d, 0xb5);
  QPalette p;
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, QColor(0x29, 0x2b, 0x2f));
  p.setColor(QPalette::ToolTipBase, QColor(0x3a, 0x3d, 0x42));
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::PlaceholderText, disabled);
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, QColor(0x36, 0x39, 0x3e));
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, QColor(0xff, 0x6b, 0x6b));
  p.setColor(QPalette::Light, QColor(0x48, 0x4b, 0x52));
  p.setColor(QPalette::Midlight, QColor(0x3c, 0x3f, 0x45));
  p.setColor(QPalette::Mid, QColor(0x26, 0x28, 0x2b));
  p.setColor(QPalette::Dark, QColor(0x1a, 0x1b, 0x1e));
  p.setColor(QPalette::Shadow, QColor(0x0c, 0x0c, 0x0e));
  p.setColor(QPalette::Highlight, highlight);
  p.setColor(QPalette::HighlightedText, Qt::white);
  p.setColor(QPalette::Link, QColor(0x6c, 0xb4, 0xee));
  p.setColor(QPalette::LinkVisited, QColor(0xb0, 0x8c, 0xe6));
  for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
    p.setColor(QPalette::Disabled, role, disabled);
  p.setColor(QPalette::Disabled, QPalette::Highlight, QColor(0x45, 0x48, 0x4e));
  return p;
}

}  // namespace

QString themeKey(Theme theme) {
  switch (theme) {
    case Theme::Light: return QStringLiteral("light");
    case Theme::Dark: return QStringLiteral("dark");
    case Theme::System: break;
  }
  return QStringLiteral("system");
}

Theme themeFromKey(const QString& key) {
  if (key == QLatin1String("light")) return Theme::Light;
  if (key == QLatin1String("dark")) return Theme::Dark;
  return Theme::System;
}

void applyTheme(Theme theme) {
  const PlatformLook& platform = platformLook();
  const QString style = theme == Theme::System ? platform.style : QStringLiteral("Fusion");
  if (QApplication::style()->name().compare(style, Qt::CaseInsensitive) != 0)
    if (QStyle* s = QStyleFactory::create(style)) QApplication::setStyle(s);
  if (theme == Theme::System) {
    QApplication::setPalette(platform.palette);
    return;
  }
  QApplication::setPalette(theme == Theme::Dark ? darkPalette() : QApplication::style()->standardPalette());
}

bool isDark(const QPalette& palette) { return palette.color(QPalette::Window).lightnessF() < 0.45; }

DrawingColors drawingColors(const QPalette& palette) {
  DrawingColors c;
  if (isDark(palette)) {
    c.background = palette.color(QPalette::Base);
    c.foreground = palette.color(QPalette::Text);
    c.grid = QColor(0x4a, 0x4d, 0x54);
    c.legend_background = QColor(0x2d, 0x2f, 0x33, 220);
    c.view_top = QColor(0x2a, 0x2e, 0x36);
    c.view_bottom = QColor(0x12, 0x16, 0x1d);
  } else {
    c.background = Qt::white;
    c.foreground = Qt::black;
    c.grid = QColor(200, 200, 200);
    c.legend_background = QColor(255, 255, 255, 210);
    c.view_top = QColor::fromRgbF(0.80f, 0.85f, 0.90f);
    c.view_bottom = QColor::fromRgbF(0.97f, 0.98f, 0.99f);
  }
  return c;
}

QColor seriesColor(int index, const QPalette& palette) {
  static const QColor colors[kSeriesColorCount] = {
      QColor(31, 119, 180), QColor(214, 39, 40),   QColor(44, 160, 44),  QColor(255, 127, 14),
      QColor(148, 103, 189), QColor(140, 86, 75),  QColor(227, 119, 194), QColor(23, 190, 207),
      QColor(127, 127, 127), QColor(188, 189, 34), QColor(0, 0, 0),       QColor(184, 134, 11)};
  const QColor c = colors[((index % kSeriesColorCount) + kSeriesColorCount) % kSeriesColorCount];
  if (!isDark(palette)) return c;
  // Lighter on a dark background; black (which no lightening lifts) becomes near-white.
  return c.value() < 40 ? QColor(230, 230, 230) : c.lighter(135);
}

}  // namespace maris::ui
