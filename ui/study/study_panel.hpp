// The Study dock: a study built from the open scenario. Its varied parameters (a full-factorial
// grid: from, to, values, spacing per number field), or a table or Latin-hypercube study opened
// from a file; Run study (every case on a pool of worker threads, StudyRunner) and Cancel; the
// result plot (StudyPlotView) whose points open their case's full results in the main window;
// export of study.csv and of the plot; save and open of the study file.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include <QWidget>

#include "study/study_session.hpp"
#include "study/sweep_dialog.hpp"
#include "study/weighted_sum_dialog.hpp"

class QAction;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QTimer;

namespace maris::ui {

class ScenarioDocument;
class StudyPlotView;
class StudyRunner;
struct SceneLibrary;

class StudyPanel : public QWidget {
  Q_OBJECT
 public:
  StudyPanel(ScenarioDocument* document, std::shared_ptr<const SceneLibrary> library, QWidget* parent = nullptr);
  ~StudyPanel() override;

  // "Sweep this parameter…": asks for the range (through the sweep prompt), then either replaces
  // the grid by it and runs the study, or adds it to the grid. False if nothing was done.
  bool sweep(const QString& path);
  // Adds (or replaces, by path) a varied parameter of the grid.
  void addParameter(const SweepRange& range);
  void removeParameter(const std::string& path);
  void clearParameters();
  const std::vector<SweepRange>& parameters() const { return grid_; }

  // Builds the study from the open scenario and the grid (unless one was opened from a file),
  // expands and validates every case and starts them. False (reason in lastError()) if invalid.
  bool startStudy();
  void cancelStudy();
  bool isRunning() const;
  // Worker threads for the next study (0: one per hardware thread).
  void setThreads(int threads);

  bool exportCsv(const QString& file);
  bool exportPlot(const QString& file);
  bool saveStudy(const QString& file);
  // A load-case table study over the open scenario (one case per row of the CSV file); false, with the
  // reason logged, when the table or a case is bad.
  bool openCaseTable(const QString& file);
  // A study file; or a study folder's study.json, which opens the folder (openStudyFolder).
  bool openStudy(const QString& file);
  // "Open study folder…": a study that `maris-cli study run` (or a Slurm array) ran, as it stands — its plot,
  // study.csv and weighted sums from the complete cases' summary.json. Nothing runs (Run study is disabled: the
  // CLI's `study run --resume` finishes it); a clicked point opens the case's results from its case folder (tables
  // and plots; caseRecord). False, with the reason
  // logged, when DIR holds no study.
  bool openStudyFolder(const QString& dir);
  // "New Latin hypercube study…": a sample over the open scenario (the engine draws the cases); false, with
  // the reason logged, when the design is bad.
  bool defineLatinHypercube(const LatinHypercubeDesign& design);

  // A table study's weighted sum (the study file's "weighted_sum"): `column` of its table holds each case's
  // weight and `results` are summed with it; "" clears it. The sums show below the run buttons at once for the
  // cases that ran. False, with the reason logged, when the engine refuses the column or the study is no table.
  bool setWeightedSum(const std::string& column, const std::vector<std::string>& results);
  // "Weighted sum…": asks for the column and the results (through the prompt) and sets them; false if nothing changed.
  bool weightedSumDialog();
  // How the weight column and results are asked for (tests replace the dialog, WeightedSumDialog): `columns` are
  // the table's columns that vary no parameter, `known` (name, label) the results the cases have so far; nullopt
  // to cancel.
  using WeightedSumPrompt = std::function<std::optional<WeightedSumChoice>(
      const std::vector<std::string>& columns, const std::vector<std::pair<std::string, std::string>>& known,
      const WeightedSumChoice& current)>;
  void setWeightedSumPrompt(WeightedSumPrompt prompt) { weighted_sum_prompt_ = std::move(prompt); }
  // The weighted sums as shown: a heading naming the weight column, then one row per summed result (its label
  // and unit, the sum, and which cases it still waits for). Hidden when the study has no weighted sum.
  QLabel* weightedSumHeading() const { return weighted_heading_; }
  QTableWidget* weightedSumTable() const { return weighted_table_; }

