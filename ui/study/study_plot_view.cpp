#include "study/study_plot_view.hpp"

#include <cmath>

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include "plots/display_units.hpp"
#include "plots/result_plot.hpp"
#include "study/study_session.hpp"

namespace maris::ui {

StudyPlotView::StudyPlotView(QWidget* parent)
    : QWidget(parent), result_(new QComboBox(this)), against_(new QComboBox(this)), kind_(new QComboBox(this)),
      plot_(new QCustomPlot(this)), readout_(new QLabel(this)) {
  result_->setObjectName(QStringLiteral("studyResult"));
  against_->setObjectName(QStringLiteral("studyAgainst"));
  kind_->setObjectName(QStringLiteral("studyPlotKind"));
  result_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  result_->setMinimumContentsLength(14);
  against_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  against_->setMinimumContentsLength(10);
  kind_->addItem(tr("Lines"));
  kind_->addItem(tr("Heat map"));
  plot_->setMinimumSize(240, 180);
  plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  readout_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  readout_->setText(tr("Run the study; then click a point to open its case."));
  auto* choices = new QHBoxLayout;
  choices->addWidget(new QLabel(tr("Result"), this));
  choices->addWidget(result_, 2);
  choices->addWidget(new QLabel(tr("against"), this));
  choices->addWidget(against_, 1);
  choices->addWidget(kind_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(choices);
  layout->addWidget(plot_, 1);
  layout->addWidget(readout_);
  for (QComboBox* box : {result_, against_, kind_})
    connect(box, &QComboBox::currentIndexChanged, this, [this] {
      if (!filling_) redraw();
    });
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* e) { onMouseMove(e->position()); });
  connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) onMousePress(e->position());
  });
  connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] {
    plot_->rescaleAxes();
    plot_->replot();
  });
}

void StudyPlotView::setSession(const StudySession* session) {
  session_ = session;
  refresh();
}

void StudyPlotView::refresh() {
  filling_ = true;
  const QString result = result_->currentData().toString();
  const QString against = against_->currentData().toString();
  result_->clear();
  against_->clear();
  if (session_ && session_->isDefined() && session_->caseCount() > 0) {
    for (const std::string& name : session_->resultNames()) {
      result_->addItem(QString::fromStdString(session_->resultLabel(name)), QString::fromStdString(name));
    }
    const StudyPlotData sample = session_->plotData({});
    for (const auto& p : sample.parameters)
      against_->addItem(studyAxisLabel(p), QString::fromStdString(p.name));
  }
  if (const int r = result_->findData(result); r >= 0) result_->setCurrentIndex(r);
  if (const int a = against_->findData(against); a >= 0) against_->setCurrentIndex(a);
  filling_ = false;
  redraw();
}

void StudyPlotView::redraw() {
  drawn_ = DrawnStudyPlot{};
  has_data_ = false;
  data_ = StudyPlotData{};
  const int x = against_->currentIndex();
  if (session_ && session_->isDefined() && result_->currentIndex() >= 0 && x >= 0) {
    data_ = session_->plotData(result_->currentData().toString().toStdString());
    // A heat map needs exactly two parameters on a full grid; otherwise lines.
    const bool heat_possible = data_.parameters.size() == 2 && isFullGrid(data_, 0, 1);
    {
      const QSignalBlocker block(kind_);
      if (!heat_possible) kind_->setCurrentIndex(0);
      kind_->setEnabled(heat_possible);
    }
    const StudyPlotKind kind = kind_->currentIndex() == 1 ? StudyPlotKind::HeatMap : StudyPlotKind::Lines;
    has_data_ = fillStudyPlot(*plot_, data_, x, kind, &drawn_);
  }
  if (!has_data_) {
    plot_->clearPlottables();
    plot_->clearItems();
  }
  readout_->setText(has_data_ ? tr("Click a point (or a cell) to open its case.")
                              : tr("Run the study; then click a point to open its case."));
  applyPlotColors(*plot_);
  plot_->replot();
}

void StudyPlotView::onMouseMove(const QPointF& pixel) {
  if (!has_data_ || !session_) return;
  const int c = studyCaseAt(*plot_, drawn_, pixel);
  if (c < 0) {
    readout_->setText(tr("Click a point (or a cell) to open its case."));
    return;
  }
  const DisplayUnit shown = displayUnit(data_.result_unit);
  const QString unit = unitText(shown.unit).isEmpty() ? QString() : QStringLiteral(" ") + unitText(shown.unit);
  const std::string label = data_.result_label.empty() ? readableName(data_.result_name) : data_.result_label;
  readout_->setText(tr("case %1 (%2): %3 = %4%5 — click to open")
                        .arg(session_->caseId(c), session_->caseLabel(c), QString::fromStdString(label))
                        .arg(data_.result[c] * shown.factor, 0, 'g', 8)
                        .arg(unit));
}

void StudyPlotView::onMousePress(const QPointF& pixel) {
  if (!has_data_) return;
  if (const int c = studyCaseAt(*plot_, drawn_, pixel); c >= 0) emit caseClicked(c);
}

bool StudyPlotView::exportTo(const QString& file, int width_px, int height_px) {
  if (!has_data_) return false;
  return savePlotWidget(*plot_, file, width_px, height_px);
}

void StudyPlotView::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::PaletteChange && has_data_) redraw();
}

}  // namespace maris::ui
