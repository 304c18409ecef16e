// Icons that follow the palette. The platform style's standard icons are drawn for a light
// window: black glyphs that vanish on the dark theme's grey. A themed icon asks the current style
// for its standard icon each time it is painted and, when the application palette is dark,
// inverts and lifts the lightness of every pixel (hue, saturation and alpha kept), so dark glyphs
// turn light and coloured ones keep their hue. Theme and style changes need no re-set of icons.
#pragma once

#include <QIcon>
#include <QStyle>

namespace maris::ui {

QIcon themedIcon(QStyle::StandardPixmap which);

// The picture in the dark palette's variant: HSL lightness l becomes 1 − l/2, so black glyphs turn white,
// mid-lightness colours become pastel and white highlights mid-grey (used by themedIcon).
QImage lightnessFlipped(const QImage& image);

}  // namespace maris::ui
