#include "plots/result_plot.hpp"

#include <QFileInfo>
#include <QSvgGenerator>
#include <qcustomplot.h>

namespace maris::ui {

QString axisLabel(const std::string& name, const std::string& unit) {
  QString label = QString::fromStdString(name);
  label.replace('_', ' ');
  if (!unit.empty() && unit != "-") label += QStringLiteral(" [%1]").arg(QString::fromStdString(unit));
  return label;
}

namespace {

QVector<double> toQVector(const std::vector<double>& v) { return QVector<double>(v.begin(), v.end()); }

// A qualitative palette readable on light and dark backgrounds.
QColor seriesColor(int i) {
  static const QColor colors[] = {QColor(31, 119, 180), QColor(214, 39, 40),  QColor(44, 160, 44),
                                  QColor(255, 127, 14), QColor(148, 103, 189), QColor(140, 86, 75),
                                  QColor(227, 119, 194), QColor(23, 190, 207)};
  return colors[i % 8];
}

}  // namespace

bool fillPlot(QCustomPlot& plot, const Results& results, const PlotSpec& spec) {
  plot.clearGraphs();
  plot.clearPlottables();
  const Table* table = results.findTable(spec.table);
  if (!table) return false;
  const Column* x = table->find(spec.x);
  if (!x) return false;
  plot.plotLayout()->clear();
  auto* rect = new QCPAxisRect(&plot);
  plot.plotLayout()->addElement(0, 0, rect);
  if (!spec.title.empty()) {
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, QString::fromStdString(spec.title)));
  }
  QCPAxis* xAxis = rect->axis(QCPAxis::atBottom);
  QCPAxis* yAxis = rect->axis(QCPAxis::atLeft);
  xAxis->setLabel(axisLabel(x->name, x->unit));
  std::string y_unit;
  int series = 0;
  for (const auto& name : spec.y) {
    const Column* y = table->find(name);
    if (!y) return false;
    y_unit = y->unit;
    QCPGraph* g = plot.addGraph(xAxis, yAxis);
    g->setName(axisLabel(y->name, y->unit));
    g->setPen(QPen(seriesColor(series++), 1.6));
    g->setData(toQVector(x->values), toQVector(y->values), true);
  }
  if (spec.y.size() == 1)
    yAxis->setLabel(axisLabel(table->find(spec.y[0])->name, y_unit));
  else
    yAxis->setLabel(y_unit.empty() || y_unit == "-" ? QString() : QStringLiteral("[%1]").arg(QString::fromStdString(y_unit)));
  if (const Table* ref = results.findTable(spec.reference_table)) {
    const Column* rx = ref->find(spec.x);
    for (const auto& name : spec.reference_y) {
      const Column* ry = ref->find(name);
      if (!rx || !ry) continue;
      QCPGraph* g = plot.addGraph(xAxis, yAxis);
      g->setName(QString::fromStdString(ref->title.empty() ? ref->name : ref->title) + ": " + axisLabel(ry->name, ""));
      g->setLineStyle(QCPGraph::lsNone);
      g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, seriesColor(series++), 6));
      g->setData(toQVector(rx->values), toQVector(ry->values));
    }
  }
  if (spec.log_x) {
    xAxis->setScaleType(QCPAxis::stLogarithmic);
    xAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  }
  if (spec.log_y) {
    yAxis->setScaleType(QCPAxis::stLogarithmic);
    yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  }
  if (plot.graphCount() > 1) {
    auto* legend = new QCPLegend;
    rect->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
    legend->setLayer(QLatin1String("legend"));
    for (int i = 0; i < plot.graphCount(); ++i) plot.graph(i)->addToLegend(legend);
    legend->setBrush(QColor(255, 255, 255, 200));
  }
  plot.rescaleAxes();
  return true;
}

bool savePlotImage(const Results& results, const PlotSpec& spec, const QString& file, int width_px, int height_px) {
  QCustomPlot plot;
  plot.resize(width_px, height_px);
  if (!fillPlot(plot, results, spec)) return false;
  const QString suffix = QFileInfo(file).suffix().toLower();
  if (suffix == QLatin1String("pdf")) return plot.savePdf(file, width_px, height_px);
  if (suffix == QLatin1String("svg")) {
    QSvgGenerator generator;
    generator.setFileName(file);
    generator.setSize(QSize(width_px, height_px));
    generator.setViewBox(QRect(0, 0, width_px, height_px));
    QCPPainter painter;
    if (!painter.begin(&generator)) return false;
    plot.toPainter(&painter, width_px, height_px);
    return painter.end();
  }
  return plot.savePng(file, width_px, height_px);
}

}  // namespace maris::ui
