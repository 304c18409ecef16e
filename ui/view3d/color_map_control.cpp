#include "view3d/color_map_control.hpp"

#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QWidgetAction>

namespace maris::ui {

namespace {

QString number(double v) { return QString::number(v, 'g', 6); }

}  // namespace

ColorMapControl::ColorMapControl(QWidget* parent)
    : QToolButton(parent), map_(new QComboBox), automatic_(new QCheckBox(tr("Automatic"))),
      per_frame_(new QCheckBox(tr("Each frame its own range"))),
      min_(new QLineEdit), max_(new QLineEdit), problem_(new QLabel) {
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
  form->addRow(tr("Min"), min_);
  form->addRow(tr("Max"), max_);
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

void ColorMapControl::showSettings(const ColorSettings& settings, double data_lo, double data_hi) {
  settings_ = settings;
  const QSignalBlocker b1(map_), b2(automatic_), b3(per_frame_);
  map_->setCurrentIndex(static_cast<int>(settings.map));
  automatic_->setChecked(settings.automatic);
  per_frame_->setChecked(settings.per_frame);
  min_->setText(number(settings.automatic ? data_lo : settings.min));
  max_->setText(number(settings.automatic ? data_hi : settings.max));
  problem_->hide();
  syncEnabled();
}

void ColorMapControl::onRangeEdited() {
  if (automatic_->isChecked()) return;
  bool ok_lo = false, ok_hi = false;
  const double lo = min_->text().trimmed().toDouble(&ok_lo), hi = max_->text().trimmed().toDouble(&ok_hi);
  QString problem;
  if (!ok_lo || !std::isfinite(lo))
    problem = tr("Min must be a number");
  else if (!ok_hi || !std::isfinite(hi))
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

void ColorMapControl::syncEnabled() {
  min_->setEnabled(!automatic_->isChecked());
  max_->setEnabled(!automatic_->isChecked());
  per_frame_->setEnabled(automatic_->isChecked());
}

}  // namespace maris::ui
