// The run panel dock: Run / Cancel buttons (the main window's actions), a progress bar with the
// solver's stage, elapsed and estimated remaining time, and a log of runs, warnings and errors
// that follows its newest line unless the user scrolled up. A cancelled or failed run resets the
// bar and the time left. A study's runs (StudyRunner) show here the same way.
#pragma once

#include <QWidget>

class QAction;
class QLabel;
class QPlainTextEdit;
class QProgressBar;

namespace maris::ui {

class RunController;
class StudyRunner;

class RunPanel : public QWidget {
  Q_OBJECT
 public:
  RunPanel(RunController* controller, QAction* run_action, QAction* cancel_action, QWidget* parent = nullptr);

  // Shows a study's progress over its cases in the same bar, stage line and time label.
  void follow(StudyRunner* study);

  enum class Level { Info, Warning, Error };
  void log(Level level, const QString& text);

  QProgressBar* progressBar() const { return progress_; }
  QPlainTextEdit* logView() const { return log_; }
  QLabel* timeLabel() const { return time_; }

 private:
  void onProgress(double fraction, const QString& stage, double elapsed_s, double remaining_s);
  void stopped(const QString& stage);

  QProgressBar* progress_;
  QLabel* stage_;
  QLabel* time_;
  QPlainTextEdit* log_;
  bool follow_log_ = true;
  bool appending_ = false;
};

// "3.2 s", "2 min 05 s".
QString formatDuration(double seconds);

}  // namespace maris::ui
