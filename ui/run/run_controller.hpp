// Runs scenarios off the GUI thread (style.md §13). The controller owns a QThread and a worker
// living in it; start() copies the validated scenario and its scene into a job, the worker runs
// maris::runScenario with a RunContext whose progress callback and partial-results sink emit
// queued signals, and the finished Results cross back once as a shared_ptr<const Results>.
// cancel() sets a std::atomic<bool> the solver polls; the destructor cancels, quits and waits.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QThread>

#include "core/scene.hpp"
#include "run/time_left.hpp"

namespace maris::ui {

using ResultsPtr = std::shared_ptr<const Results>;

// A finished run, kept for plots, overlays and exports.
struct RunRecord {
  quint64 id = 0;
  Scenario scenario;     // exactly what ran
  ResultsPtr results;
  double wall_time_s = 0.0;
  std::chrono::system_clock::time_point started_at;  // when the run was started (summary.json's started_at)
  QString label;         // "run 3" plus what differs from the run before ("segment count = 100")
};

// Nanoseconds of std::chrono::steady_clock: when a cancel was asked for and when a solver stopped.
qint64 steadyNanoseconds();

// What one run through runScenario gave: results, or the failure in words, or a cancellation.
struct RunOutcome {
  ResultsPtr results;  // set when the run finished
  QString error;       // set when it failed (the engine's message, as the run log shows it)
  bool cancelled = false;
};
// Runs `scenario` through maris::runScenario and turns every engine exception into an outcome. The
// single run (RunWorker) and each case of a study (StudyRunner) go through here, so both report alike.
RunOutcome runCaught(const SceneDefinition& scene, const Scenario& scenario, RunContext& context);

// What the worker runs; owned by the job, so the GUI may edit its own scenario meanwhile.
struct RunJob {
  quint64 id = 0;
  SceneDefinition scene;
  Scenario scenario;
  std::shared_ptr<std::atomic<bool>> cancel;
  double partial_interval_s = 0.25;
};

class RunWorker : public QObject {
  Q_OBJECT
 public:
  void run(const RunJob& job);  // called in the worker thread

 signals:
  void progressed(quint64 run, double fraction, const QString& stage);
  void partial(quint64 run, maris::ui::ResultsPtr results);
  void finished(quint64 run, maris::ui::ResultsPtr results);
  void failed(quint64 run, const QString& message);
  void cancelled(quint64 run, qint64 stopped_ns);  // steady-clock time the solver stopped
};

class RunController : public QObject {
  Q_OBJECT
 public:
  explicit RunController(QObject* parent = nullptr);
  ~RunController() override;

  bool isRunning() const { return running_; }
  // Starts a run; returns its id, or 0 when a run is still going (the caller disables Run then).
  quint64 start(const SceneDefinition& scene, const Scenario& scenario);
  void cancel();
  // Seconds from the last cancel() until the solver stopped, measured in the worker thread
  // (negative before any cancel).
  double lastCancelLatency() const { return last_cancel_latency_s_; }
  // Seconds from the last cancel() until the GUI thread heard of it (adds event-queue delay).
  double lastCancelAcknowledgeLatency() const { return last_cancel_ack_s_; }
  double elapsedSeconds() const { return running_ ? clock_.elapsed() / 1000.0 : 0.0; }
  // Minimum wall time between partial results sent to the GUI.
  void setPartialInterval(double seconds) { partial_interval_s_ = seconds; }

 signals:
  void started(quint64 run);
  // remaining_s < 0 when no estimate is possible yet (TimeLeftEstimate: from the solver's recent pace in its stage).
  void progressed(double fraction, const QString& stage, double elapsed_s, double remaining_s);
  void partialResults(maris::ui::ResultsPtr results);
  void finished(const maris::ui::RunRecord& record);
  void failed(const QString& message);
  void cancelled();
  void runningChanged(bool running);

 private:
  void onProgress(quint64 run, double fraction, const QString& stage);
  void onPartial(quint64 run, ResultsPtr results);
  void onFinished(quint64 run, ResultsPtr results);
  void onFailed(quint64 run, const QString& message);
  void onCancelled(quint64 run, qint64 stopped_ns);
  void setRunning(bool running);

  QThread thread_;
  RunWorker* worker_;
  bool running_ = false;
  quint64 current_ = 0;
  quint64 next_id_ = 1;
  Scenario current_scenario_;
  std::shared_ptr<std::atomic<bool>> cancel_flag_;
  QElapsedTimer clock_;
  TimeLeftEstimate time_left_;
  std::chrono::system_clock::time_point started_at_;
  qint64 cancel_requested_ns_ = 0;
  double last_cancel_latency_s_ = -1.0;
  double last_cancel_ack_s_ = -1.0;
  double partial_interval_s_ = 0.25;
};

}  // namespace maris::ui

Q_DECLARE_METATYPE(maris::ui::ResultsPtr)
Q_DECLARE_METATYPE(maris::ui::RunRecord)
