#include "run/run_panel.hpp"

#include <cmath>

#include <QAction>
#include <QDateTime>
#include <QGridLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QScrollBar>
#include <QToolButton>

#include "counted.hpp"
#include "run/run_controller.hpp"
#include "study/study_runner.hpp"

namespace maris::ui {

QString formatDuration(double seconds) {
  if (seconds < 60.0) return QStringLiteral("%1 s").arg(seconds, 0, 'f', 1);
  const int total = static_cast<int>(std::lround(seconds));
  return QStringLiteral("%1 min %2 s").arg(total / 60).arg(total % 60, 2, 10, QLatin1Char('0'));
}

RunPanel::RunPanel(RunController* controller, QAction* run_action, QAction* cancel_action, QWidget* parent)
    : QWidget(parent), progress_(new QProgressBar(this)), stage_(new QLabel(this)), time_(new QLabel(this)),
      log_(new QPlainTextEdit(this)) {
  auto* run = new QToolButton(this);
  run->setDefaultAction(run_action);
  run->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  auto* cancel = new QToolButton(this);
  cancel->setDefaultAction(cancel_action);
  cancel->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setTextVisible(true);
  progress_->setFormat(QStringLiteral("%p%"));
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(2000);
  log_->setObjectName(QStringLiteral("runLog"));
  // The log follows its newest line until the user scrolls up, and again once they scroll back to
  // the bottom. Only the user moves the bar outside log(), so its position there says which.
  connect(log_->verticalScrollBar(), &QScrollBar::valueChanged, this, [this](int value) {
    if (!appending_) follow_log_ = value >= log_->verticalScrollBar()->maximum();
  });

  auto* layout = new QGridLayout(this);
  layout->addWidget(run, 0, 0);
  layout->addWidget(cancel, 0, 1);
  layout->addWidget(progress_, 0, 2);
  layout->addWidget(time_, 0, 3);
  layout->addWidget(stage_, 1, 0, 1, 4);
  layout->addWidget(log_, 2, 0, 1, 4);
  layout->setColumnStretch(2, 1);
  layout->setRowStretch(2, 1);

  connect(controller, &RunController::progressed, this, &RunPanel::onProgress);
  connect(controller, &RunController::started, this, [this] {
    progress_->setValue(0);
    stage_->setText(tr("Starting…"));
    time_->clear();
  });
  connect(controller, &RunController::finished, this, [this](const RunRecord& record) {
    progress_->setValue(progress_->maximum());
    stage_->setText(tr("Finished %1").arg(record.label));
    time_->setText(formatDuration(record.wall_time_s));
  });
  connect(controller, &RunController::failed, this, [this] { stopped(tr("Failed")); });
  connect(controller, &RunController::cancelled, this, [this] { stopped(tr("Cancelled")); });
}

void RunPanel::follow(StudyRunner* study) {
  connect(study, &StudyRunner::progressed, this, &RunPanel::onProgress);
  connect(study, &StudyRunner::started, this, [this](int cases) {
    progress_->setValue(0);
    stage_->setText(tr("Starting a study of %1…").arg(counted(cases, tr("case"), tr("cases"))));
    time_->clear();
  });
  connect(study, &StudyRunner::finished, this, [this](int succeeded, int failed) {
    progress_->setValue(progress_->maximum());
    stage_->setText(tr("Study finished: %1 succeeded, %2 failed").arg(succeeded).arg(failed));
  });
  connect(study, &StudyRunner::cancelled, this, [this] { stopped(tr("Study cancelled")); });
}

void RunPanel::stopped(const QString& stage) {
  // A stopped run has no progress and no time left: the bar and the estimate must not stay behind.
  progress_->setValue(0);
  stage_->setText(stage);
  time_->clear();
}

void RunPanel::onProgress(double fraction, const QString& stage, double elapsed_s, double remaining_s) {
  progress_->setValue(static_cast<int>(std::lround(fraction * progress_->maximum())));
  stage_->setText(stage);
  QString text = tr("elapsed %1").arg(formatDuration(elapsed_s));
  if (remaining_s >= 0.0) text += tr(", about %1 left").arg(formatDuration(remaining_s));
  time_->setText(text);
}

void RunPanel::log(Level level, const QString& text) {
  const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"));
  QString color;
  QString prefix;
  if (level == Level::Warning) {
    color = QStringLiteral("#d08000");
    prefix = tr("warning: ");
  } else if (level == Level::Error) {
    color = QStringLiteral("#d62728");
    prefix = tr("error: ");
  }
  QString html = (prefix + text).toHtmlEscaped();
  html.replace('\n', QStringLiteral("<br>&nbsp;&nbsp;"));
  if (!color.isEmpty()) html = QStringLiteral("<span style='color:%1'>%2</span>").arg(color, html);
  appending_ = true;
  log_->appendHtml(QStringLiteral("<span style='color:gray'>%1</span> %2").arg(stamp, html));
  QScrollBar* bar = log_->verticalScrollBar();
  if (follow_log_) bar->setValue(bar->maximum());
  appending_ = false;
}

}  // namespace maris::ui
