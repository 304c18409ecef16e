// "Weighted sum…" of a table study: which column of its table holds each case's weight (a sea state's
// probability) and which scalar results to sum with it, i.e. the study file's "weighted_sum". The dialog
// only describes the choice; the study panel hands it to the engine, which reads and checks the column.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace maris::ui {

struct WeightedSumChoice {
  std::string column;                // "" for no weighted sum
  std::vector<std::string> results;  // scalar names, as in a run's summary.json
  bool operator==(const WeightedSumChoice&) const = default;
};

class WeightedSumDialog : public QDialog {
  Q_OBJECT
 public:
  // `columns`: the table's columns that vary no parameter; `known`: (name, label for people) of the results the
  // study's cases have so far (empty before a run: the names are then typed); `current`: the study's choice.
  WeightedSumDialog(const std::vector<std::string>& columns, const std::vector<std::pair<std::string, std::string>>& known,
                    const WeightedSumChoice& current, QWidget* parent = nullptr);

  WeightedSumChoice choice() const;
  // Why the choice cannot be taken (a column without results), or empty.
  QString problem() const;

  QComboBox* columnBox() const { return column_; }
  QListWidget* resultList() const { return results_; }
  QLineEdit* otherResults() const { return other_; }
  QPushButton* okButton() const { return ok_; }

 private:
  void check();

  QComboBox* column_;
  QListWidget* results_;
  QLineEdit* other_;
  QLabel* problem_;
  QPushButton* ok_;
};

}  // namespace maris::ui
