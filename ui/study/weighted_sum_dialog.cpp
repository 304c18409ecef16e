#include "study/weighted_sum_dialog.hpp"

#include <algorithm>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QScrollBar>
#include <QVBoxLayout>

namespace maris::ui {

WeightedSumDialog::WeightedSumDialog(const std::vector<std::string>& columns,
                                     const std::vector<std::pair<std::string, std::string>>& known,
                                     const WeightedSumChoice& current, QWidget* parent)
    : QDialog(parent), column_(new QComboBox(this)), results_(new QListWidget(this)), other_(new QLineEdit(this)),
      problem_(new QLabel(this)) {
  setWindowTitle(tr("Weighted sum"));
  setMinimumWidth(560);  // the results' labels and names, and the hint in the field, whole
  auto* intro = new QLabel(tr("A column of the table that is no parameter can hold each case's weight (a sea "
                              "state's probability, a number ≥ 0). The study then reports Σ weight · result of "
                              "each chosen scalar result over its cases, as <tt>maris-cli study collect</tt> "
                              "writes it into study.json."),
                           this);
  intro->setWordWrap(true);
  column_->setObjectName(QStringLiteral("weightColumn"));
  column_->addItem(tr("none (no weighted sum)"), QString());
  std::vector<std::string> all_columns = columns;
  if (!current.column.empty() && std::find(all_columns.begin(), all_columns.end(), current.column) == all_columns.end())
    all_columns.push_back(current.column);
  for (const std::string& c : all_columns) column_->addItem(QString::fromStdString(c), QString::fromStdString(c));
  column_->setCurrentIndex(std::max(0, column_->findData(QString::fromStdString(current.column))));
  if (all_columns.empty())
    column_->setToolTip(tr("Every column of the table varies a parameter: add a column of weights to the CSV file"));

  results_->setObjectName(QStringLiteral("weightedResults"));
  QStringList other;
  for (const auto& [name, label] : known) {
    auto* item = new QListWidgetItem(label == name ? QString::fromStdString(name)
                                                   : tr("%1 (%2)").arg(QString::fromStdString(label), QString::fromStdString(name)),
                                     results_);
    item->setData(Qt::UserRole, QString::fromStdString(name));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    const bool chosen = std::find(current.results.begin(), current.results.end(), name) != current.results.end();
    item->setCheckState(chosen ? Qt::Checked : Qt::Unchecked);
  }
  for (const std::string& name : current.results)
    if (std::none_of(known.begin(), known.end(), [&](const auto& k) { return k.first == name; }))
      other << QString::fromStdString(name);
  if (known.empty()) results_->hide();
  // As tall as its results, up to eight rows (a scene reports a dozen or more scalars: it scrolls then).
  if (results_->count() > 0)
    results_->setMaximumHeight(std::min(results_->count(), 8) * results_->sizeHintForRow(0) + 2 * results_->frameWidth() +
                               results_->horizontalScrollBar()->sizeHint().height());
  other_->setObjectName(QStringLiteral("otherWeightedResults"));
  other_->setText(other.join(QStringLiteral(", ")));
  other_->setPlaceholderText(known.empty() ? tr("names as in a run's summary.json, e.g. max_fatigue_damage_per_year")
                                           : tr("more results by name, comma-separated"));
  problem_->setWordWrap(true);
  problem_->setStyleSheet(QStringLiteral("color: #d62728"));

  auto* form = new QFormLayout;
  form->addRow(tr("Weight column"), column_);
  form->addRow(known.empty() ? tr("Results to sum") : tr("Results of the cases"), known.empty() ? static_cast<QWidget*>(other_) : results_);
  if (!known.empty()) form->addRow(tr("Other results"), other_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  ok_ = buttons->button(QDialogButtonBox::Ok);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addWidget(buttons);

  connect(column_, &QComboBox::currentIndexChanged, this, &WeightedSumDialog::check);
  connect(results_, &QListWidget::itemChanged, this, &WeightedSumDialog::check);
  connect(other_, &QLineEdit::textChanged, this, &WeightedSumDialog::check);
  check();
}

WeightedSumChoice WeightedSumDialog::choice() const {
  WeightedSumChoice c;
  c.column = column_->currentData().toString().toStdString();
  if (c.column.empty()) return c;
  auto add = [&c](const std::string& name) {
    if (!name.empty() && std::find(c.results.begin(), c.results.end(), name) == c.results.end()) c.results.push_back(name);
  };
  for (int i = 0; i < results_->count(); ++i)
    if (results_->item(i)->checkState() == Qt::Checked) add(results_->item(i)->data(Qt::UserRole).toString().toStdString());
  for (const QString& name : other_->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) add(name.trimmed().toStdString());
  return c;
}

QString WeightedSumDialog::problem() const {
  const WeightedSumChoice c = choice();
  if (!c.column.empty() && c.results.empty()) return tr("Choose or type at least one result to sum.");
  return {};
}

void WeightedSumDialog::check() {
  const QString why = problem();
  problem_->setText(why);
  ok_->setEnabled(why.isEmpty());
}

}  // namespace maris::ui
