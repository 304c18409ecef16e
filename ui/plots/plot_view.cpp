#include "plots/plot_view.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <QEvent>
#include <QFileInfo>
#include <QLabel>
#include <QToolTip>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include "plots/plot_axes.hpp"
#include "plots/plot_export.hpp"
#include "plots/result_plot.hpp"

namespace maris::ui {

PlotView::PlotView(PlotSpec spec, QWidget* parent)
    : QWidget(parent), spec_(std::move(spec)), plot_(new QCustomPlot(this)), readout_(new QLabel(this)),
      empty_(new QLabel(tr("No data yet: run the scenario."), this)), log_x_(spec_.log_x), log_y_(spec_.log_y) {
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  // Antialiased curves of a few thousand points drawn as one polyline each: a replot costs 2–3 times
  // less than segment by segment (1.6–2.4 ms instead of 4.4–7.5 ms for riser_default's time
  // histories, 6000–12000 points, under Xvfb), which counts while live results stream in.
  plot_->setPlottingHint(QCP::phFastPolylines, true);
  plot_->setMinimumSize(200, 150);
  readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  readout_->setMinimumHeight(readout_->fontMetrics().height());
  empty_->setAlignment(Qt::AlignCenter);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(empty_);
  layout->addWidget(plot_, 1);
  layout->addWidget(readout_);
  plot_->hide();
  plot_->installEventFilter(this);
  connect(plot_, &QCustomPlot::mouseMove, this, &PlotView::onMouseMove);
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { resetZoom(); });
}

void PlotView::setSources(std::vector<Source> sources) {
  sources_ = std::move(sources);
  if (isVisible())
    redraw();
  else
    stale_ = true;
}

void PlotView::setReferences(std::vector<Table> references) {
  references_ = std::move(references);
  if (isVisible())
    redraw();
  else
    stale_ = true;
}

void PlotView::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  ensureDrawn();
}

bool PlotView::eventFilter(QObject* watched, QEvent* event) {
  // Which corner is free, and how many legend entries fit side by side under the axes, depend on the plot's size;
  // the plot is drawn (and its legend first placed) before it is shown and laid out at its size.
  if (watched == plot_ && event->type() == QEvent::Resize && has_data_ && !stale_) {
    placePlotLegend(*plot_);
    plot_->replot(QCustomPlot::rpQueuedReplot);
  }
  return QWidget::eventFilter(watched, event);
}

void PlotView::ensureDrawn() const {
  // Drawing is not a visible change of state: the data were set already.
  if (stale_) const_cast<PlotView*>(this)->redraw();
}

void PlotView::redraw() {
  stale_ = false;
  std::vector<PlotSource> drawn;
  for (const auto& s : sources_) drawn.push_back({s.label, s.results.get()});
  tracer_ = nullptr;
  // fillPlot makes new axes: a user's zoom is read from the old ones and put back on the new.
  const bool keep = user_range_ && has_data_ && plot_->axisRect();
  QCPRange kept_x, kept_y;
  if (keep) {
    kept_x = plot_->axisRect()->axis(QCPAxis::atBottom)->range();
    kept_y = plot_->axisRect()->axis(QCPAxis::atLeft)->range();
  }
  setting_range_ = true;
  has_data_ = !drawn.empty() && fillPlot(*plot_, drawn, spec_, references_);
  if (has_data_) {
    for (auto* axis : plot_->axisRect()->axes()) axis->grid()->setSubGridVisible(false);
    applyAxisScales();
    if (keep) {
      plot_->axisRect()->axis(QCPAxis::atBottom)->setRange(kept_x);
      plot_->axisRect()->axis(QCPAxis::atLeft)->setRange(kept_y);
      placePlotLegend(*plot_);
    }
    watchUserRange();
    tracer_ = new QCPItemTracer(plot_);
    tracer_->setStyle(QCPItemTracer::tsCircle);
    tracer_->setSize(8);
    tracer_->setPen(QPen(Qt::black));
    tracer_->setVisible(false);
    plot_->axisRect()->setRangeDrag(Qt::Horizontal | Qt::Vertical);
    plot_->axisRect()->setRangeZoom(Qt::Horizontal | Qt::Vertical);
  }
  setting_range_ = false;
  plot_->setVisible(has_data_);
  empty_->setVisible(!has_data_);
  readout_->clear();
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

void PlotView::watchUserRange() {
  // Wheel zoom, drag pan or a range set from outside: any range change that is not our own rescale.
  for (QCPAxis* axis : {plot_->axisRect()->axis(QCPAxis::atBottom), plot_->axisRect()->axis(QCPAxis::atLeft)})
    connect(axis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this] {
      if (!setting_range_) user_range_ = true;
    });
}

