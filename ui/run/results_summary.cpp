#include "run/results_summary.hpp"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QColor>
#include <QDir>
#include <QFileDialog>
#include <QHeaderView>
#include <QLabel>
#include <QScrollArea>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

#include <stdexcept>

#include "core/scenario.hpp"
#include "document/scenario_document.hpp"
#include "plots/display_units.hpp"
#include "start_folder.hpp"

namespace maris::ui {

namespace {

// One column per scalar and one row of values: the engine's CSV layout (Table::toCsv).
Table scalarTable(const Results& results) {
  Table table;
  table.name = "scalars";
  for (const Scalar& s : results.scalars) table.add(s.name, s.unit, {s.value});
  return table;
}

}  // namespace

ResultsSummary::ResultsSummary(QWidget* parent)
    : QWidget(parent), copy_action_(new QAction(tr("&Copy"), this)),
      export_action_(new QAction(tr("&Export as CSV…"), this)), heading_(new QLabel(this)),
      table_(new QTableWidget(0, 4, this)), stats_(new QLabel(this)) {
  table_->setHorizontalHeaderLabels({tr("Quantity"), tr("Value"), tr("Unit"), tr("Meaning")});
  // Sized to the scalars once per run (warning rows span the table and must not widen column 0).
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setAlternatingRowColors(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  copy_action_->setShortcut(QKeySequence::Copy);
  copy_action_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  copy_action_->setToolTip(tr("Copy the selected quantities (or all) as tab-separated text"));
  connect(copy_action_, &QAction::triggered, this, &ResultsSummary::copyToClipboard);
  export_action_->setToolTip(tr("Write the quantities of this run to a CSV file (names row, units row, values)"));
  connect(export_action_, &QAction::triggered, this, &ResultsSummary::exportDialog);
  table_->addAction(copy_action_);
  table_->addAction(export_action_);
  table_->setContextMenuPolicy(Qt::ActionsContextMenu);
  stats_->setWordWrap(true);
  stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  stats_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  // The method line scrolls beyond three lines: a long one (the riser's automatic integrator explains its choice
  // in five) took the dock's height in a 768-pixel-high window, left the table one row and was cut off itself.
  auto* stats_area = new QScrollArea(this);
  stats_area->setWidget(stats_);
  stats_area->setWidgetResizable(true);
  stats_area->setFrameShape(QFrame::NoFrame);
  stats_area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  stats_area->setMaximumHeight(3 * stats_->fontMetrics().lineSpacing() + 2 * stats_->margin() + 2);
  stats_area->viewport()->setAutoFillBackground(false);
  stats_->setAutoFillBackground(false);
  // The header and at least three quantities stay in view.
  table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                           3 * table_->verticalHeader()->defaultSectionSize() + 2 * table_->frameWidth());
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(heading_);
  layout->addWidget(table_, 1);
  layout->addWidget(stats_area);
  clear();
}

void ResultsSummary::clear() {
  results_.reset();
  copy_action_->setEnabled(false);
  export_action_->setEnabled(false);
  heading_->setText(tr("No results yet."));
  table_->setRowCount(0);
  stats_->clear();
}

void ResultsSummary::showRun(const RunRecord& record, const Schema* schema) {
  if (!record.results) return clear();
  results_ = record.results;
  copy_action_->setEnabled(true);
  export_action_->setEnabled(true);
  const Results& r = *record.results;
  heading_->setText(tr("<b>%1</b> — %2").arg(record.label.toHtmlEscaped(),
                                             QString::fromStdString(record.scenario.name).toHtmlEscaped()));
  const int scalars = static_cast<int>(r.scalars.size());
  table_->clearContents();
  table_->clearSpans();
  table_->setRowCount(scalars + static_cast<int>(r.warnings.size()));
  for (int i = 0; i < static_cast<int>(r.scalars.size()); ++i) {
    const Scalar& s = r.scalars[i];
    auto* name = new QTableWidgetItem(QString::fromStdString(displayLabel(s)));
    name->setToolTip(QString::fromStdString(s.name));  // the key in summary.json and the CSV
    const DisplayUnit shown = displayUnit(s.unit);
    auto* value = new QTableWidgetItem(QString::number(s.value * shown.factor, 'g', 6));
    value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    table_->setItem(i, 0, name);
    table_->setItem(i, 1, value);
    table_->setItem(i, 2, new QTableWidgetItem(unitText(shown.unit)));
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
    text += tr(" · error estimate %1 %2").arg(st.error_estimate, 0, 'g', 3).arg(unitText(st.error_unit));
  stats_->setText(text);
  // Warnings follow the scalars as full-width rows, so the statistics line stays short.
  for (int i = 0; i < static_cast<int>(r.warnings.size()); ++i) {
    const QString warning = schema ? withFieldNames(r.warnings[i], *schema) : QString::fromStdString(r.warnings[i]);
    auto* item = new QTableWidgetItem(QStringLiteral("⚠ ") + warning);
    item->setForeground(QColor(0xd0, 0x80, 0x00));
    item->setToolTip(warning);
    table_->setItem(scalars + i, 0, item);
    table_->setSpan(scalars + i, 0, 1, 4);
  }
}

QString ResultsSummary::copyText() const {
  if (!results_) return {};
  const auto& scalars = results_->scalars;
  QSet<int> selected;
  for (const QModelIndex& index : table_->selectionModel()->selectedIndexes())
    if (index.row() < static_cast<int>(scalars.size())) selected.insert(index.row());
  QStringList lines{QStringList{tr("Quantity"), tr("Value"), tr("Unit"), tr("Meaning")}.join('\t')};
  auto cell = [](const std::string& text) { return QString::fromStdString(text).simplified(); };
  for (int i = 0; i < static_cast<int>(scalars.size()); ++i) {
    if (!selected.isEmpty() && !selected.contains(i)) continue;
    const Scalar& s = scalars[i];
    const DisplayUnit shown = displayUnit(s.unit);
    lines << QStringList{cell(displayLabel(s)), QString::number(s.value * shown.factor, 'g', QLocale::FloatingPointShortest),
                         unitText(shown.unit),
                         cell(s.description)}
                 .join('\t');
  }
  return lines.join('\n') + '\n';
}

void ResultsSummary::copyToClipboard() const {
  if (results_) QApplication::clipboard()->setText(copyText());
}

void ResultsSummary::exportCsv(const std::filesystem::path& file) const {
  if (!results_) throw std::runtime_error("no results to export");
  writeFileAtomic(file, scalarTable(*results_).toCsv());
}

void ResultsSummary::exportDialog() {
  if (!results_) return;
  const QString file = QFileDialog::getSaveFileName(this, tr("Export results as CSV"),
                                                    QDir(startFolder({})).filePath(QStringLiteral("scalars.csv")),
                                                    tr("CSV files (*.csv)"));
  if (file.isEmpty()) return;
  try {
    exportCsv(file.toStdString());
    emit message(tr("Results written to %1").arg(file));
  } catch (const std::exception& e) {
    emit message(tr("Could not write %1: %2").arg(file, QString::fromUtf8(e.what())));
  }
}

}  // namespace maris::ui
