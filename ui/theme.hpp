// Light and dark palettes for the whole application. The widgets follow Qt's palette; the plots
// (QCustomPlot) and the 3D view (VTK) draw their own backgrounds and text, so they read the
// palette through these helpers and redraw when it changes (QEvent::PaletteChange).
#pragma once

#include <QColor>
#include <QPalette>
#include <QString>

namespace maris::ui {

enum class Theme { System, Light, Dark };

QString themeKey(Theme theme);                 // "system", "light", "dark" (the QSettings value)
Theme themeFromKey(const QString& key);        // unknown keys give Theme::System
// Sets the application's style and palette: Fusion with a light or dark palette, or the
// platform's own style and palette for System. Needs a QApplication.
void applyTheme(Theme theme);

// True when the palette's window colour is dark (text is then light).
bool isDark(const QPalette& palette);

// Colours for things Qt does not paint: plot backgrounds, axes, grids, 3D backgrounds.
struct DrawingColors {
  QColor background;        // plot area and margins
  QColor foreground;        // axes, tick labels, titles, legend text
  QColor grid;              // major grid lines
  QColor legend_background; // legend box (slightly translucent)
  QColor view_top;          // 3D view background gradient, top
  QColor view_bottom;       // 3D view background gradient, bottom
};
DrawingColors drawingColors(const QPalette& palette);

// Qualitative series colours that stay apart: Tableau 10 (blue, red, green, orange, purple, brown,
// pink, cyan first, then grey and olive), black and dark gold; index k gets colour k mod 12. On a
// dark palette they are lightened to keep their contrast. The plot tabs (runs or columns, then
// reference markers) and the benchmarks' work-precision plots use this one list.
constexpr int kSeriesColorCount = 12;
QColor seriesColor(int index, const QPalette& palette);

}  // namespace maris::ui
