#include "run/live_results.hpp"

#include <algorithm>

#include "plots/plot_panel.hpp"
#include "view3d/scene_view.hpp"
#include "view3d/vtk_gl_widget.hpp"

namespace maris::ui {

LiveResults::LiveResults(PlotPanel* plots, SceneView* view, QObject* parent)
    : QObject(parent), plots_(plots), view_(view) {}

void LiveResults::follow(RunController* controller) {
  connect(controller, &RunController::partialResults, this, &LiveResults::show);
  connect(controller, &RunController::runningChanged, this, [this](bool running) {
    if (!running) stop();
  });
}

void LiveResults::restart() {
  since_view_.invalidate();
  pending_view_.reset();
}

void LiveResults::stop() { pending_view_.reset(); }

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
  since_view_.start();
  const bool queued = pending_view_ != nullptr;
  pending_view_ = std::move(partial);
  if (!queued) QMetaObject::invokeMethod(this, &LiveResults::showInView, Qt::QueuedConnection);
}

void LiveResults::showInView() {
  if (!pending_view_) return;
  QElapsedTimer clock;
  clock.start();
  view_->showResults(std::move(pending_view_));
  pending_view_.reset();
  stats_.slowest_view_update_ms = std::max(stats_.slowest_view_update_ms, clock.nsecsElapsed() * 1e-6);
  ++stats_.view_updates;
}

}  // namespace maris::ui
