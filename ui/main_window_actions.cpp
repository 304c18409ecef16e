// MainWindow: opening and saving scenarios, and runs with their results.
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

#include "browser/scenario_browser.hpp"
#include "counted.hpp"
#include "document/scenario_document.hpp"
#include "main_window.hpp"
#include "plots/plot_export.hpp"
#include "plots/plot_panel.hpp"
#include "run/live_results.hpp"
#include "run/results_summary.hpp"
#include "run/run_panel.hpp"
#include "scene_library.hpp"
#include "start_folder.hpp"
#include "study/study_panel.hpp"
#include "view3d/scene_view.hpp"

namespace maris::ui {

bool MainWindow::loadScenario(const Scenario& scenario, const QString& path, const QString& example_id) {
  const SceneDefinition* scene = library_->findScene(scenario.scene);
  if (!scene) {
    QStringList known;
    for (const auto& s : library_->scenes) known << QString::fromStdString(s.name);
    last_error_ = tr("The scenario's scene \"%1\" is not built into this program (known: %2).")
                      .arg(QString::fromStdString(scenario.scene), known.join(QStringLiteral(", ")));
    run_panel_->log(RunPanel::Level::Error, last_error_);
    status(last_error_);
    return false;
  }
  // Results of another scenario do not belong beside this one (probe 3 may sit at another arc length, the
  // riser have another length): the views are cleared. The finished runs stay in the history, and runs of
  // the same scenario are offered for overlays again once it runs.
  plots_->clear();
  view_->clear();
  summary_->clear();
  shown_run_ = 0;
  example_id_ = example_id;
  // Renamed fields of older files are rewritten before editing, so the editor shows them and Save writes them.
  Scenario upgraded = scenario;
  const std::vector<std::string> notes = upgradeParameters(*scene, upgraded.parameters);
  document_->reset(scene, upgraded, path);
  for (const std::string& note : notes) run_panel_->log(RunPanel::Level::Warning, withFieldNames(note, scene->schema));
  browser_->setCurrent(example_id, path);
  updateTitle();
  updateRunEnabled();
  const QString what = path.isEmpty() ? example_id : path;
  if (!document_->isValid())
    run_panel_->log(RunPanel::Level::Warning, tr("Opened %1 with %2; see the parameter editor.")
                                                 .arg(what, counted(static_cast<int>(document_->errors().size()),
                                                                    tr("invalid value"), tr("invalid values"))));
  status(tr("Opened %1").arg(what));
  return true;
}

bool MainWindow::openExample(const QString& id) {
  const BuiltinScenario* example = library_->findExample(id.toStdString());
  if (!example) {
    last_error_ = tr("There is no built-in scenario \"%1\".").arg(id);
    status(last_error_);
    return false;
  }
  if (!confirmDiscard()) return false;
  return loadScenario(example->scenario, QString(), id);
}

bool MainWindow::openFile(const QString& path) {
  if (!confirmDiscard()) return false;
  Scenario scenario;
  try {
    scenario = loadScenarioFile(path.toStdString());
  } catch (const std::exception& e) {
    last_error_ = tr("Could not open %1: %2").arg(path, QString::fromUtf8(e.what()));
    run_panel_->log(RunPanel::Level::Error, last_error_);
    status(last_error_);
    return false;
  }
  if (!loadScenario(scenario, QFileInfo(path).absoluteFilePath(), QString())) return false;
  addRecentFile(path);
  return true;
}

bool MainWindow::newScenario(const QString& scene_name) {
  const SceneDefinition* scene = library_->findScene(scene_name.toStdString());
  if (!scene || !confirmDiscard()) return false;
  return loadScenario(defaultScenario(*scene), QString(), QString());
}

bool MainWindow::save() {
  if (document_->isEmpty()) return false;
  if (document_->filePath().isEmpty()) {
    saveAsDialog();
    return !document_->isModified() && !document_->filePath().isEmpty();
  }
  return saveAs(document_->filePath());
}

bool MainWindow::saveAs(const QString& path) {
  if (document_->isEmpty() || path.isEmpty()) return false;
  try {
    saveScenarioFile(document_->scenario(), path.toStdString());  // atomic: temp file + rename
  } catch (const std::exception& e) {
    last_error_ = tr("Could not save %1: %2").arg(path, QString::fromUtf8(e.what()));
    run_panel_->log(RunPanel::Level::Error, last_error_);
    status(last_error_);
    return false;
  }
  document_->setFilePath(QFileInfo(path).absoluteFilePath());
  document_->markSaved();
  example_id_.clear();
  browser_->setCurrent(QString(), document_->filePath());
  addRecentFile(path);
  updateTitle();
  status(tr("Saved %1").arg(path));
  return true;
}

bool MainWindow::writeReport(const QString& dir) {
  const RunRecord* record = history_.find(shown_run_);
  if (!record) {
    status(tr("No finished run to report: run the scenario first."));
    return false;
  }
  try {
    const QImage image = view_->renderImage(1600, 1000);
    const auto files = writeReportFolder(dir.toStdString(), record->scenario, *record->results, record->started_at, image);
    run_panel_->log(RunPanel::Level::Info, tr("Report of %1 written to %2 (%3)")
                                              .arg(record->label, dir,
                                                   counted(static_cast<int>(files.size()), tr("file"), tr("files"))));
    status(tr("Report written to %1").arg(dir));
    return true;
  } catch (const std::exception& e) {
    last_error_ = tr("Could not write the report: %1").arg(QString::fromUtf8(e.what()));
    run_panel_->log(RunPanel::Level::Error, last_error_);
    status(last_error_);
    return false;
  }
}

bool MainWindow::startRun() {
  if (runs_->isRunning() || study_->isRunning() || !document_->isValid()) {
    if (!document_->isValid()) status(tr("Fix the invalid values first (marked red in the parameter editor)."));
    return false;
  }
  if (!confirmLargeRun()) return false;
  live_->restart();
  plots_->setDeclaredGroups(document_->scene()->plot_groups);  // live plots are grouped as the scene wants
  const quint64 id = runs_->start(*document_->scene(), document_->scenario());
  run_panel_->log(RunPanel::Level::Info,
                  tr("Run %1 started: %2").arg(id).arg(QString::fromStdString(document_->scenario().name)));
  status(tr("Running…"), 0);
  return id != 0;
}

bool MainWindow::confirmLargeRun() {
  const auto errors = workLimitErrors(estimateWork(*document_->scene(), document_->scenario().parameters));
  if (errors.empty()) return true;
  QStringList lines;
  for (const auto& e : errors) lines << QString::fromStdString(e.str());
  const auto answer = QMessageBox::warning(
      this, tr("Large run"),
      tr("This run is beyond the work limits:\n\n%1\n\nRun it anyway?").arg(lines.join(QStringLiteral("\n\n"))),
      QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
  if (answer == QMessageBox::Yes) return true;
  status(tr("Run not started: beyond the work limits."));
  return false;
}

void MainWindow::cancelRun() {
  if (study_->isRunning()) {
    study_->cancelStudy();
    status(tr("Cancelling the study…"), 0);
    return;
  }
  if (!runs_->isRunning()) return;
  runs_->cancel();
  status(tr("Cancelling…"), 0);
}

void MainWindow::showRecord(const RunRecord& record) {
  shown_run_ = record.id;
  if (const SceneDefinition* scene = library_->findScene(record.scenario.scene)) plots_->setDeclaredGroups(scene->plot_groups);
  plots_->showResults(record.results, record.label);
  plots_->showPlotWithData();  // a statics-only run opens on its shape, not on an empty time history
  // Overlays and the all-runs CSV combine runs whose columns mean the same: runs of the same scenario.
  std::vector<RunRecord> same_scenario;
  for (const auto& r : history_.runs())
    if (sameScenario(r.scenario, record.scenario)) same_scenario.push_back(r);
  plots_->setAvailableRuns(same_scenario, record.id);
  view_->showResults(record.results);
  const SceneDefinition* scene = library_->findScene(record.scenario.scene);
  summary_->showRun(record, scene ? &scene->schema : nullptr);
}

// After a failed or cancelled run the plots may hold partial results: show the last finished run.
void MainWindow::restoreShownRun() {
  if (const RunRecord* shown = history_.find(shown_run_)) {
    showRecord(*shown);
  } else {
    plots_->clear();
    view_->clear();
  }
}

bool MainWindow::openStudyCase(int index) {
  QString note;
  const std::optional<RunRecord> record = study_->caseRecord(index, next_study_case_id_++, &note);
  if (!record) {
    // Said, not silently ignored: a failed case's cell can be clicked.
    if (!note.isEmpty()) {
      run_panel_->log(RunPanel::Level::Warning, note);
      status(note.section(QLatin1Char('\n'), 0, 0), 15000);
    }
    return false;
  }
  showRecord(history_.add(*record, true));
  // A case read from its folder has no 3D view: say so rather than leave another run's view beside its plots.
  if (record->results->view.empty()) {
    const QString folder = study_->session().folder();
    const QString scenario = folder.isEmpty() ? tr("cases/NNNN.json in the study folder")
                                              : QDir(folder).filePath(QStringLiteral("cases/%1.json")
                                                                          .arg(study_->session().caseId(index)));
    view_->clear(tr("No 3D view: a study's case folder stores none. To see it, open the case's scenario (%1) "
                    "and run it.").arg(scenario));
  }
  if (!view_->isPlaying()) view_->setFrame(view_->frameCount() - 1);
  if (!note.isEmpty()) run_panel_->log(RunPanel::Level::Info, note);
  status(tr("Showing %1").arg(record->label));
  return true;
}

void MainWindow::onRunFinished(const RunRecord& finished) {
  const SceneDefinition* scene = library_->findScene(finished.scenario.scene);
  const RunRecord& record = history_.add(finished, false, scene ? &scene->schema : nullptr);
  showRecord(record);
  // A finished run opens on its final state (the end of the time history, the last load step).
  if (!view_->isPlaying()) view_->setFrame(view_->frameCount() - 1);
  for (const auto& w : record.results->warnings)
    run_panel_->log(RunPanel::Level::Warning, scene ? withFieldNames(w, scene->schema) : QString::fromStdString(w));
  run_panel_->log(RunPanel::Level::Info,
                  tr("Finished %1 in %2").arg(record.label, formatDuration(record.wall_time_s)));
  status(tr("Finished %1 in %2").arg(record.label, formatDuration(record.wall_time_s)));
  emit runFinished(record.id);
}

void MainWindow::onRunFailed(const QString& message) {
  last_error_ = message;
  run_panel_->log(RunPanel::Level::Error, message);
  status(message.section(QLatin1Char('\n'), 0, 0), 15000);
  restoreShownRun();
  emit runFailed(message);
}

void MainWindow::onRunCancelled() {
  const double latency_ms = runs_->lastCancelLatency() * 1e3;
  run_panel_->log(RunPanel::Level::Info, tr("Run cancelled: the solver stopped %1 ms after the request")
                                             .arg(latency_ms, 0, 'f', 1));
  status(tr("Run cancelled"));
  restoreShownRun();
  emit runCancelled();
}

void MainWindow::openFileDialog() {
  const QString dir = recent_files_.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                              : QFileInfo(recent_files_.front()).absolutePath();
  const QString path = QFileDialog::getOpenFileName(this, tr("Open scenario"), dir, tr("Maris scenario (*.json)"));
  if (!path.isEmpty()) openFile(path);
}

void MainWindow::saveAsDialog() {
  if (document_->isEmpty()) return;
  QString suggested = document_->filePath();
  if (suggested.isEmpty())
    suggested = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) + "/" +
                (example_id_.isEmpty() ? QStringLiteral("scenario") : example_id_) + ".json";
  const QString path = QFileDialog::getSaveFileName(this, tr("Save scenario as"), suggested, tr("Maris scenario (*.json)"));
  if (!path.isEmpty()) saveAs(path.endsWith(QLatin1String(".json")) ? path : path + ".json");
}

void MainWindow::newScenarioDialog() {
  QStringList titles;
  for (const auto& s : library_->scenes) titles << QString::fromStdString(s.title);
  if (titles.isEmpty()) return;
  int index = 0;
  if (titles.size() > 1) {
    bool ok = false;
    const QString title = QInputDialog::getItem(this, tr("New scenario"), tr("Scene"), titles, 0, false, &ok);
    if (!ok) return;
    index = static_cast<int>(titles.indexOf(title));
  }
  newScenario(QString::fromStdString(library_->scenes[index].name));
}

void MainWindow::reportDialog() {
  const QString last_key = QStringLiteral("report/lastFolder");
  const QString dir = QFileDialog::getExistingDirectory(this, tr("Report folder"),
                                                        startFolder(QSettings().value(last_key).toString()));
  if (dir.isEmpty()) return;
  QSettings().setValue(last_key, dir);
  // Each report goes into its own folder named after the scenario and the run.
  const RunRecord* record = history_.find(shown_run_);
  QString name = record ? QString::fromStdString(record->scenario.name) + QStringLiteral(" run %1").arg(record->id)
                        : QStringLiteral("report");
  name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]+")), QStringLiteral("_"));
  writeReport(QDir(dir).filePath(name));
}

}  // namespace maris::ui
