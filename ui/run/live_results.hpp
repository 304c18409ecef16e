// Shows a run's partial results while it goes, at the rate each view can afford. The plots take
// every update (the run controller already throttles them to one per partial interval, and only
// the visible tab redraws). The 3D view costs far more: with a software OpenGL renderer one paint
// takes ~0.1–0.2 s in the GUI thread. It is therefore redrawn at most once per interval, that
// interval being the larger of a floor (1 s) and 10 × the last paint's cost, so 3D redraws never
// take more than ~10 % of the GUI thread; a hidden 3D view is not redrawn at all. The finished run
// is shown by the caller as usual.
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

  // A partial result of the running run.
  void show(ResultsPtr partial);
  // A new run begins: its first partial result redraws the 3D view at once.
  void restart();

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
  PlotPanel* plots_;
  SceneView* view_;
  QElapsedTimer since_view_;
  double min_view_interval_ms_ = 1000.0;
  Stats stats_;
};

}  // namespace maris::ui
