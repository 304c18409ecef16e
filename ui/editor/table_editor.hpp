// Editor for a Table parameter (an array of rows whose fields are the spec's columns): a grid
// with one column per field ("outer diameter [m]"), add/remove row buttons, and bad cells
// marked with the validation message as their tooltip. Each change emits the whole new array,
// which the parameter editor turns into one undoable SetParameterCommand. A number cell's context menu
// offers "Sweep this cell…".
#pragma once

#include <QWidget>

#include "core/errors.hpp"
#include "core/schema.hpp"

class QMenu;
class QTableWidget;
class QPushButton;

namespace maris::ui {

class TableEditor : public QWidget {
  Q_OBJECT
 public:
  TableEditor(const ParamSpec& spec, QWidget* parent = nullptr);

  void setValue(const Json& rows);
  Json value() const { return rows_; }
  // Marks cells whose "<full_path>[row].<column>" appears in `errors`.
  void markErrors(const std::vector<FieldError>& errors, const std::string& full_path);
  QTableWidget* grid() const { return grid_; }
  // The context menu of the cell at (`row`, `column`): "Sweep this cell…" for a number column; nullptr for a
  // cell that is not there or not a number.
  QMenu* cellMenu(int row, int column, QWidget* parent = nullptr);

 signals:
  void edited(const maris::Json& rows);
  // "Sweep this cell…" was chosen for row `row` (from 0) and column `column` (its key, "outer_diameter").
  void sweepRequested(int row, const QString& column);

 private:
  void onCellChanged(int row, int column);
  void addRow();
  void removeRows();

  ParamSpec spec_;
  Json rows_ = Json::array();
  QTableWidget* grid_;
  QPushButton* add_;
  QPushButton* remove_;
};

}  // namespace maris::ui
