#include "themed_icon.hpp"

#include <QApplication>
#include <QIconEngine>
#include <QImage>
#include <QPainter>
#include <QPixmap>

#include "theme.hpp"

namespace maris::ui {

namespace {

class ThemedIconEngine : public QIconEngine {
 public:
  explicit ThemedIconEngine(QStyle::StandardPixmap which) : which_(which) {}

  QIconEngine* clone() const override { return new ThemedIconEngine(which_); }
  QString key() const override { return QStringLiteral("maris-themed"); }

  QSize actualSize(const QSize& size, QIcon::Mode mode, QIcon::State state) override {
    return standard().actualSize(size, mode, state);
  }

  QPixmap pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state) override {
    return scaledPixmap(size, mode, state, 1.0);
  }

  QPixmap scaledPixmap(const QSize& size, QIcon::Mode mode, QIcon::State state, qreal scale) override {
    QPixmap base = standard().pixmap(size, scale, mode, state);
    if (base.isNull() || !isDark(QApplication::palette())) return base;
    QPixmap flipped = QPixmap::fromImage(lightnessFlipped(base.toImage()));
    flipped.setDevicePixelRatio(base.devicePixelRatio());
    return flipped;
  }

  void paint(QPainter* painter, const QRect& rect, QIcon::Mode mode, QIcon::State state) override {
    const qreal scale = painter->device() ? painter->device()->devicePixelRatioF() : 1.0;
    painter->drawPixmap(rect, scaledPixmap(rect.size(), mode, state, scale));
  }

 private:
  // Asked each time: the style changes with the theme (System ↔ Fusion).
  QIcon standard() const { return QApplication::style()->standardIcon(which_); }

  QStyle::StandardPixmap which_;
};

}  // namespace

QImage lightnessFlipped(const QImage& image) {
  QImage out = image.convertToFormat(QImage::Format_ARGB32);
  for (int y = 0; y < out.height(); ++y) {
    auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
    for (int x = 0; x < out.width(); ++x) {
      const QColor c = QColor::fromRgba(line[x]);
      if (c.alpha() == 0) continue;
      const QColor light = QColor::fromHslF(c.hslHueF(), c.hslSaturationF(), 1.0f - 0.5f * c.lightnessF(), c.alphaF());
      line[x] = light.rgba();
    }
  }
  return out;
}

QIcon themedIcon(QStyle::StandardPixmap which) { return QIcon(new ThemedIconEngine(which)); }

}  // namespace maris::ui
