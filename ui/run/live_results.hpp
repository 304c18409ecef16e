// Shows a run's partial results while it goes, at the rate each view can afford, without blocking
// the GUI thread for long (issue: ~50 ms). The plots take every update (the run controller already
// throttles them to one per partial interval, only the visible tab redraws, and the replot is
// queued to its own event-loop turn). The 3D view costs more: its actors are rebuilt in a later
// event-loop turn than the plots (so the two never add up to one stall), and it is redrawn at
// most once per interval, that interval being the larger of a floor (1 s) and 10 × the last paint's cost, so 3D redraws never
// take more than ~10 % of the GUI thread; a hidden 3D view is not redrawn at all. The finished run
// is shown by the caller as usual; a deferred 3D update still pending then is dropped.
#pragma once

#include <QElapsedTimer>
#include <QObject>

#include "run/run_controller.hpp"

namespace maris::ui {

class PlotPanel;
class SceneView;

class LiveResults : public QObject {
  Q_OBJECT
 public:
  LiveResults(PlotPanel* plots, SceneView* view, QObject* parent = nullptr);

  // Shows `controller`'s partial results; stops when its run ends.
  void follow(RunController* controller);
  // A partial result of the running run.
  void show(ResultsPtr partial);
  // A new run begins: its first partial result redraws the 3D view at once.
  void restart();
  // The run ended: a 3D update not yet made is dropped (the finished results replace it).
  void stop();

  // The 3D view's minimum interval between live redraws (the floor of the adaptive interval).
  void setMinimumViewInterval(double milliseconds) { min_view_interval_ms_ = milliseconds; }
  double viewInterval() const;

  struct Stats {
    int plot_updates = 0;
    int view_updates = 0;
    double slowest_plot_update_ms = 0.0;  // PlotPanel::showResults in the GUI thread
    double slowest_view_update_ms = 0.0;  // SceneView::showResults (actors rebuilt), paint excluded
  };
  const Stats& stats() const { return stats_; }

 private:
  void showInView();

  PlotPanel* plots_;
  SceneView* view_;
  QElapsedTimer since_view_;
  double min_view_interval_ms_ = 1000.0;
  ResultsPtr pending_view_;  // waiting for its own event-loop turn
  Stats stats_;
};

}  // namespace maris::ui
