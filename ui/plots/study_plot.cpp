#include "plots/study_plot.hpp"

#include <algorithm>
#include <cmath>

#include <qcustomplot.h>

#include "plots/result_plot.hpp"
#include "theme.hpp"

namespace maris::ui {

namespace {

// A fresh layout: the title row (if any) above one axis rect.
QCPAxisRect* resetLayout(QCustomPlot& plot, const QString& title) {
  plot.clearGraphs();
  plot.clearPlottables();
  plot.clearItems();
  plot.plotLayout()->clear();
  auto* rect = new QCPAxisRect(&plot);
  plot.plotLayout()->addElement(0, 0, rect);
  if (!title.isEmpty()) {
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, title));
  }
  return rect;
}

// Tick labels at the grid's values (cell centres at indices 0..n-1), thinned to about 12.
QSharedPointer<QCPAxisTickerText> valueTicker(const std::vector<double>& values) {
  QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
  const std::size_t step = std::max<std::size_t>(1, values.size() / 12);
  for (std::size_t i = 0; i < values.size(); i += step)
    ticker->addTick(static_cast<double>(i), QString::number(values[i], 'g', 4));
  return ticker;
}

}  // namespace

bool fillStudyPoints(QCustomPlot& plot, const StudyPoints& points) {
  if (points.x.empty() || points.x.size() != points.y.size()) return false;
  QCPAxisRect* rect = resetLayout(plot, points.title);
  QCPGraph* graph = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  const QColor color = seriesColor(0, plot.palette());
  graph->setPen(QPen(color, 1.6));
  graph->setLineStyle(points.line ? QCPGraph::lsLine : QCPGraph::lsNone);
  graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(color, 1.2), QBrush(color), 6));
  graph->setData(QVector<double>(points.x.begin(), points.x.end()), QVector<double>(points.y.begin(), points.y.end()),
                 true);
  rect->axis(QCPAxis::atBottom)->setLabel(points.x_label);
  rect->axis(QCPAxis::atLeft)->setLabel(points.y_label);
  plot.rescaleAxes();
  // A margin so points at the ends are not cut by the axes.
  for (QCPAxis* axis : {rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)}) {
    const QCPRange r = axis->range();
    const double pad = r.size() > 0 ? 0.04 * r.size() : std::max(1e-12, 0.05 * std::abs(r.center()));
    axis->setRange(r.lower - pad, r.upper + pad);
  }
  applyPlotColors(plot);
  return true;
}

bool fillStudyHeatMap(QCustomPlot& plot, const StudyHeatMap& map) {
  const std::size_t nx = map.x.size(), ny = map.y.size();
  if (nx == 0 || ny == 0 || map.z.size() != nx * ny) return false;
  if (std::none_of(map.z.begin(), map.z.end(), [](double z) { return std::isfinite(z); })) return false;
  QCPAxisRect* rect = resetLayout(plot, map.title);
  QCPAxis* x_axis = rect->axis(QCPAxis::atBottom);
  QCPAxis* y_axis = rect->axis(QCPAxis::atLeft);
  auto* color_map = new QCPColorMap(x_axis, y_axis);
  color_map->data()->setSize(static_cast<int>(nx), static_cast<int>(ny));
  color_map->data()->setRange(QCPRange(0, std::max<double>(1, static_cast<double>(nx - 1))),
                              QCPRange(0, std::max<double>(1, static_cast<double>(ny - 1))));
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix)
      color_map->data()->setCell(static_cast<int>(ix), static_cast<int>(iy), map.z[iy * nx + ix]);
  QCPColorGradient gradient(QCPColorGradient::gpThermal);
  gradient.setNanHandling(QCPColorGradient::nhTransparent);
  color_map->setGradient(gradient);
  color_map->setInterpolate(false);
  auto* scale = new QCPColorScale(&plot);
  plot.plotLayout()->addElement(plot.plotLayout()->rowCount() - 1, 1, scale);
  scale->setType(QCPAxis::atRight);
  scale->axis()->setLabel(map.z_label);
  color_map->setColorScale(scale);  // before the range: the map takes the scale's range when joined to it
  color_map->rescaleDataRange(true);
  auto* group = new QCPMarginGroup(&plot);
  rect->setMarginGroup(QCP::msBottom | QCP::msTop, group);
  scale->setMarginGroup(QCP::msBottom | QCP::msTop, group);
  x_axis->setTicker(valueTicker(map.x));
  y_axis->setTicker(valueTicker(map.y));
  x_axis->setLabel(map.x_label);
  y_axis->setLabel(map.y_label);
  x_axis->setRange(-0.5, static_cast<double>(nx) - 0.5);
  y_axis->setRange(-0.5, static_cast<double>(ny) - 0.5);
  applyPlotColors(plot);
  const DrawingColors c = drawingColors(plot.palette());
  scale->axis()->setLabelColor(c.foreground);
  scale->axis()->setTickLabelColor(c.foreground);
  scale->axis()->setBasePen(QPen(c.foreground, 1));
  return true;
}

bool saveStudyPointsImage(const StudyPoints& points, const QString& file, int width_px, int height_px) {
  QCustomPlot plot;
  plot.resize(width_px, height_px);
  return fillStudyPoints(plot, points) && savePlotWidget(plot, file, width_px, height_px);
}

bool saveStudyHeatMapImage(const StudyHeatMap& map, const QString& file, int width_px, int height_px) {
  QCustomPlot plot;
  plot.resize(width_px, height_px);
  return fillStudyHeatMap(plot, map) && savePlotWidget(plot, file, width_px, height_px);
}

}  // namespace maris::ui
