#include "study/latin_hypercube_dialog.hpp"

#include <cmath>

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include "document/scenario_document.hpp"
#include "study/study_cell_text.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

enum RangeColumn { kRangeParameter, kRangeFrom, kRangeTo, kRangeAllowed };
constexpr int kMaxSamples = 100000;  // the engine's limit of cases in one study (StudyLimits::kCases)

double cellNumber(const QTableWidget* table, int row, int column) {
  bool ok = false;
  const double v = table->item(row, column) ? table->item(row, column)->text().trimmed().toDouble(&ok) : 0.0;
  return ok ? v : std::nan("");
}

}  // namespace

LatinHypercubeDialog::LatinHypercubeDialog(const SceneDefinition& scene, const Scenario& scenario, QWidget* parent)
    : QDialog(parent), table_(new QTableWidget(this)), samples_(new QSpinBox(this)), seed_(new QSpinBox(this)),
      problem_(new QLabel(this)) {
  setWindowTitle(tr("New Latin hypercube study"));
  auto* intro = new QLabel(tr("Tick the parameters to sample and set each one's interval. Every parameter gets "
                              "exactly one sample in each of the equal intervals that the number of samples "
                              "divides it into; the same seed gives the same cases."), this);
  intro->setWordWrap(true);
  for (const ParamSpec& spec : scene.schema.fields)
    if (spec.kind == ParamKind::Real || spec.kind == ParamKind::Integer) specs_.push_back(spec);
  table_->setColumnCount(4);
  table_->setHorizontalHeaderLabels({tr("Parameter"), tr("From"), tr("To"), tr("Allowed")});
  table_->setRowCount(static_cast<int>(specs_.size()));
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(kRangeParameter, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  for (int row = 0; row < static_cast<int>(specs_.size()); ++row) {
    const ParamSpec& spec = specs_[row];
    const Json* value = findAtPath(scenario.parameters, spec.path);
    const SweepRange proposed = proposedSampleRange(spec, value ? *value : Json());
    const QString unit = unitText(spec.unit).isEmpty() ? QString() : QStringLiteral(" [%1]").arg(unitText(spec.unit));
    auto* name = new QTableWidgetItem(QString::fromStdString(parameterLabel(spec)) + unit);
    name->setFlags((name->flags() | Qt::ItemIsUserCheckable) & ~Qt::ItemIsEditable);
    name->setCheckState(Qt::Unchecked);
    name->setToolTip(QString::fromStdString(spec.path + (spec.description.empty() ? "" : ": " + spec.description)));
    table_->setItem(row, kRangeParameter, name);
    table_->setItem(row, kRangeFrom, new QTableWidgetItem(cellText(proposed.from)));
    table_->setItem(row, kRangeTo, new QTableWidgetItem(cellText(proposed.to)));
    auto* allowed = new QTableWidgetItem(QString::fromStdString(spec.range.str()));
    allowed->setFlags(allowed->flags() & ~Qt::ItemIsEditable);
    table_->setItem(row, kRangeAllowed, allowed);
  }
  table_->setMinimumSize(560, 260);
  samples_->setRange(2, kMaxSamples);
  samples_->setValue(20);
  seed_->setRange(0, 2147483647);
  seed_->setValue(1);
  problem_->setStyleSheet(QStringLiteral("color: #d62728;"));
  problem_->setWordWrap(true);

  auto* form = new QFormLayout;
  form->addRow(tr("Samples (cases)"), samples_);
  form->addRow(tr("Seed"), seed_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  create_ = buttons->addButton(tr("Create study"), QDialogButtonBox::AcceptRole);
  create_->setDefault(true);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addWidget(table_);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addWidget(buttons);
  connect(table_, &QTableWidget::itemChanged, this, &LatinHypercubeDialog::check);
  check();
}

bool LatinHypercubeDialog::choose(const std::string& path, double from, double to) {
  for (int row = 0; row < static_cast<int>(specs_.size()); ++row) {
    if (specs_[row].path != path) continue;
    table_->item(row, kRangeFrom)->setText(cellText(from));
    table_->item(row, kRangeTo)->setText(cellText(to));
    table_->item(row, kRangeParameter)->setCheckState(Qt::Checked);
    return true;
  }
  return false;
}

LatinHypercubeDesign LatinHypercubeDialog::design() const {
  LatinHypercubeDesign d;
  for (int row = 0; row < static_cast<int>(specs_.size()); ++row) {
    if (table_->item(row, kRangeParameter)->checkState() != Qt::Checked) continue;
    SweepRange r;
    r.path = specs_[row].path;
    r.from = cellNumber(table_, row, kRangeFrom);
    r.to = cellNumber(table_, row, kRangeTo);
    d.ranges.push_back(r);
  }
  d.samples = samples_->value();
  d.seed = static_cast<std::uint64_t>(seed_->value());
  return d;
}

QString LatinHypercubeDialog::problem() const {
  const LatinHypercubeDesign d = design();
  if (d.ranges.empty()) return tr("Tick at least one parameter to sample.");
  for (int row = 0; row < static_cast<int>(specs_.size()); ++row) {
    if (table_->item(row, kRangeParameter)->checkState() != Qt::Checked) continue;
    SweepRange r{specs_[row].path, cellNumber(table_, row, kRangeFrom), cellNumber(table_, row, kRangeTo), 2, false};
    QString why = sweepProblem(specs_[row], r);
    if (why.isEmpty() && !(r.from < r.to)) why = tr("from: must be below to");
    if (!why.isEmpty()) return QStringLiteral("%1: %2").arg(QString::fromStdString(parameterLabel(specs_[row])), why);
  }
  return {};
}

void LatinHypercubeDialog::check() {
  const QString why = problem();
  problem_->setText(why);
  problem_->setVisible(!why.isEmpty());
  create_->setEnabled(why.isEmpty());
}

}  // namespace maris::ui
