// The Maris main window: scenario browser, parameter editor, run panel and results summary as
// dock widgets around a central 3D view and plot tabs. It takes the scene library as a
// dependency (the engine's catalog in the application, a small test scene in tests) and knows no
// scene by name. File handling (New/Open/Save/Save As, recent files, drag and drop, the prompt
// before losing edits) and runs (start, cancel, results, failures) are in main_window_*.cpp.
#pragma once

#include <functional>
#include <memory>

#include <QMainWindow>
#include <QMessageBox>

#include "run/run_history.hpp"
#include "theme.hpp"

class QAction;
class QDockWidget;
class QMenu;
class QLabel;
class QSplitter;

namespace maris::ui {

struct SceneLibrary;
class ScenarioDocument;
class ScenarioBrowser;
class ParameterEditor;
class RunController;
class RunPanel;
class ResultsSummary;
class PlotPanel;
class LiveResults;
class SceneView;
class StudyPanel;

// The size of a first window: 90 % of the screen's available area, at most 1600 × 1000.
QSize defaultWindowSize(const QSize& available);

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(std::shared_ptr<const SceneLibrary> library, QWidget* parent = nullptr);
  ~MainWindow() override;

  // Each returns false (and says why in the log and status bar) when nothing was opened; they ask
  // before discarding unsaved edits.
  bool openExample(const QString& id);
  bool openFile(const QString& path);
  bool newScenario(const QString& scene_name);
  bool save();
  bool saveAs(const QString& path);
  // Writes the report folder of the shown run. False if there is none or writing failed.
  bool writeReport(const QString& dir);

  bool startRun();
  void cancelRun();

  // Light, dark or the platform's palette for the whole application; kept in QSettings.
  void setTheme(Theme theme);
  Theme theme() const { return theme_; }

  // How the window asks before discarding unsaved edits (tests replace the dialog).
  using UnsavedPrompt = std::function<QMessageBox::StandardButton()>;
  void setUnsavedPrompt(UnsavedPrompt prompt) { unsaved_prompt_ = std::move(prompt); }

  ScenarioDocument* document() const { return document_; }
  ParameterEditor* editor() const { return editor_; }
  RunController* runController() const { return runs_; }
  RunPanel* runPanel() const { return run_panel_; }
  PlotPanel* plots() const { return plots_; }
  SceneView* sceneView() const { return view_; }
  LiveResults* liveResults() const { return live_; }
  ResultsSummary* summary() const { return summary_; }
  ScenarioBrowser* browser() const { return browser_; }
  StudyPanel* study() const { return study_; }
  // Shows case `index` of the study's results in the plots, 3D view and Results dock, as a run.
  bool openStudyCase(int index);
  const RunHistory& history() const { return history_; }
  QAction* runAction() const { return run_action_; }
  QAction* cancelAction() const { return cancel_action_; }
  QString lastError() const { return last_error_; }
  QStringList recentFiles() const { return recent_files_; }

 signals:
  void runFinished(quint64 run);
  void runFailed(const QString& message);
  void runCancelled();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createActions();
  void createDocks();
  void showStudyDock();  // docked beside the views where the window is wide enough, else floating over them
  void restoreSettings();
  void saveSettings() const;
  void addRecentFile(const QString& path);
  void updateTitle();
  void updateRunEnabled();
  bool confirmDiscard();
  // Asks before a run beyond the work limits (core/work_estimate.hpp); true to go ahead.
  bool confirmLargeRun();
  bool loadScenario(const Scenario& scenario, const QString& path, const QString& example_id);
  void showRecord(const RunRecord& record);
  void restoreShownRun();
  void onRunFinished(const RunRecord& record);
  void onRunFailed(const QString& message);
  void onRunCancelled();
  void openFileDialog();
  void saveAsDialog();
  void newScenarioDialog();
  void reportDialog();
  void status(const QString& text, int timeout_ms = 6000);

  std::shared_ptr<const SceneLibrary> library_;
  ScenarioDocument* document_;
  RunController* runs_;
  RunHistory history_;
  quint64 shown_run_ = 0;
  QString example_id_;
  QString last_error_;
  QStringList recent_files_;
  UnsavedPrompt unsaved_prompt_;
  Theme theme_ = Theme::System;
  QMenu* theme_menu_ = nullptr;

  ScenarioBrowser* browser_ = nullptr;
  ParameterEditor* editor_ = nullptr;
  RunPanel* run_panel_ = nullptr;
  ResultsSummary* summary_ = nullptr;
  PlotPanel* plots_ = nullptr;
  SceneView* view_ = nullptr;
  LiveResults* live_ = nullptr;
  QSplitter* central_ = nullptr;
  StudyPanel* study_ = nullptr;
  QDockWidget* study_dock_ = nullptr;
  QDockWidget* left_dock_ = nullptr;  // the scenario browser's dock (the parameter editor's column)
  quint64 next_study_case_id_ = 1'000'000'000;  // above the run controller's ids
  QLabel* validity_ = nullptr;
  QAction* run_action_ = nullptr;
  QAction* cancel_action_ = nullptr;
  QAction* save_action_ = nullptr;
  QAction* report_action_ = nullptr;
};

}  // namespace maris::ui
