#include "run/results_summary.hpp"

#include <QColor>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace maris::ui {

ResultsSummary::ResultsSummary(QWidget* parent)
    : QWidget(parent), heading_(new QLabel(this)), table_(new QTableWidget(0, 4, this)), stats_(new QLabel(this)) {
  table_->setHorizontalHeaderLabels({tr("Quantity"), tr("Value"), tr("Unit"), tr("Meaning")});
  // Sized to the scalars once per run (warning rows span the table and must not widen column 0).
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setAlternatingRowColors(true);
  stats_->setWordWrap(true);
  stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(heading_);
  layout->addWidget(table_, 1);
  layout->addWidget(stats_);
  clear();
}

void ResultsSummary::clear() {
  heading_->setText(tr("No results yet."));
  table_->setRowCount(0);
  stats_->clear();
}

void ResultsSummary::showRun(const RunRecord& record) {
  if (!record.results) return clear();
  const Results& r = *record.results;
  heading_->setText(tr("<b>%1</b> — %2").arg(record.label.toHtmlEscaped(),
                                             QString::fromStdString(record.scenario.name).toHtmlEscaped()));
  const int scalars = static_cast<int>(r.scalars.size());
  table_->clearContents();
  table_->clearSpans();
  table_->setRowCount(scalars + static_cast<int>(r.warnings.size()));
  for (int i = 0; i < static_cast<int>(r.scalars.size()); ++i) {
    const Scalar& s = r.scalars[i];
    QString name = QString::fromStdString(s.name);
    name.replace('_', ' ');
    auto* value = new QTableWidgetItem(QString::number(s.value, 'g', 6));
    value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    table_->setItem(i, 0, new QTableWidgetItem(name));
    table_->setItem(i, 1, value);
    table_->setItem(i, 2, new QTableWidgetItem(QString::fromStdString(s.unit)));
    table_->setItem(i, 3, new QTableWidgetItem(QString::fromStdString(s.description)));
  }
  table_->resizeColumnsToContents();
  const SolverStats& st = r.stats;
  QString text = tr("Method: %1 · steps %2 (rejected %3) · rhs evaluations %4 · wall time %5 s")
                     .arg(st.method.empty() ? QStringLiteral("-") : QString::fromStdString(st.method))
                     .arg(st.steps)
                     .arg(st.rejected_steps)
                     .arg(st.rhs_evaluations)
                     .arg(st.wall_time_s, 0, 'g', 3);
  if (st.error_estimate > 0.0)
    text += tr(" · error estimate %1 %2").arg(st.error_estimate, 0, 'g', 3).arg(QString::fromStdString(st.error_unit));
  stats_->setText(text);
  // Warnings follow the scalars as full-width rows, so the statistics line stays short.
  for (int i = 0; i < static_cast<int>(r.warnings.size()); ++i) {
    auto* item = new QTableWidgetItem(QStringLiteral("⚠ ") + QString::fromStdString(r.warnings[i]));
    item->setForeground(QColor(0xd0, 0x80, 0x00));
    item->setToolTip(QString::fromStdString(r.warnings[i]));
    table_->setItem(scalars + i, 0, item);
    table_->setSpan(scalars + i, 0, 1, 4);
  }
}

}  // namespace maris::ui
