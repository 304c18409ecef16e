// "New Latin hypercube study…": which number fields of the open scenario to sample, each over an
// interval (by default the field's allowed range when it is bounded, else half to one and a half times
// its value), the number of samples and the seed. The dialog only describes the design; the study panel
// builds the study document and the engine draws the samples (engine/study), as for `maris-cli study run`.
#pragma once

#include <cstdint>
#include <vector>

#include <QDialog>

#include "core/scene.hpp"
#include "study/sweep_dialog.hpp"

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace maris::ui {

// A Latin-hypercube design over the open scenario: each range's `from` and `to` bound one parameter
// (`count` and `log` of SweepRange are not used: one sample per stratum, linear).
struct LatinHypercubeDesign {
  std::vector<SweepRange> ranges;
  int samples = 20;
  std::uint64_t seed = 1;
};

class LatinHypercubeDialog : public QDialog {
  Q_OBJECT
 public:
  // Rows: every Real and Integer field of `scene`, the value of each from `scenario`.
  LatinHypercubeDialog(const SceneDefinition& scene, const Scenario& scenario, QWidget* parent = nullptr);

  // Ticks the row of `path` and sets its interval; false if there is no such row.
  bool choose(const std::string& path, double from, double to);
  LatinHypercubeDesign design() const;
  // Why the design cannot be sampled (the first problem), or empty.
  QString problem() const;

  QTableWidget* table() const { return table_; }
  QSpinBox* samplesBox() const { return samples_; }
  QSpinBox* seedBox() const { return seed_; }
  QPushButton* createButton() const { return create_; }

 private:
  void check();

  std::vector<ParamSpec> specs_;  // one per row
  QTableWidget* table_;
  QSpinBox* samples_;
  QSpinBox* seed_;
  QLabel* problem_;
  QPushButton* create_;
};

}  // namespace maris::ui
