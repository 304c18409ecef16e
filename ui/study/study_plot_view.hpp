// The result plot of a study: choose a result scalar, the varied parameter on the x axis and lines
// or a heat map (offered for two parameters on a full grid); hovering names a point's case and its
// value, clicking a point (or a cell) asks to open that case's full results.
#pragma once

#include <functional>

#include <QWidget>

#include "plots/study_plot.hpp"

class QComboBox;
class QCustomPlot;
class QLabel;

namespace maris::ui {

class StudySession;

class StudyPlotView : public QWidget {
  Q_OBJECT
 public:
  explicit StudyPlotView(QWidget* parent = nullptr);

  // Shows `session`'s results (it must outlive the view or be replaced); keeps the chosen result,
  // parameter and kind when they still exist.
  void setSession(const StudySession* session);
  void refresh();

  bool hasData() const { return has_data_; }
  QCustomPlot* plot() const { return plot_; }
  const DrawnStudyPlot& drawn() const { return drawn_; }
  QComboBox* resultBox() const { return result_; }
  QComboBox* againstBox() const { return against_; }
  QComboBox* kindBox() const { return kind_; }
  QLabel* readout() const { return readout_; }
  // PNG, PDF or SVG by suffix, atomically. False if there is nothing to draw or writing failed.
  bool exportTo(const QString& file, int width_px = 1200, int height_px = 800);

 signals:
  void caseClicked(int index);

 protected:
  void changeEvent(QEvent* event) override;  // a new palette (theme) redraws

 private:
  void redraw();
  void onMouseMove(const QPointF& pixel);
  void onMousePress(const QPointF& pixel);

  const StudySession* session_ = nullptr;
  QComboBox* result_;
  QComboBox* against_;
  QComboBox* kind_;
  QCustomPlot* plot_;
  QLabel* readout_;
  DrawnStudyPlot drawn_;
  StudyPlotData data_;
  bool has_data_ = false;
  bool filling_ = false;
};

}  // namespace maris::ui
