// The results summary dock: the shown run's key scalars (value, unit, meaning), its solver
// statistics (method, steps, error estimate, wall time) and warnings.
#pragma once

#include <QWidget>

#include "run/run_controller.hpp"

class QTableWidget;
class QLabel;

namespace maris::ui {

class ResultsSummary : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsSummary(QWidget* parent = nullptr);
  void showRun(const RunRecord& record);
  void clear();
  QTableWidget* table() const { return table_; }

 private:
  QLabel* heading_;
  QTableWidget* table_;
  QLabel* stats_;
};

}  // namespace maris::ui
