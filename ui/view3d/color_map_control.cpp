#include "view3d/color_map_control.hpp"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QWidgetAction>

#include "plots/result_plot.hpp"

namespace maris::ui {

namespace {

QString limitText(double v) { return QString::number(v, 'g', 6); }

}  // namespace

ColorMapControl::ColorMapControl(QWidget* parent)
    : QToolButton(parent), map_(new QComboBox), automatic_(new QCheckBox(tr("Automatic"))),
      per_frame_(new QCheckBox(tr("Each frame its own range"))),
      min_(new QLineEdit), max_(new QLineEdit), problem_(new QLabel), min_label_(new QLabel(tr("Min"))),
      max_label_(new QLabel(tr("Max"))) {
  setText(tr("Colours"));
  setToolTip(tr("Colour map and colour-bar range of the coloured quantity"));
  setPopupMode(QToolButton::InstantPopup);
  map_->addItems(colorMapNames());
  map_->setObjectName(QStringLiteral("colorMap"));
  min_->setObjectName(QStringLiteral("colorMin"));
  max_->setObjectName(QStringLiteral("colorMax"));
  problem_->setStyleSheet(QStringLiteral("color: #d62728;"));
  problem_->hide();

  // The form lives in the button's menu, which stays open while its fields are edited.
  auto* form_host = new QWidget;
  auto* form = new QFormLayout(form_host);
  form->addRow(tr("Map"), map_);
  form->addRow(tr("Range"), automatic_);
  form->addRow(QString(), per_frame_);
  per_frame_->setObjectName(QStringLiteral("colorPerFrame"));
  per_frame_->setToolTip(tr("Automatic range of the frame shown (else of all frames of the run)"));
  form->addRow(min_label_, min_);
  form->addRow(max_label_, max_);
  form->addRow(problem_);
  auto* menu = new QMenu(this);
  auto* action = new QWidgetAction(menu);
  action->setDefaultWidget(form_host);
  menu->addAction(action);
  setMenu(menu);

  connect(map_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index < 0 || static_cast<ColorMap>(index) == settings_.map) return;
    settings_.map = static_cast<ColorMap>(index);
    emit settingsChanged(settings_);
  });
  connect(automatic_, &QCheckBox::toggled, this, [this](bool on) {
    syncEnabled();
    if (on == settings_.automatic) return;
    if (on) {
      settings_.automatic = true;
      problem_->hide();
      emit settingsChanged(settings_);
    } else {
      onRangeEdited();  // the fields hold the data's range: a fixed range starts from it
    }
  });
  connect(per_frame_, &QCheckBox::toggled, this, [this](bool on) {
    if (on == settings_.per_frame) return;
    settings_.per_frame = on;
    emit settingsChanged(settings_);
  });
  connect(min_, &QLineEdit::editingFinished, this, &ColorMapControl::onRangeEdited);
  connect(max_, &QLineEdit::editingFinished, this, &ColorMapControl::onRangeEdited);
  syncEnabled();
}

void ColorMapControl::showSettings(const ColorSettings& settings, double data_lo, double data_hi,
                                   const DisplayUnit& unit) {
  settings_ = settings;
  unit_ = unit.unit.empty() ? DisplayUnit{} : unit;
  min_label_->setText(axisLabel(tr("Min").toStdString(), unit_.unit));
  max_label_->setText(axisLabel(tr("Max").toStdString(), unit_.unit));
  const QSignalBlocker b1(map_), b2(automatic_), b3(per_frame_);
  map_->setCurrentIndex(static_cast<int>(settings.map));
  automatic_->setChecked(settings.automatic);
  per_frame_->setChecked(settings.per_frame);
  shown_min_si_ = settings.automatic ? data_lo : settings.min;
  shown_max_si_ = settings.automatic ? data_hi : settings.max;
  shown_min_ = limitText(shown_min_si_ * unit_.factor);
  shown_max_ = limitText(shown_max_si_ * unit_.factor);
  min_->setText(shown_min_);
  max_->setText(shown_max_);
  problem_->hide();
  syncEnabled();
}

void ColorMapControl::onRangeEdited() {
  if (automatic_->isChecked()) return;
  double lo = 0.0, hi = 0.0;
  const bool ok_lo = fieldValue(min_, shown_min_, shown_min_si_, lo);
  const bool ok_hi = fieldValue(max_, shown_max_, shown_max_si_, hi);
  QString problem;
  if (!ok_lo)
    problem = tr("Min must be a number");
  else if (!ok_hi)
    problem = tr("Max must be a number");
  else if (!(hi > lo))
    problem = tr("Max must be greater than min");
  problem_->setText(problem);
  problem_->setVisible(!problem.isEmpty());
  if (!problem.isEmpty()) return;
  ColorSettings next = settings_;
  next.automatic = false;
  next.min = lo;
  next.max = hi;
  if (next == settings_) return;
  settings_ = next;
  emit settingsChanged(settings_);
}

bool ColorMapControl::fieldValue(const QLineEdit* field, const QString& shown_text, double shown_si, double& si) const {
  const QString text = field->text().trimmed();
  if (text == shown_text) {
    si = shown_si;  // not retyped: no rounding through the 6 digits shown
    return true;
  }
  bool ok = false;
  const double shown = text.toDouble(&ok);
  si = shown / unit_.factor;
  return ok && std::isfinite(shown) && std::isfinite(si);
}

void ColorMapControl::syncEnabled() {
  min_->setEnabled(!automatic_->isChecked());
  max_->setEnabled(!automatic_->isChecked());
  per_frame_->setEnabled(automatic_->isChecked());
}

}  // namespace maris::ui
