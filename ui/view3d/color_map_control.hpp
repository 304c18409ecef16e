// The 3D view's "Colours" button: a drop-down form with the colour map, an automatic range
// (all frames' min … max) and a user's min and max. It only edits ColorSettings; SceneView applies
// them and remembers them per quantity.
#pragma once

#include <QToolButton>

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

  // Shows `settings`; in automatic mode the range fields show the data's range [data_lo, data_hi].
  void showSettings(const ColorSettings& settings, double data_lo, double data_hi);
  const ColorSettings& settings() const { return settings_; }

  // The form's widgets, for tests that drive them as a user would.
  QComboBox* mapBox() const { return map_; }
  QCheckBox* automaticBox() const { return automatic_; }
  QCheckBox* perFrameBox() const { return per_frame_; }
  QLineEdit* minEdit() const { return min_; }
  QLineEdit* maxEdit() const { return max_; }

 signals:
  void settingsChanged(const maris::ui::ColorSettings& settings);

 private:
  void onRangeEdited();
  void syncEnabled();

  ColorSettings settings_;
  QComboBox* map_;
  QCheckBox* automatic_;
  QCheckBox* per_frame_;
  QLineEdit* min_;
  QLineEdit* max_;
  QLabel* problem_;
};

}  // namespace maris::ui
