#include "editor/table_editor.hpp"

#include <algorithm>
#include <set>

#include <QHBoxLayout>
#include <QHeaderView>
#include <QMenu>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include "editor/field_text.hpp"
#include "plots/result_plot.hpp"

namespace maris::ui {

TableEditor::TableEditor(const ParamSpec& spec, QWidget* parent)
    : QWidget(parent), spec_(spec), grid_(new QTableWidget(this)),
      add_(new QPushButton(tr("Add row"), this)), remove_(new QPushButton(tr("Remove row"), this)) {
  grid_->setColumnCount(static_cast<int>(spec_.columns.size()));
  QStringList headers;
  for (int c = 0; c < static_cast<int>(spec_.columns.size()); ++c) {
    const ParamSpec& column = spec_.columns[c];
    std::string key = column.path;
    std::replace(key.begin(), key.end(), '_', ' ');
    headers << axisLabel(key, column.unit);
  }
  grid_->setHorizontalHeaderLabels(headers);
  for (int c = 0; c < static_cast<int>(spec_.columns.size()); ++c)
    grid_->horizontalHeaderItem(c)->setToolTip(fieldTooltip(spec_.columns[c]));
  grid_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  grid_->verticalHeader()->setDefaultSectionSize(grid_->fontMetrics().height() + 8);
  grid_->setMinimumHeight(grid_->fontMetrics().height() * 7);
  grid_->setSelectionBehavior(QAbstractItemView::SelectRows);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(add_);
  buttons->addWidget(remove_);
  buttons->addStretch();
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(grid_);
  layout->addLayout(buttons);

  grid_->setContextMenuPolicy(Qt::CustomContextMenu);
  connect(grid_, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
    const QModelIndex index = grid_->indexAt(at);
    QMenu* menu = index.isValid() ? cellMenu(index.row(), index.column(), this) : nullptr;
    if (!menu) return;
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->popup(grid_->viewport()->mapToGlobal(at));
  });
  connect(grid_, &QTableWidget::cellChanged, this, &TableEditor::onCellChanged);
  connect(add_, &QPushButton::clicked, this, &TableEditor::addRow);
  connect(remove_, &QPushButton::clicked, this, &TableEditor::removeRows);
}

QMenu* TableEditor::cellMenu(int row, int column, QWidget* parent) {
  if (row < 0 || row >= grid_->rowCount() || column < 0 || column >= static_cast<int>(spec_.columns.size())) return nullptr;
  const ParamSpec& spec = spec_.columns[column];
  if (spec.kind != ParamKind::Real && spec.kind != ParamKind::Integer) return nullptr;
  auto* menu = new QMenu(parent);
  QAction* sweep = menu->addAction(tr("Sweep this cell…"));
  sweep->setObjectName(QStringLiteral("sweepCellAction"));
  connect(sweep, &QAction::triggered, this,
          [this, row, key = QString::fromStdString(spec.key())] { emit sweepRequested(row, key); });
  return menu;
}

void TableEditor::setValue(const Json& rows) {
  rows_ = rows.is_array() ? rows : Json::array();
  const QSignalBlocker blocker(grid_);
  grid_->setRowCount(static_cast<int>(rows_.size()));
  for (int r = 0; r < static_cast<int>(rows_.size()); ++r) {
    for (int c = 0; c < static_cast<int>(spec_.columns.size()); ++c) {
      const ParamSpec& column = spec_.columns[c];
      const Json* cell = rows_[r].is_object() && rows_[r].contains(column.path) ? &rows_[r][column.path] : nullptr;
      auto* item = new QTableWidgetItem(cell ? fieldText(*cell, column.kind) : QString());
      item->setToolTip(fieldTooltip(column));
      grid_->setItem(r, c, item);
    }
  }
  remove_->setEnabled(!rows_.empty());
}

void TableEditor::markErrors(const std::vector<FieldError>& errors, const std::string& full_path) {
  const QSignalBlocker blocker(grid_);
  for (int r = 0; r < grid_->rowCount(); ++r) {
    for (int c = 0; c < grid_->columnCount(); ++c) {
      QTableWidgetItem* item = grid_->item(r, c);
      if (!item) continue;
      const std::string cell_path = full_path + "[" + std::to_string(r) + "]." + spec_.columns[c].path;
      QString message;
      for (const auto& e : errors)
        if (e.path == cell_path) message = QString::fromStdString(e.message);
      item->setBackground(message.isEmpty() ? QBrush() : QBrush(QColor(214, 39, 40, 90)));
      item->setToolTip(message.isEmpty() ? fieldTooltip(spec_.columns[c]) : message);
    }
  }
}

void TableEditor::onCellChanged(int row, int column) {
  if (row < 0 || row >= static_cast<int>(rows_.size())) return;
  const ParamSpec& spec = spec_.columns[column];
  Json rows = rows_;
  if (!rows[row].is_object()) rows[row] = Json::object();
  rows[row][spec.path] = parseFieldText(grid_->item(row, column)->text(), spec.kind);
  emit edited(rows);
}

void TableEditor::addRow() {
  // A new row copies the last one (or the column defaults), so it starts out valid.
  Json rows = rows_;
  Json row = Json::object();
  if (!rows.empty()) {
    row = rows.back();
  } else {
    for (const auto& column : spec_.columns) row[column.path] = column.default_value;
  }
  rows.push_back(row);
  emit edited(rows);
}

void TableEditor::removeRows() {
  std::set<int> selected;
  for (const auto* item : grid_->selectedItems()) selected.insert(item->row());
  if (selected.empty() && !rows_.empty()) selected.insert(static_cast<int>(rows_.size()) - 1);
  Json rows = Json::array();
  for (int r = 0; r < static_cast<int>(rows_.size()); ++r)
    if (!selected.count(r)) rows.push_back(rows_[r]);
  emit edited(rows);
}

}  // namespace maris::ui
