// The study the Study panel shows: its definition (the open scenario as base, the varied
// parameters), its cases as the engine expands them, and each case's outcome once it ran. The
// study file, the expansion into cases, the validation of every case and study.csv are the
// engine's (engine/study/); this class only keeps them together with the results in memory and
// turns them into plot data. No physics and no second expansion here.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <QString>

#include "plots/study_plot.hpp"
#include "run/run_controller.hpp"
#include "study/study_collect.hpp"
#include "study/latin_hypercube_dialog.hpp"
#include "study/sweep_dialog.hpp"

namespace maris::ui {

struct SceneLibrary;

class StudySession {
 public:
  enum class Status { Pending, Finished, Failed, Cancelled };
  struct CaseOutcome {
    Status status = Status::Pending;
    ResultsPtr results;
    QString error;
    double wall_time_s = 0.0;
  };

  // A grid study over `base` (kept inline in the study file). Clears cases and outcomes.
  void define(const SceneDefinition& scene, const Scenario& base, std::vector<SweepRange> grid);
  // A load-case table study over `base`: one case per data row of `csv_file` (a column per parameter
  // path; a units row may follow the names). With a `weight_column`, that column is no parameter but each
  // case's weight, and `weighted_results` are summed with it (the study file's "weighted_sum"). Throws
  // InputError naming every problem of the table.
  void defineTable(const SceneDefinition& scene, const Scenario& base, const QString& csv_file,
                   const std::string& weight_column = {}, const std::vector<std::string>& weighted_results = {});
  // A Latin-hypercube study over `base`: the engine draws `design.samples` cases from `design.seed`, one per
  // stratum of every parameter's interval. Throws InputError naming every problem of the design.
  void defineLatinHypercube(const SceneDefinition& scene, const Scenario& base, const LatinHypercubeDesign& design);
  // Reads a study file (grid, table or Latin hypercube); its base scenario's scene must be in
  // `library`. Throws InputError (every problem) or std::runtime_error.
  void load(const QString& file, const SceneLibrary& library);
  // Opens a study folder that `maris-cli study run` (or a Slurm array and `study collect`) wrote: the study as
  // run (its study.json), every case's scenario, and each case's outcome — the scalars of a complete case's
  // summary.json (its tables and plots stay in its run folder), the message of a failed one; a case not run
  // yet is Pending. Nothing runs. Throws InputError (no study there, an unknown scene) or std::runtime_error.
  void loadFolder(const QString& dir, const SceneLibrary& library);
  // The study folder it was opened from ("" when the study was defined here or read from a study file).
  QString folder() const { return folder_; }
  // Writes the study file atomically. Throws std::runtime_error (also for a study opened from its folder: its
  // study file is the one it was run from).
  void save(const QString& file) const;

  bool isDefined() const { return scene_ != nullptr; }
  const SceneDefinition* scene() const { return scene_.get(); }
  const Scenario& base() const { return base_; }
  // The varied parameters of a grid study (empty for a table or sample loaded from a file).
  const std::vector<SweepRange>& grid() const { return grid_; }
  // The varied parameters' paths, whatever the design.
  std::vector<std::string> parameterPaths() const;
  // Their labels for people ("Length L"; the path where the scene has none), in the same order.
  std::vector<std::string> parameterLabels() const;
  // "grid", "table" or "latin hypercube".
  QString kindName() const;
  bool isTable() const;
  bool isGrid() const;  // also when nothing is defined yet (the dock builds grids)

  // A table study's weighted sum (the study file's "weighted_sum"): the column of case weights ("" for none)
  // and the scalar results summed with it.
  std::string weightColumn() const;
  std::vector<std::string> weightedResults() const;
  // The columns of the table study's CSV file that vary no parameter: what may be its weight column.
  std::vector<std::string> weightCandidates() const;
  // The columns of `csv_file` that vary no parameter of `scene` over the base `parameters` (before a table
  // study is defined from it). Throws InputError when the file cannot be read.
  static std::vector<std::string> nonParameterColumns(const SceneDefinition& scene, const Json& parameters,
                                                      const QString& csv_file);
  // Sets (a `column` of the table) or clears ("") the table study's weighted sum; the engine reads the table
  // again and checks the column and its weights. The cases and their outcomes are kept when the table's
  // cases are the same, so the sums of a finished study show at once. Throws InputError or std::runtime_error
  // (not a table study); nothing changes then.
  void setWeightedSum(const std::string& column, const std::vector<std::string>& results);
  // Each weighted result summed over the cases so far with their weights (the engine's sum, as `maris-cli
  // study collect` writes it into study.json): no value while a case of weight > 0 has none, naming those
  // cases. Empty without a weighted sum or before the cases are expanded.
  std::vector<study::WeightedSum> weightedSums() const;

  // Expands the study into its cases and validates every one. Throws InputError naming every bad
  // case and field (nothing is kept then).
  void expand();
  int caseCount() const;
  const Scenario& caseScenario(int index) const;
  QString caseId(int index) const;  // "0001"
  // "length = 120 m, tension = 2e+06 N": the varied values of a case.
  QString caseLabel(int index) const;
  std::vector<Scenario> caseScenarios() const;

  void setOutcome(int index, CaseOutcome outcome);
  const CaseOutcome& outcome(int index) const { return outcomes_.at(index); }
  // Cases not finished or failed become Cancelled (after a cancel).
  void markUnfinishedCancelled();

  // The scalar results the finished cases have: those the study lists ("results") first, in its order, then the
  // others in the order of the first case that has them.
  std::vector<std::string> resultNames() const;
  // The label for people of result scalar `name` ("σ_b max"), from the first case that has it; else `name`.
  std::string resultLabel(const std::string& name) const;
  // The varied parameters (names, units, per-case values) and `result` per case (NaN where missing).
  StudyPlotData plotData(const std::string& result) const;
  // study.csv of the cases so far (the engine's writer), atomically. Throws std::runtime_error.
  void writeCsv(const QString& file) const;

 private:
  struct Impl;
  // Builds the engine's study from `document` (relative paths against `folder`) and makes it this session's.
  void adopt(const SceneDefinition& scene, const Scenario& base, const Json& document,
             const std::filesystem::path& folder, std::vector<SweepRange> grid);
  // The cases so far as the engine collects them: each case's status and values, and its scalars.
  study::CollectedStudy collected(std::vector<study::CaseScalars>* scalars = nullptr) const;
  std::shared_ptr<const SceneDefinition> scene_;
  Scenario base_;
  std::vector<SweepRange> grid_;
  std::shared_ptr<Impl> impl_;  // the engine's study and cases
  std::vector<CaseOutcome> outcomes_;
  QString folder_;
};

}  // namespace maris::ui
