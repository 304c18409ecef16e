// "Sweep this parameter…": from, to, number of values and spacing (linear or logarithmic) for one
// numeric field of the open scenario, checked against the field's range as they are typed. The
// dialog only describes the sweep; the study panel builds and expands the study.
#pragma once

#include <functional>

#include <QDialog>

#include "core/schema.hpp"

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace maris::ui {

// One varied parameter of a full-factorial grid: `count` values from `from` to `to`, evenly spaced
// (or evenly in the logarithm).
struct SweepRange {
  std::string path;  // below "parameters"
  double from = 0.0;
  double to = 1.0;
  int count = 5;
  bool log = false;
  bool operator==(const SweepRange&) const = default;
};

// A sweep proposed for a field whose value is `current`: half to one and a half times the value
// (0 … 1 for a zero), clipped to the field's range, 5 values, linear.
SweepRange proposedSweep(const ParamSpec& spec, const Json& current);

// The interval proposed for sampling `spec` (value `current`) in a Latin hypercube: proposedSweep's (half to
// one and a half times the value, clipped to the field's range).
SweepRange proposedSampleRange(const ParamSpec& spec, const Json& current);

// Why `range` cannot be swept over `spec` ("from: must be > 0 for a logarithmic spacing"), or empty.
QString sweepProblem(const ParamSpec& spec, const SweepRange& range);

class SweepDialog : public QDialog {
  Q_OBJECT
 public:
  SweepDialog(const ParamSpec& spec, const SweepRange& proposed, QWidget* parent = nullptr);

  SweepRange range() const;
  // True when "Add to study" closed the dialog (the study panel then adds the parameter to its grid
  // instead of replacing the grid and running).
  bool addOnly() const { return add_only_; }

  QLineEdit* fromEdit() const { return from_; }
  QLineEdit* toEdit() const { return to_; }
  QSpinBox* countBox() const { return count_; }
  QComboBox* spacingBox() const { return spacing_; }
  QPushButton* sweepButton() const { return sweep_; }
  QLabel* problemLabel() const { return problem_; }
  QPushButton* addButton() const { return add_; }

  // Checks the cases the answer would make (the second argument: "Add to study"); a non-empty answer keeps
  // the dialog open with it shown (a value the field allows can still break a cross-field rule, e.g. a probe
  // beyond a shorter riser). Without one, the dialog checks the field's range only.
  using CaseCheck = std::function<QString(const SweepRange&, bool)>;
  void setCaseCheck(CaseCheck check) { case_check_ = std::move(check); }

 private:
  void check();
  void finish(bool add_only);  // Run sweep or Add to study: accepts unless the case check objects

  ParamSpec spec_;
  QLineEdit* from_;
  QLineEdit* to_;
  QSpinBox* count_;
  QComboBox* spacing_;
  QLabel* problem_;
  CaseCheck case_check_;
  QPushButton* sweep_;
  QPushButton* add_;
  bool add_only_ = false;
};

}  // namespace maris::ui
