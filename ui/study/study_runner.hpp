// Runs the cases of a study on a pool of worker threads (a QThreadPool of its own, one case per
// thread at a time). Each case goes through runCaught, the seam the single run uses, with a
// RunContext that shares one cancel flag: cancel() stops the running cases at the solver's next
// poll and the queued ones before they start. Progress is reported like a single run's (fraction,
// stage, elapsed, remaining), so the run panel shows either. A failed case is reported and the
// study goes on. The destructor cancels and waits for the pool.
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include <QElapsedTimer>
#include <QObject>
#include <QThreadPool>

#include "run/run_controller.hpp"

namespace maris::ui {

class StudyRunner : public QObject {
  Q_OBJECT
 public:
  explicit StudyRunner(QObject* parent = nullptr);
  ~StudyRunner() override;

  // Runs every scenario of `cases` (index = position). `threads` <= 0: one per hardware thread.
  // False (nothing started) while a study runs or when there are no cases.
  bool start(const SceneDefinition& scene, std::vector<Scenario> cases, int threads = 0);
  void cancel();
  bool isRunning() const { return running_; }
  int threadCount() const { return pool_.maxThreadCount(); }
  int caseCount() const { return static_cast<int>(fraction_.size()); }
  // Seconds from the last cancel() until the last running case stopped, measured in the worker
  // threads (negative before any cancel).
  double lastCancelLatency() const { return last_cancel_latency_s_; }

 signals:
  void started(int cases);
  void caseFinished(int index, maris::ui::ResultsPtr results, double wall_time_s);
  void caseFailed(int index, const QString& message);
  // As RunController::progressed: remaining_s < 0 while no estimate is possible.
  void progressed(double fraction, const QString& stage, double elapsed_s, double remaining_s);
  void finished(int succeeded, int failed);  // every case ran (or failed)
  void cancelled();                          // every worker has stopped
  void runningChanged(bool running);

 private:
  enum class Ending { Finished, Failed, Stopped };
  void onCaseProgress(int index, double fraction, const QString& stage);
  void onCaseEnded(int index, Ending ending, qint64 stopped_ns);
  void emitProgress(const QString& stage);

  QThreadPool pool_;
  std::shared_ptr<std::atomic<bool>> cancel_flag_;
  bool running_ = false;
  std::vector<double> fraction_;  // per case, 0 … 1 (1 once it ended)
  std::vector<bool> started_case_, ended_case_;
  int ended_ = 0, succeeded_ = 0, failed_ = 0, active_ = 0;
  QElapsedTimer clock_;
  // The study's pace over recent cases. Fed the highest fraction reached so far: a case's own fraction counts
  // from zero again at each of its stages, which must not read as the whole study starting over.
  TimeLeftEstimate time_left_;
  double fraction_reached_ = 0.0;
  qint64 cancel_requested_ns_ = 0, last_stop_ns_ = 0;
  double last_cancel_latency_s_ = -1.0;
};

}  // namespace maris::ui
