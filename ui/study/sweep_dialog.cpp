#include "study/sweep_dialog.hpp"

#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "document/scenario_document.hpp"
#include "study/study_cell_text.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

constexpr int kMaxSweepValues = 10000;

// The nearest value inside `range` (an open end is approached by a hundredth of the span).
double clipToRange(double v, const Range& range) {
  const double span = std::isfinite(range.max - range.min) ? range.max - range.min : std::max(1.0, std::abs(v));
  if (std::isfinite(range.min) && (v < range.min || (range.min_open && v <= range.min)))
    v = range.min_open ? range.min + 0.01 * span : range.min;
  if (std::isfinite(range.max) && (v > range.max || (range.max_open && v >= range.max)))
    v = range.max_open ? range.max - 0.01 * span : range.max;
  return v;
}

}  // namespace

SweepRange proposedSweep(const ParamSpec& spec, const Json& current) {
  SweepRange r;
  r.path = spec.path;
  const double v = current.is_number() ? current.get<double>() : spec.default_value.is_number() ? spec.default_value.get<double>() : 0.0;
  r.from = clipToRange(v == 0.0 ? 0.0 : 0.5 * v, spec.range);
  r.to = clipToRange(v == 0.0 ? 1.0 : 1.5 * v, spec.range);
  if (spec.kind == ParamKind::Integer) {
    r.from = std::ceil(r.from);
    r.to = std::floor(r.to);
    r.count = static_cast<int>(std::clamp(r.to - r.from + 1.0, 2.0, 5.0));
  }
  return r;
}

SweepRange proposedSampleRange(const ParamSpec& spec, const Json& current) {
  // Around the design being studied, like a sweep: a field's allowed range is a validity limit (a riser's
  // length may be up to 100 km), far wider than the variations worth sampling, and its ends often break
  // the scene's rules between fields.
  return proposedSweep(spec, current);
}

QString sweepProblem(const ParamSpec& spec, const SweepRange& r) {
  const QString unit = unitText(spec.unit).isEmpty() ? QString() : QStringLiteral(" ") + unitText(spec.unit);
  const QString allowed = QString::fromStdString(spec.range.str());
  if (!std::isfinite(r.from)) return QObject::tr("from: must be a number");
  if (!std::isfinite(r.to)) return QObject::tr("to: must be a number");
  if (!spec.range.contains(r.from)) return QObject::tr("from: must be in %1%2").arg(allowed, unit);
  if (!spec.range.contains(r.to)) return QObject::tr("to: must be in %1%2").arg(allowed, unit);
  if (r.from == r.to) return QObject::tr("to: must differ from from");
  if (r.count < 2 || r.count > kMaxSweepValues) return QObject::tr("values: must be in [2, %1]").arg(kMaxSweepValues);
  if (r.log && (r.from <= 0.0 || r.to <= 0.0)) return QObject::tr("spacing: logarithmic needs from and to > 0");
  if (spec.kind == ParamKind::Integer) {
    if (r.from != std::floor(r.from) || r.to != std::floor(r.to)) return QObject::tr("from, to: must be whole numbers");
    if (r.count > std::abs(r.to - r.from) + 1)
      return QObject::tr("values: at most %1 whole numbers lie from %2 to %3")
          .arg(std::abs(r.to - r.from) + 1).arg(cellText(r.from), cellText(r.to));
  }
  return {};
}

SweepDialog::SweepDialog(const ParamSpec& spec, const SweepRange& proposed, QWidget* parent)
    : QDialog(parent), spec_(spec), from_(new QLineEdit(cellText(proposed.from), this)),
      to_(new QLineEdit(cellText(proposed.to), this)), count_(new QSpinBox(this)), spacing_(new QComboBox(this)),
      problem_(new QLabel(this)) {
  setWindowTitle(tr("Sweep %1").arg(QString::fromStdString(parameterLabel(spec))));
  const QString unit = unitText(spec.unit);
  auto* intro = new QLabel(tr("<b>%1</b> (%2)%3<br>allowed: %4 %5")
                               .arg(QString::fromStdString(parameterLabel(spec)), QString::fromStdString(spec.path),
                                    spec.description.empty() ? QString() : QStringLiteral(": ") + QString::fromStdString(spec.description).toHtmlEscaped(),
                                    QString::fromStdString(spec.range.str()), unit), this);
  intro->setWordWrap(true);
  count_->setRange(2, kMaxSweepValues);
  count_->setValue(proposed.count);
  spacing_->addItem(tr("linear"));
  spacing_->addItem(tr("logarithmic"));
  spacing_->setCurrentIndex(proposed.log ? 1 : 0);
  problem_->setStyleSheet(QStringLiteral("color: #d62728;"));
  problem_->setWordWrap(true);
  from_->setObjectName(QStringLiteral("sweepFrom"));
  to_->setObjectName(QStringLiteral("sweepTo"));

  auto* form = new QFormLayout;
  form->addRow(tr("From (%1)").arg(unit.isEmpty() ? QStringLiteral("-") : unit), from_);
  form->addRow(tr("To (%1)").arg(unit.isEmpty() ? QStringLiteral("-") : unit), to_);
  form->addRow(tr("Values"), count_);
  form->addRow(tr("Spacing"), spacing_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  sweep_ = buttons->addButton(tr("Run sweep"), QDialogButtonBox::AcceptRole);
  sweep_->setToolTip(tr("Replace the study's parameters by this one and run every value"));
  sweep_->setDefault(true);
  add_ = buttons->addButton(tr("Add to study"), QDialogButtonBox::AcceptRole);
  add_->setToolTip(tr("Add this parameter to the study's grid (Study panel) without running"));
  connect(sweep_, &QPushButton::clicked, this, [this] { finish(false); });
  connect(add_, &QPushButton::clicked, this, [this] { finish(true); });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro);
  layout->addLayout(form);
  layout->addWidget(problem_);
  layout->addWidget(buttons);
  connect(from_, &QLineEdit::textChanged, this, &SweepDialog::check);
  connect(to_, &QLineEdit::textChanged, this, &SweepDialog::check);
  connect(count_, &QSpinBox::valueChanged, this, &SweepDialog::check);
  connect(spacing_, &QComboBox::currentIndexChanged, this, &SweepDialog::check);
  check();
}

SweepRange SweepDialog::range() const {
  SweepRange r;
  r.path = spec_.path;
  bool ok_from = false, ok_to = false;
  r.from = from_->text().trimmed().toDouble(&ok_from);
  r.to = to_->text().trimmed().toDouble(&ok_to);
  if (!ok_from) r.from = std::nan("");
  if (!ok_to) r.to = std::nan("");
  r.count = count_->value();
  r.log = spacing_->currentIndex() == 1;
  return r;
}

void SweepDialog::finish(bool add_only) {
  if (case_check_) {
    const QString problem = case_check_(range(), add_only);
    if (!problem.isEmpty()) {
      problem_->setText(problem);
      problem_->setVisible(true);
      adjustSize();
      return;
    }
  }
  add_only_ = add_only;
  accept();
}

void SweepDialog::check() {
  const QString problem = sweepProblem(spec_, range());
  problem_->setText(problem);
  problem_->setVisible(!problem.isEmpty());
  sweep_->setEnabled(problem.isEmpty());
  add_->setEnabled(problem.isEmpty());
}

}  // namespace maris::ui