  // A finished case as a run record for the results view ("study case 0003 (Length L [m] = 120)"). Its id is `id`.
  // A case of a study opened from its folder brings its full results from its case folder (tables, plots,
  // warnings; no 3D view is stored there). Nullopt if the case has no results. `note` (if given) receives in words
  // why there is nothing (failed, with its message; cancelled; not run) or what the case folder could not give.
  std::optional<RunRecord> caseRecord(int index, quint64 id, QString* note = nullptr) const;

  const StudySession& session() const { return session_; }
  StudyRunner* runner() const { return runner_; }
  StudyPlotView* plotView() const { return plot_view_; }
  QTableWidget* parameterTable() const { return table_; }
  QString lastError() const { return last_error_; }

  // How the panel asks for a sweep's range (tests replace the dialog): nullopt to cancel; the
  // bool is true for "Add to study" (no run).
  using SweepPrompt = std::function<std::optional<std::pair<SweepRange, bool>>(const ParamSpec&, const SweepRange&)>;
  void setSweepPrompt(SweepPrompt prompt) { sweep_prompt_ = std::move(prompt); }
  // How "Add parameter…" asks what to vary (tests replace the dialog, AddParameterDialog): the path of a
  // number field or a table cell of `scene` over the base's `parameters`, not one of `taken`; "" to cancel.
  using ParameterPrompt =
      std::function<std::string(const SceneDefinition& scene, const Json& parameters, const std::vector<std::string>& taken)>;
  void setParameterPrompt(ParameterPrompt prompt) { parameter_prompt_ = std::move(prompt); }
  // "Add parameter…": asks what to vary, then its range; false if nothing was added.
  bool addParameterDialog();

  // What the study may vary at `path` (a number field or a table cell whose row is in the base), or nothing
  // with the reason in `why`: the engine's check of a study file's parameters.
  std::optional<ParamSpec> parameterSpec(const std::string& path, QString* why = nullptr) const;

 signals:
  void caseOpened(int index);              // a plot point was clicked
  void message(const QString& text);       // for the status bar
  void logged(int level, const QString& text);  // 0 info, 1 warning, 2 error (RunPanel::Level)
  void studyFinished(int succeeded, int failed);
  void studyCancelled();

 private:
  void rebuildTable();
  void updateButtons();
  // The parameters of the study's base: the study's own when it came from a file, else the open scenario's.
  const Json& baseParameters() const;
  // Shows the study's weighted sums (the engine's, over the outcomes so far), or hides them when it has none.
  void showWeightedSums();
  void onCaseFinished(int index, ResultsPtr results, double wall_time_s);
  void onCaseFailed(int index, const QString& message);
  void fail(const QString& text);
  // Why the grid `grid` over the study's base cannot run (its first invalid cases), or "" (sweep dialog).
  QString gridProblem(std::vector<SweepRange> grid) const;
  bool replaceSession(const QString& failure, const std::function<void(StudySession&)>& build);
  // A table or Latin-hypercube study opened or built here: its parameters are its design (a CSV table, a sample),
  // so no grid parameter is added to it (that would replace the design by a grid over its base).
  bool fixedDesign() const;

  ScenarioDocument* document_;
  std::shared_ptr<const SceneLibrary> library_;
  StudySession session_;
  std::vector<SweepRange> grid_;
  bool from_file_ = false;  // the session was opened from a study file (its own base and cases)
  int threads_ = 0;
  StudyRunner* runner_;
  QLabel* base_;
  QTableWidget* table_;
  QPushButton* add_;
  QPushButton* remove_;
  QPushButton* run_;
  QPushButton* cancel_;
  QSpinBox* threads_box_;
  QLabel* summary_;
  QWidget* weighted_box_;
  QLabel* weighted_heading_;
  QTableWidget* weighted_table_;
  QAction* weighted_action_ = nullptr;
  StudyPlotView* plot_view_;
  QTimer* refresh_timer_;
  QString last_error_;
  SweepPrompt sweep_prompt_;
  ParameterPrompt parameter_prompt_;
  WeightedSumPrompt weighted_sum_prompt_;
};

}  // namespace maris::ui
