// GUI-thread latency during a live run in the real main window (xvfb-run, Mesa's software OpenGL):
// the default riser scenario runs while a 5 ms heartbeat timer records the longest gap between its
// ticks, which is the longest time the GUI thread could not answer the user. A timing
// QApplication::notify names the events that took longest (what blocks), and the live path reports
// its plot, 3D-rebuild and 3D-paint times. The precise numbers go to docs/gui.md; the assertion is
// a generous bound (see kGapBoundMs) that still fails if a whole-window OpenGL recomposition or an
// unthrottled 3D paint comes back on every live update.
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <time.h>

#include <algorithm>
#include <map>
#include <string>

#include "document/scenario_document.hpp"
#include "main_window.hpp"
#include "plots/plot_panel.hpp"
#include "run/live_results.hpp"
#include "run/run_controller.hpp"
#include "scene_library.hpp"
#include "ui_test_support.hpp"
#include "view3d/scene_view.hpp"
#include "view3d/vtk_gl_widget.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

// CPU time of the calling thread: unlike wall time, not stretched by other processes.
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// An application that times every top-level event delivery and keeps the slowest per kind.
class TimingApplication : public QApplication {
 public:
  using QApplication::QApplication;
  bool notify(QObject* receiver, QEvent* event) override {
    if (depth_ > 0 || !recording_ || QThread::currentThread() != thread()) return QApplication::notify(receiver, event);
    ++depth_;
    // The receiver may delete itself (DeferredDelete): name it first.
    const std::string key = std::string(receiver->metaObject()->className()) + " event " +
                            std::to_string(static_cast<int>(event->type()));
    QElapsedTimer clock;
    clock.start();
    const double cpu_start = threadCpuMs();
    const bool result = QApplication::notify(receiver, event);
    const double ms = clock.nsecsElapsed() * 1e-6, cpu_ms = threadCpuMs() - cpu_start;
    --depth_;
    busy_ms_ += cpu_ms;
    if (ms > 1.0) timeline_.push_back({since_start_.nsecsElapsed() * 1e-6 - ms, ms, cpu_ms, key});
    {
      Kind& kind = slowest_[key];
      kind.slowest = std::max(kind.slowest, cpu_ms);
      kind.total += cpu_ms;
      ++kind.count;
    }
    return result;
  }
  void record(bool on) {
    recording_ = on;
    if (on) {
      slowest_.clear();
      busy_ms_ = 0.0;
      timeline_.clear();
      since_start_.start();
    }
  }
  void report() const {
    qInfo("  GUI-thread CPU time in event deliveries: %.0f ms", busy_ms_);
    for (const auto& [key, kind] : slowest_)
      if (kind.total > 20.0 || kind.slowest > 10.0)
        qInfo("  %s: %d deliveries, %.1f ms CPU in all, slowest %.1f ms CPU", key.c_str(), kind.count, kind.total,
              kind.slowest);
  }

 private:
  int depth_ = 0;
  bool recording_ = false;
  double busy_ms_ = 0.0;
  QElapsedTimer since_start_;
  struct Delivery {
    double start_ms, ms, cpu_ms;  // wall-clock start and length, GUI-thread CPU time
    std::string key;
  };
  std::vector<Delivery> timeline_;

 public:
  double now() const { return since_start_.nsecsElapsed() * 1e-6; }
  // Deliveries of more than 1 ms that overlap [from, to] (ms since recording began).
  void reportBetween(double from, double to) const {
    for (const auto& d : timeline_)
      if (d.start_ms + d.ms >= from && d.start_ms <= to)
        qInfo("    at %.1f ms: %s %.1f ms (%.1f ms CPU)", d.start_ms, d.key.c_str(), d.ms, d.cpu_ms);
  }
  struct Kind {
    int count = 0;
    double total = 0.0, slowest = 0.0;
  };
  std::map<std::string, Kind> slowest_;
};

// What is bounded: the GUI thread's CPU time between two turns of its event loop (two ticks of a
// 5 ms heartbeat), i.e. the longest stretch of work it does without answering the user. CPU time,
// not wall time, so that other processes on CI's 2 cores do not stretch it as much; the wall-time
// gap is reported beside it (docs/gui.md has both). The target is ~50 ms. Measured here with
// 5–9 other jobs on the 2 cores: 73–193 ms of CPU time (wall gaps 0.28–0.98 s), the longest pieces
// a replot of all points and a 3D redraw in one Mesa thread, both slowed by the shared caches.
// 250 ms, best of three runs, tolerates that load; a change that puts a whole-window OpenGL
// composition or an unthrottled 3D redraw back on every update fails it.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kGapBoundMs = 750.0;  // ASan makes Qt, VTK and the plots ~3x slower
#else
constexpr double kGapBoundMs = 250.0;
#endif

struct Probe {
  double longest_cpu_gap_ms = 0.0;  // GUI-thread CPU time between two heartbeats
  double longest_gap_ms = 0.0;
  int ticks = 0;
  std::vector<double> paints_ms;
  double wall_s = 0.0;
  double gap_end_ms = 0.0;
  double cpu_gap_end_ms = 0.0, cpu_gap_wall_ms = 0.0;  // where the longest CPU gap ended, its wall length
};

}  // namespace

class LatencyTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void theGuiThreadAnswersDuringALiveRiserRun() {
    auto library = SceneLibrary::fromEngine();
    if (!library->findExample("riser_default")) QSKIP("this build has no riser scene");
    auto* app = static_cast<TimingApplication*>(QCoreApplication::instance());
    MainWindow window(library);
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openExample(QStringLiteral("riser_default")));
#if defined(__SANITIZE_ADDRESS__)
    // Under ASan the full 24 s would take minutes; the code paths are the same.
    window.document()->edit("solver.end_time", 4.0);
