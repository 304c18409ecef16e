#include "study/add_parameter_dialog.hpp"

#include <algorithm>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "document/scenario_document.hpp"
#include "plots/study_plot.hpp"
#include "study/study.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

bool isNumberKind(ParamKind kind) { return kind == ParamKind::Real || kind == ParamKind::Integer; }

// "Length L [m]": a field's or column's label for people (the schema's) with its SI unit.
QString labelWithUnit(const ParamSpec& spec) {
  const QString unit = unitText(spec.unit).isEmpty() ? QString() : QStringLiteral(" [%1]").arg(unitText(spec.unit));
  return QString::fromStdString(parameterLabel(spec)) + unit;
}

std::size_t rowCount(const Json& parameters, const std::string& table) {
  const Json* rows = findAtPath(parameters, table);
  return rows && rows->is_array() ? rows->size() : 0;
}

}  // namespace

AddParameterDialog::AddParameterDialog(const SceneDefinition& scene, const Json& parameters,
                                       std::vector<std::string> taken, QWidget* parent)
    : QDialog(parent), scene_(&scene), schema_(scene.schema), parameters_(parameters), taken_(std::move(taken)),
      field_choice_(new QRadioButton(tr("A field"), this)),
      cell_choice_(new QRadioButton(tr("A cell of a table"), this)), field_(new QComboBox(this)),
      table_(new QComboBox(this)), row_(new QSpinBox(this)), column_(new QComboBox(this)), summary_(new QLabel(this)),
      add_(nullptr) {
  setWindowTitle(tr("Add parameter"));
  field_->setObjectName(QStringLiteral("studyField"));
  table_->setObjectName(QStringLiteral("studyTable"));
  row_->setObjectName(QStringLiteral("studyRow"));
  column_->setObjectName(QStringLiteral("studyColumn"));
  for (const ParamSpec& spec : schema_.fields) {
    if (isNumberKind(spec.kind) && std::find(taken_.begin(), taken_.end(), spec.path) == taken_.end())
      field_->addItem(QStringLiteral("%1 (%2)").arg(labelWithUnit(spec), QString::fromStdString(spec.path)),
                      QString::fromStdString(spec.path));
    // A table whose base has rows and which has a number column: a study varies one of its cells.
    const bool numbers = std::any_of(spec.columns.begin(), spec.columns.end(),
                                     [](const ParamSpec& c) { return isNumberKind(c.kind); });
    if (spec.kind == ParamKind::Table && numbers && rowCount(parameters_, spec.path) > 0)
      table_->addItem(QString::fromStdString(spec.path), QString::fromStdString(spec.path));
  }
  field_choice_->setEnabled(field_->count() > 0);
  cell_choice_->setEnabled(table_->count() > 0);
  (field_->count() > 0 || table_->count() == 0 ? field_choice_ : cell_choice_)->setChecked(true);
  row_->setToolTip(tr("Rows are counted from 0, as in the study file's path TABLE[ROW].COLUMN"));
  summary_->setWordWrap(true);

  auto* form = new QFormLayout;
  form->addRow(field_choice_);
  form->addRow(tr("Field"), field_);
  form->addRow(cell_choice_);
  form->addRow(tr("Table"), table_);
  form->addRow(tr("Row (from 0)"), row_);
  form->addRow(tr("Column"), column_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  add_ = buttons->addButton(tr("Add…"), QDialogButtonBox::AcceptRole);
  add_->setDefault(true);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(summary_);
  layout->addWidget(buttons);

  connect(field_choice_, &QRadioButton::toggled, this, &AddParameterDialog::check);
  connect(field_, &QComboBox::currentIndexChanged, this, &AddParameterDialog::check);
  connect(table_, &QComboBox::currentIndexChanged, this, &AddParameterDialog::tableChosen);
  connect(row_, &QSpinBox::valueChanged, this, &AddParameterDialog::check);
  connect(column_, &QComboBox::currentIndexChanged, this, &AddParameterDialog::check);
  tableChosen();
}

void AddParameterDialog::tableChosen() {
  const std::string table = table_->currentData().toString().toStdString();
  const ParamSpec* spec = table.empty() ? nullptr : schema_.find(table);
  {
    const QSignalBlocker block_rows(row_), block_columns(column_);
    column_->clear();
    if (spec)
      for (const ParamSpec& c : spec->columns)
        if (isNumberKind(c.kind)) column_->addItem(labelWithUnit(c), QString::fromStdString(c.key()));
    row_->setRange(0, std::max(0, static_cast<int>(rowCount(parameters_, table)) - 1));
  }
  check();
}

std::string AddParameterDialog::path() const {
  std::string path;
  if (field_choice_->isChecked()) {
    path = field_->currentData().toString().toStdString();
  } else {
    const std::string table = table_->currentData().toString().toStdString();
    const std::string column = column_->currentData().toString().toStdString();
    if (!table.empty() && !column.empty()) path = study::tableCellPath(table, static_cast<std::size_t>(row_->value()), column);
  }
  return std::find(taken_.begin(), taken_.end(), path) == taken_.end() ? path : std::string();
}

bool AddParameterDialog::chooseField(const std::string& path) {
  const int index = field_->findData(QString::fromStdString(path));
  if (index < 0) return false;
  field_choice_->setChecked(true);
  field_->setCurrentIndex(index);
  return true;
}

bool AddParameterDialog::chooseCell(const std::string& table, int row, const std::string& column) {
  const int t = table_->findData(QString::fromStdString(table));
  if (t < 0) return false;
  cell_choice_->setChecked(true);
  table_->setCurrentIndex(t);
  const int c = column_->findData(QString::fromStdString(column));
  if (c < 0 || row < row_->minimum() || row > row_->maximum()) return false;
  column_->setCurrentIndex(c);
  row_->setValue(row);
  return path() == study::tableCellPath(table, static_cast<std::size_t>(row), column);
}

void AddParameterDialog::check() {
  const bool cell = cell_choice_->isChecked();
  field_->setEnabled(!cell);
  table_->setEnabled(cell);
  row_->setEnabled(cell);
  column_->setEnabled(cell);
  const std::string chosen = path();
  if (chosen.empty()) {
    summary_->setText(cell && !table_->currentData().isNull() ? tr("This cell is varied already.") : QString());
  } else {
    const Json* value = study::findParameterValue(parameters_, chosen);
    const auto spec = study::findStudyParameter(*scene_, parameters_, chosen);
    summary_->setText(tr("%1 (%2), now %3")
                          .arg(spec ? studyAxisLabel(parameterLabel(*spec), spec->unit) : QString::fromStdString(chosen),
                               QString::fromStdString(chosen),
                               value ? displayValue(*value) : tr("not set")));
  }
  add_->setEnabled(!chosen.empty());
}

}  // namespace maris::ui