void PlotView::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  // Queued: this widget hears of a new palette before its child plot has it.
  if (event->type() == QEvent::PaletteChange)
    QMetaObject::invokeMethod(this, [this] {
      if (has_data_ || stale_) redraw();
      applyPlotColors(*plot_);
      plot_->replot(QCustomPlot::rpQueuedReplot);
    }, Qt::QueuedConnection);
}

int PlotView::pointCount() const {
  ensureDrawn();
  return has_data_ ? primaryPointCount(*plot_, spec_) : 0;
}

void PlotView::applyAxisScales() {
  QCPAxisRect* rect = plot_->axisRect();
  auto apply = [](QCPAxis* axis, bool log) {
    axis->setScaleType(log ? QCPAxis::stLogarithmic : QCPAxis::stLinear);
    if (log)
      axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    else
      axis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
  };
  apply(rect->axis(QCPAxis::atBottom), log_x_);
  apply(rect->axis(QCPAxis::atLeft), log_y_);
  apply(rect->axis(QCPAxis::atRight), log_y_);
  fitAxesToData(*plot_);
  placePlotLegend(*plot_);
}

// A new axis scale fits the data again (a linear range rarely makes sense on a log axis).
void PlotView::setLogX(bool on) {
  log_x_ = on;
  resetZoom();
}

void PlotView::setLogY(bool on) {
  log_y_ = on;
  resetZoom();
}

void PlotView::resetZoom() {
  user_range_ = false;
  setting_range_ = true;
  if (has_data_) applyAxisScales();
  setting_range_ = false;
  plot_->replot();
}

void PlotView::exportTo(const QString& file, int width_px, int height_px) {
  ensureDrawn();
  if (!has_data_ || sources_.empty()) throw std::runtime_error("the plot has no data to export");
  if (QFileInfo(file).suffix().toLower() == QLatin1String("csv")) {
    writePlotCsv(file.toStdString(), *sources_.front().results, spec_);
    return;
  }
  if (tracer_) tracer_->setVisible(false);
  if (!savePlotWidget(*plot_, file, width_px, height_px))
    throw std::runtime_error("could not write " + file.toStdString() + " (use .png, .pdf, .svg or .csv)");
}

QString PlotView::readout() const { return readout_->text(); }

void PlotView::onMouseMove(QMouseEvent* event) {
  if (!has_data_ || !tracer_) return;
  // A shortened legend entry shows its whole text as a tooltip.
  auto* entry = qobject_cast<QCPPlottableLegendItem*>(plot_->layoutElementAt(event->position()));
  if (entry && fullGraphName(*entry->plottable()) != entry->plottable()->name())
    QToolTip::showText(event->globalPosition().toPoint(), fullGraphName(*entry->plottable()), plot_);
  else
    QToolTip::hideText();
  // The nearest data point on screen over all graphs.
  QCPGraph* best = nullptr;
  double best_key = 0.0, best_value = 0.0, best_distance = std::numeric_limits<double>::infinity();
  const QPointF mouse = event->position();
  for (int i = 0; i < plot_->graphCount(); ++i) {
    QCPGraph* g = plot_->graph(i);
    if (g->dataCount() == 0) continue;
    const double key = g->keyAxis()->pixelToCoord(mouse.x());
    auto it = g->data()->findBegin(key);
    for (int step = 0; step < 2 && it != g->data()->constEnd(); ++step, ++it) {
      const double px = g->keyAxis()->coordToPixel(it->key);
      const double py = g->valueAxis()->coordToPixel(it->value);
      const double d = std::hypot(px - mouse.x(), py - mouse.y());
      if (d < best_distance) {
        best_distance = d;
        best = g;
        best_key = it->key;
        best_value = it->value;
      }
    }
  }
  const bool near = best && best_distance < 40.0;
  tracer_->setVisible(near);
  if (near) {
    tracer_->setGraph(best);
    tracer_->setGraphKey(best_key);
    readout_->setText(QStringLiteral("%1 = %2    %3 = %4")
                          .arg(best->keyAxis()->label())
                          .arg(best_key, 0, 'g', 6)
                          .arg(fullGraphName(*best))
                          .arg(best_value, 0, 'g', 6));
  }
  plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace maris::ui
