// One plot tab: a QCustomPlot drawn from a PlotSpec and one or more runs, with zoom (wheel), pan
// (drag), double-click to fit, log-axis toggles, a zoom that survives live updates, a hover read-out of the nearest data point, and
// export of the picture (PNG/PDF/SVG) and of the data behind it (CSV with a units row).
#pragma once

#include <memory>
#include <vector>

#include <QWidget>

#include "core/results.hpp"

class QCustomPlot;
class QCPItemTracer;
class QLabel;
class QMouseEvent;

namespace maris::ui {

class PlotView : public QWidget {
  Q_OBJECT
 public:
  explicit PlotView(PlotSpec spec, QWidget* parent = nullptr);

  struct Source {
    QString label;
    std::shared_ptr<const Results> results;
  };
  // First source solid, the others overlaid. Keeps the results alive while shown. A hidden tab
  // redraws when it is shown (or asked for its data), so live updates cost one visible plot only.
  void setSources(std::vector<Source> sources);

  // A user's reference tables drawn as markers on this plot (kept across runs).
  void setReferences(std::vector<Table> references);
  const std::vector<Table>& references() const { return references_; }

  const PlotSpec& spec() const { return spec_; }
  QCustomPlot* plot() const {
    ensureDrawn();
    return plot_;
  }
  bool hasData() const {
    ensureDrawn();
    return has_data_;
  }
  // Points drawn for the first source's y columns (what the test of "expected points" reads).
  int pointCount() const;

  void setLogX(bool on);
  void setLogY(bool on);
  bool logX() const { return log_x_; }
  bool logY() const { return log_y_; }
  // Fits the axes to the data and lets later updates rescale again (Fit, double-click).
  void resetZoom();
  // True once the user zoomed or panned (or the axes' range was set from outside): redraws with new
  // data (live partial results, overlays) then keep the ranges instead of rescaling.
  bool keepsUserRange() const { return user_range_; }

  // PNG/PDF/SVG by suffix, or CSV of the first source's data. Throws std::runtime_error on failure.
  void exportTo(const QString& file, int width_px = 1200, int height_px = 800);
  QString readout() const;

 protected:
  void changeEvent(QEvent* event) override;  // a new palette (theme) redraws in its colours
  void showEvent(QShowEvent* event) override;
  bool eventFilter(QObject* watched, QEvent* event) override;  // the plot resized: its legend is placed again

 private:
  void redraw();
  void ensureDrawn() const;
  void applyAxisScales();
  void watchUserRange();
  void onMouseMove(QMouseEvent* event);

  PlotSpec spec_;
  std::vector<Source> sources_;
  std::vector<Table> references_;
  QCustomPlot* plot_;
  QLabel* readout_;
  QLabel* empty_;
  QCPItemTracer* tracer_ = nullptr;
  bool has_data_ = false;
  bool stale_ = false;  // sources changed while hidden
  bool user_range_ = false;    // the user moved the axes: do not rescale on new data
  bool setting_range_ = false;  // our own rescaling is under way (not a user's range change)
  bool log_x_;
  bool log_y_;
};

}  // namespace maris::ui
