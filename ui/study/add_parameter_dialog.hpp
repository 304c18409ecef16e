// "Add parameter…" of the Study dock: what to vary, either a number field of the scene or one cell of a
// table field (its table, row and number column). The answer is the path a study file names it by,
// "geometry.length" or "sections[1].outer_diameter"; the study panel then asks for its range (SweepDialog).
#pragma once

#include <string>
#include <vector>

#include <QDialog>

#include "core/scene.hpp"

class QComboBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;

namespace maris::ui {

class AddParameterDialog : public QDialog {
  Q_OBJECT
 public:
  // The fields and tables of `scene`; the rows a cell may be in are those of `parameters` (the study's base);
  // the paths in `taken` (already varied) are not offered.
  AddParameterDialog(const SceneDefinition& scene, const Json& parameters, std::vector<std::string> taken,
                     QWidget* parent = nullptr);

  // The chosen parameter's path, or "" when the choice cannot be added.
  std::string path() const;
  // Chooses the number field `path`, or the cell in row `row` (from 0) and `column` of `table`; false if the
  // dialog does not offer it.
  bool chooseField(const std::string& path);
  bool chooseCell(const std::string& table, int row, const std::string& column);

  QRadioButton* fieldButton() const { return field_choice_; }
  QRadioButton* cellButton() const { return cell_choice_; }
  QComboBox* fieldBox() const { return field_; }
  QComboBox* tableBox() const { return table_; }
  QSpinBox* rowBox() const { return row_; }
  QComboBox* columnBox() const { return column_; }
  QLabel* summaryLabel() const { return summary_; }
  QPushButton* addButton() const { return add_; }

 private:
  void tableChosen();
  void check();

  const SceneDefinition* scene_;  // the registry's entry: lives as long as the program
  Schema schema_;
  Json parameters_;
  std::vector<std::string> taken_;
  QRadioButton* field_choice_;
  QRadioButton* cell_choice_;
  QComboBox* field_;
  QComboBox* table_;
  QSpinBox* row_;
  QComboBox* column_;
  QLabel* summary_;
  QPushButton* add_;
};

}  // namespace maris::ui
