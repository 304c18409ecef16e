#include "run/run_controller.hpp"

#include <chrono>
#include <exception>

#include "core/errors.hpp"

namespace maris::ui {

qint64 steadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void RunWorker::run(const RunJob& job) {
  const quint64 id = job.id;
  RunContext context([this, id](double fraction, const std::string& stage) {
                       emit progressed(id, fraction, QString::fromStdString(stage));
                     },
                     job.cancel.get());
  context.setPartialSink([this, id](std::shared_ptr<const Results> partial_results) {
                           emit partial(id, std::move(partial_results));
                         },
                         job.partial_interval_s);
  RunOutcome outcome = runCaught(job.scene, job.scenario, context);
  if (outcome.results)
    emit finished(id, std::move(outcome.results));
  else if (outcome.cancelled)
    emit cancelled(id, steadyNanoseconds());
  else
    emit failed(id, outcome.error);
}

RunOutcome runCaught(const SceneDefinition& scene, const Scenario& scenario, RunContext& context) {
  RunOutcome outcome;
  try {
    outcome.results = std::make_shared<const Results>(runScenario(scene, scenario, context));
  } catch (const RunCancelled&) {
    outcome.cancelled = true;
  } catch (const InputError& e) {
    outcome.error = RunWorker::tr("The scenario is invalid:\n%1").arg(QString::fromStdString(describeErrors(e.errors())));
  } catch (const SolverError& e) {
    outcome.error = RunWorker::tr("The solver failed: %1").arg(QString::fromStdString(e.what()));
  } catch (const std::exception& e) {
    outcome.error = RunWorker::tr("The run failed: %1").arg(QString::fromStdString(e.what()));
  }
  return outcome;
}

RunController::RunController(QObject* parent) : QObject(parent), worker_(new RunWorker) {
  qRegisterMetaType<ResultsPtr>();
  qRegisterMetaType<RunRecord>();
  thread_.setObjectName(QStringLiteral("maris-run"));
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &RunWorker::progressed, this, &RunController::onProgress);
  connect(worker_, &RunWorker::partial, this, &RunController::onPartial);
  connect(worker_, &RunWorker::finished, this, &RunController::onFinished);
  connect(worker_, &RunWorker::failed, this, &RunController::onFailed);
  connect(worker_, &RunWorker::cancelled, this, &RunController::onCancelled);
  thread_.start();
}

RunController::~RunController() {
  if (cancel_flag_) cancel_flag_->store(true);
  thread_.quit();
  thread_.wait();
}

quint64 RunController::start(const SceneDefinition& scene, const Scenario& scenario) {
  if (running_) return 0;
  RunJob job;
  job.id = next_id_++;
  job.scene = scene;
  job.scenario = scenario;
  job.cancel = std::make_shared<std::atomic<bool>>(false);
  job.partial_interval_s = partial_interval_s_;
  current_ = job.id;
  current_scenario_ = scenario;
  cancel_flag_ = job.cancel;
  clock_.start();
  time_left_.restart();
  started_at_ = std::chrono::system_clock::now();
  setRunning(true);
  emit started(job.id);
  QMetaObject::invokeMethod(worker_, [worker = worker_, job] { worker->run(job); }, Qt::QueuedConnection);
  return current_;
}

void RunController::cancel() {
  if (!running_ || !cancel_flag_ || cancel_flag_->load()) return;
  cancel_requested_ns_ = steadyNanoseconds();
  cancel_flag_->store(true);
}

void RunController::onProgress(quint64 run, double fraction, const QString& stage) {
  if (run != current_ || !running_) return;
  const double elapsed = clock_.elapsed() / 1000.0;
  emit progressed(fraction, stage, elapsed, time_left_.update(elapsed, fraction, stage));
}

void RunController::onPartial(quint64 run, ResultsPtr results) {
  if (run == current_ && running_ && !cancel_flag_->load()) emit partialResults(std::move(results));
}

void RunController::onFinished(quint64 run, ResultsPtr results) {
  if (run != current_) return;
  RunRecord record;
  record.id = run;
  record.scenario = std::move(current_scenario_);
  record.results = std::move(results);
  record.wall_time_s = clock_.elapsed() / 1000.0;
  record.started_at = started_at_;
  record.label = tr("run %1").arg(run);
  setRunning(false);
  emit finished(record);
}

void RunController::onFailed(quint64 run, const QString& message) {
  if (run != current_) return;
  setRunning(false);
  emit failed(message);
}

void RunController::onCancelled(quint64 run, qint64 stopped_ns) {
  if (run != current_) return;
  last_cancel_latency_s_ = (stopped_ns - cancel_requested_ns_) * 1e-9;
  last_cancel_ack_s_ = (steadyNanoseconds() - cancel_requested_ns_) * 1e-9;
  setRunning(false);
  emit cancelled();
}

void RunController::setRunning(bool running) {
  if (running_ == running) return;
  running_ = running;
  emit runningChanged(running);
}

}  // namespace maris::ui
