// The 3D view's "Colours" button: a drop-down form with the colour map, an automatic range
// (all frames' min … max) and a user's min and max. It only edits ColorSettings; SceneView applies
// them and remembers them per quantity. The min and max are typed and shown in the display unit the view gives (MPa
// where the settings, like the results, hold Pa).
#pragma once

#include <QToolButton>

#include "plots/display_units.hpp"
#include "view3d/color_maps.hpp"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;

namespace maris::ui {

class ColorMapControl : public QToolButton {
  Q_OBJECT
 public:
  explicit ColorMapControl(QWidget* parent = nullptr);

  // Shows `settings`; in automatic mode the range fields show the data's range [data_lo, data_hi]. The settings and
  // the data's range are SI; the fields show them in `unit` (shown = SI × unit.factor), and a range typed there is
  // turned back to SI.
  void showSettings(const ColorSettings& settings, double data_lo, double data_hi, const DisplayUnit& unit = {});
  const ColorSettings& settings() const { return settings_; }

  // The form's widgets, for tests that drive them as a user would.
  QComboBox* mapBox() const { return map_; }
  QCheckBox* automaticBox() const { return automatic_; }
  QCheckBox* perFrameBox() const { return per_frame_; }
  QLineEdit* minEdit() const { return min_; }
  QLineEdit* maxEdit() const { return max_; }
  QLabel* minLabel() const { return min_label_; }
  const DisplayUnit& unit() const { return unit_; }

 signals:
  void settingsChanged(const maris::ui::ColorSettings& settings);

 private:
  void onRangeEdited();
  void syncEnabled();

  // The field's value in SI: the shown value exactly while its text is the one shown, else the text's number.
  bool fieldValue(const QLineEdit* field, const QString& shown_text, double shown_si, double& si) const;

  ColorSettings settings_;
  DisplayUnit unit_;
  QString shown_min_, shown_max_;  // the texts showSettings wrote, for the SI values below
  double shown_min_si_ = 0.0, shown_max_si_ = 0.0;
  QComboBox* map_;
  QCheckBox* automatic_;
  QCheckBox* per_frame_;
  QLineEdit* min_;
  QLineEdit* max_;
  QLabel* problem_;
  QLabel* min_label_;
  QLabel* max_label_;
};

}  // namespace maris::ui
