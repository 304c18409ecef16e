// The results summary dock: the shown run's key scalars (value, unit, meaning), its solver
// statistics (method, steps, error estimate, wall time) and warnings. The scalars can be copied
// (Ctrl+C or the context menu: tab-separated with a header row, for spreadsheets) and exported as
// CSV (names row, units row, one row of values, like the engine's tables).
#pragma once

#include <filesystem>

#include <QWidget>

#include "run/run_controller.hpp"

class QAction;
class QTableWidget;
class QLabel;

namespace maris::ui {

class ResultsSummary : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsSummary(QWidget* parent = nullptr);
  // Warnings name parameters as the editor does when the run's `schema` is given (withFieldNames).
  void showRun(const RunRecord& record, const Schema* schema = nullptr);
  void clear();
  QTableWidget* table() const { return table_; }

  // The selected scalar rows (all of them when none is selected) as tab-separated text: a header
  // row "Quantity, Value, Unit, Meaning", then one row per scalar, its value to full precision.
  QString copyText() const;
  void copyToClipboard() const;
  // Writes the shown run's scalars as CSV, atomically. Throws std::runtime_error if there is no
  // run or the file cannot be written.
  void exportCsv(const std::filesystem::path& file) const;
  QAction* copyAction() const { return copy_action_; }
  QAction* exportAction() const { return export_action_; }

 signals:
  void message(const QString& text);

 private:
  void exportDialog();

  ResultsPtr results_;
  QAction* copy_action_;
  QAction* export_action_;
  QLabel* heading_;
  QTableWidget* table_;
  QLabel* stats_;
};

}  // namespace maris::ui
