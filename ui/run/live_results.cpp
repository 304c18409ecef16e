#include "run/live_results.hpp"

#include <algorithm>

#include "plots/plot_panel.hpp"
#include "view3d/scene_view.hpp"
#include "view3d/vtk_gl_widget.hpp"

namespace maris::ui {

LiveResults::LiveResults(PlotPanel* plots, SceneView* view, QObject* parent)
    : QObject(parent), plots_(plots), view_(view) {}

void LiveResults::restart() { since_view_.invalidate(); }

double LiveResults::viewInterval() const {
  return std::max(min_view_interval_ms_, 10.0 * view_->glWidget()->lastPaintMilliseconds());
}

void LiveResults::show(ResultsPtr partial) {
  QElapsedTimer clock;
  clock.start();
  plots_->showResults(partial, tr("running"));
  stats_.slowest_plot_update_ms = std::max(stats_.slowest_plot_update_ms, clock.nsecsElapsed() * 1e-6);
  ++stats_.plot_updates;
  if (!view_->isVisible()) return;
  if (since_view_.isValid() && since_view_.elapsed() < viewInterval()) return;
  clock.restart();
  view_->showResults(std::move(partial));
  stats_.slowest_view_update_ms = std::max(stats_.slowest_view_update_ms, clock.nsecsElapsed() * 1e-6);
  ++stats_.view_updates;
  since_view_.start();
}

}  // namespace maris::ui