#endif
    // A first run compiles Mesa's shaders (~1 s in one paint): not what a live update costs.
    QSignalSpy finished(&window, &MainWindow::runFinished);
    QVERIFY(window.startRun());
    QVERIFY(finished.wait(300000));

    // What one 3D redraw of unchanged actors costs (fastest of 5: the least disturbed by other
    // processes), wall and GUI-thread CPU time.
    VtkGlWidget* gl = window.sceneView()->glWidget();
    {
      double fastest = 1e9, fastest_cpu = 1e9;
      for (int i = 0; i < 5; ++i) {
        const double cpu = threadCpuMs();
        gl->grabFramebuffer();
        fastest_cpu = std::min(fastest_cpu, threadCpuMs() - cpu);
        fastest = std::min(fastest, gl->lastPaintMilliseconds());
      }
      qInfo("3D redraw of %d x %d device pixels, fastest of 5: %.1f ms (%.1f ms CPU)", gl->width(), gl->height(),
            fastest, fastest_cpu);
    }

    // Up to three live runs: a burst of other work on the machine may stretch one, a design that
    // blocks the GUI thread too long fails all three.
    double best_gap_ms = 1e9;
    for (int attempt = 0; attempt < 3; ++attempt) {
      Probe probe;
      QTimer heartbeat;
      QElapsedTimer since_beat, wall;
      double cpu_at_beat = -1.0, beat_at_ms = 0.0;
      int paints = gl->paintCount();
      heartbeat.setInterval(5);
      heartbeat.setTimerType(Qt::PreciseTimer);
      QObject::connect(&heartbeat, &QTimer::timeout, [&] {
        if (since_beat.isValid() && since_beat.nsecsElapsed() * 1e-6 > probe.longest_gap_ms) {
          probe.longest_gap_ms = since_beat.nsecsElapsed() * 1e-6;
          probe.gap_end_ms = app->now();
        }
        since_beat.start();
        const double cpu = threadCpuMs();
        if (cpu_at_beat >= 0.0 && cpu - cpu_at_beat > probe.longest_cpu_gap_ms) {
          probe.longest_cpu_gap_ms = cpu - cpu_at_beat;
          probe.cpu_gap_end_ms = app->now();
          probe.cpu_gap_wall_ms = app->now() - beat_at_ms;
        }
        beat_at_ms = app->now();
        cpu_at_beat = cpu;
        ++probe.ticks;
        if (gl->paintCount() != paints) {
          paints = gl->paintCount();
          probe.paints_ms.push_back(gl->lastPaintMilliseconds());
        }
      });
      app->record(true);
      wall.start();
      QVERIFY(window.startRun());
      heartbeat.start();
      QVERIFY(finished.wait(300000));
      // The finished run is drawn at full resolution after the signal: keep measuring through it.
      QTest::qWait(500);
      heartbeat.stop();
      app->record(false);
      probe.wall_s = wall.elapsed() / 1000.0;
      const std::vector<double> in_order = probe.paints_ms;
      std::sort(probe.paints_ms.begin(), probe.paints_ms.end());
      QString paint_list;
      for (double ms : in_order) paint_list += QString::number(ms, 'f', 1) + QLatin1Char(' ');
      qInfo("3D paints: %s", qPrintable(paint_list));
      qInfo("live riser_default run: %.2f s, %d heartbeats, longest GUI-thread gap %.1f ms (%.1f ms of its CPU time); %zu 3D "
            "paints (median %.1f ms, slowest %.1f ms)",
            probe.wall_s, probe.ticks, probe.longest_gap_ms, probe.longest_cpu_gap_ms, probe.paints_ms.size(),
            probe.paints_ms.empty() ? 0.0 : probe.paints_ms[probe.paints_ms.size() / 2],
            probe.paints_ms.empty() ? 0.0 : probe.paints_ms.back());
      const LiveResults::Stats& live = window.liveResults()->stats();
      qInfo("  live updates: %d of the plots (slowest %.1f ms), %d of the 3D view (slowest actor rebuild %.1f ms)",
            live.plot_updates, live.slowest_plot_update_ms, live.view_updates, live.slowest_view_update_ms);
      app->report();
      qInfo("  the longest gap:");
      app->reportBetween(probe.gap_end_ms - probe.longest_gap_ms, probe.gap_end_ms);
      qInfo("  the gap with the most GUI-thread CPU time:");
      app->reportBetween(probe.cpu_gap_end_ms - probe.cpu_gap_wall_ms, probe.cpu_gap_end_ms);
      QVERIFY(probe.ticks > 0);
      best_gap_ms = std::min(best_gap_ms, probe.longest_cpu_gap_ms);
      if (best_gap_ms < kGapBoundMs) break;
    }
    QVERIFY2(best_gap_ms < kGapBoundMs, qPrintable(QStringLiteral("GUI-thread CPU time between two heartbeats %1 ms").arg(best_gap_ms)));
  }
};

int main(int argc, char** argv) {
  // Mesa's software renderer draws in the calling thread, so a 3D paint counts in the GUI thread's
  // CPU time (with its default worker threads a paint would hide there; one thread is slower, so
  // the measured stalls are if anything longer than the application's).
  qputenv("LP_NUM_THREADS", "0");
  TimingApplication app(argc, argv);
  LatencyTest test;
  QTEST_SET_MAIN_SOURCE_PATH
  return QTest::qExec(&test, argc, argv);
}

#include "test_latency.moc"
