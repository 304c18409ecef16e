#include "study/study_runner.hpp"

#include <algorithm>
#include <numeric>
#include <thread>

#include <QMetaObject>
#include <QRunnable>

#include "counted.hpp"

namespace maris::ui {

StudyRunner::StudyRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<ResultsPtr>();
  pool_.setObjectName(QStringLiteral("maris-study"));
}

StudyRunner::~StudyRunner() {
  if (cancel_flag_) cancel_flag_->store(true);
  pool_.clear();  // queued cases never start
  pool_.waitForDone();
}

bool StudyRunner::start(const SceneDefinition& scene, std::vector<Scenario> cases, int threads) {
  if (running_ || cases.empty()) return false;
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  pool_.setMaxThreadCount(std::clamp(threads > 0 ? threads : hardware, 1, static_cast<int>(cases.size())));
  cancel_flag_ = std::make_shared<std::atomic<bool>>(false);
  fraction_.assign(cases.size(), 0.0);
  started_case_.assign(cases.size(), false);
  ended_case_.assign(cases.size(), false);
  ended_ = succeeded_ = failed_ = active_ = 0;
  last_stop_ns_ = 0;
  clock_.start();
  time_left_.restart();
  fraction_reached_ = 0.0;
  running_ = true;
  emit runningChanged(true);
  emit started(static_cast<int>(cases.size()));
  emitProgress(tr("Starting %1…").arg(counted(static_cast<int>(cases.size()), tr("case"), tr("cases"))));
  // Shared by the tasks; each copies nothing but its index.
  auto shared_scene = std::make_shared<const SceneDefinition>(scene);
  auto shared_cases = std::make_shared<const std::vector<Scenario>>(std::move(cases));
  for (int index = 0; index < static_cast<int>(shared_cases->size()); ++index) {
    pool_.start(QRunnable::create([this, index, shared_scene, shared_cases, flag = cancel_flag_] {
      if (flag->load()) {
        QMetaObject::invokeMethod(this, [this, index, stopped = steadyNanoseconds()] {
          onCaseEnded(index, Ending::Stopped, stopped);
        }, Qt::QueuedConnection);
        return;
      }
      QMetaObject::invokeMethod(this, [this, index] { onCaseProgress(index, 0.0, QString()); }, Qt::QueuedConnection);
      RunContext context([this, index](double fraction, const std::string& stage) {
                           QMetaObject::invokeMethod(this, [this, index, fraction, s = QString::fromStdString(stage)] {
                             onCaseProgress(index, fraction, s);
                           }, Qt::QueuedConnection);
                         },
                         flag.get());
      QElapsedTimer wall;
      wall.start();
      RunOutcome outcome = runCaught(*shared_scene, (*shared_cases)[index], context);
      const double wall_s = wall.elapsed() / 1000.0;
      const qint64 stopped = steadyNanoseconds();
      QMetaObject::invokeMethod(this, [this, index, outcome = std::move(outcome), wall_s, stopped] {
        if (outcome.results) {
          emit caseFinished(index, outcome.results, wall_s);
          onCaseEnded(index, Ending::Finished, stopped);
        } else if (outcome.cancelled) {
          onCaseEnded(index, Ending::Stopped, stopped);
        } else {
          emit caseFailed(index, outcome.error);
          onCaseEnded(index, Ending::Failed, stopped);
        }
      }, Qt::QueuedConnection);
    }));
  }
  return true;
}

void StudyRunner::cancel() {
  if (!running_ || !cancel_flag_ || cancel_flag_->load()) return;
  cancel_requested_ns_ = steadyNanoseconds();
  cancel_flag_->store(true);
  // Queued cases stay in the pool: each sees the flag and reports itself stopped in microseconds,
  // so every case ends exactly once and the study is over when all have.
  emitProgress(tr("Cancelling…"));
}

void StudyRunner::onCaseProgress(int index, double fraction, const QString& stage) {
  if (!running_ || index < 0 || index >= static_cast<int>(fraction_.size()) || ended_case_[index]) return;
  if (!started_case_[index]) {
    started_case_[index] = true;
    ++active_;
  }
  fraction_[index] = std::clamp(fraction, 0.0, 1.0);
  if (cancel_flag_->load()) return;
  emitProgress(stage.isEmpty() ? QString() : tr("case %1: %2").arg(index + 1).arg(stage));
}

void StudyRunner::onCaseEnded(int index, Ending ending, qint64 stopped_ns) {
  if (!running_ || index < 0 || index >= static_cast<int>(fraction_.size()) || ended_case_[index]) return;
  ended_case_[index] = true;
  ++ended_;
  if (started_case_[index]) --active_;
  fraction_[index] = 1.0;
  if (ending == Ending::Finished) ++succeeded_;
  if (ending == Ending::Failed) ++failed_;
  last_stop_ns_ = std::max(last_stop_ns_, stopped_ns);
  const bool cancelling = cancel_flag_->load();
  if (ended_ < static_cast<int>(fraction_.size())) {
    if (!cancelling) emitProgress(QString());
    return;
  }
  running_ = false;
  if (cancelling) {
    last_cancel_latency_s_ = std::max<qint64>(0, last_stop_ns_ - cancel_requested_ns_) * 1e-9;
    emit runningChanged(false);
    emit cancelled();
  } else {
    emitProgress(QString());
    emit runningChanged(false);
    emit finished(succeeded_, failed_);
  }
}

void StudyRunner::emitProgress(const QString& stage) {
  const int total = static_cast<int>(fraction_.size());
  const double sum = std::accumulate(fraction_.begin(), fraction_.end(), 0.0);
  const double fraction = total ? sum / total : 0.0;
  const double elapsed = clock_.elapsed() / 1000.0;
  fraction_reached_ = std::max(fraction_reached_, fraction);
  const double remaining = time_left_.update(elapsed, fraction_reached_, QStringLiteral("cases"));
  QString text = tr("%1 of %2 cases done, %3 running").arg(ended_).arg(total).arg(active_);
  if (failed_ > 0) text += tr(", %n failed", nullptr, failed_);
  if (!stage.isEmpty()) text += QStringLiteral(" — ") + stage;
  emit progressed(fraction, text, elapsed, remaining);
}

}  // namespace maris::ui
