// The 3D tab: draws a run's View3D (shapes per animation frame, colour map with a colour bar,
// still-water and sea-bed planes), an axes triad, a time slider with play/pause, reset camera and
// PNG export at a chosen resolution, and a "Colours" control (map, automatic or fixed range),
// remembered per coloured quantity (across sessions, QSettings). Results of a model of another size or place
// (a new scenario, another length) frame the camera anew; results of the same model (a rerun, live partial
// results) keep the user's view. Until the user moves the camera, a resized view is framed anew too.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <QImage>
#include <QWidget>

#include <vtkSmartPointer.h>

#include "core/results.hpp"
#include "view3d/color_maps.hpp"
#include "view3d/shape_actors.hpp"

class QComboBox;
class QLabel;
class QResizeEvent;
class QSlider;
class QTimer;
class QToolButton;
class vtkActor;
class vtkColorTransferFunction;
class vtkOrientationMarkerWidget;
class vtkTextActor;

namespace maris::ui {

class ColorBarActor;
class ColorMapControl;
class VtkGlWidget;

class SceneView : public QWidget {
  Q_OBJECT
 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  // A run's results, finished or partial (a live run's): the frame shown stays; the camera is placed
  // anew when the model's bounds differ from those it was framed for (framesAnew).
  void showResults(std::shared_ptr<const Results> results);
  // Shows no 3D view, saying `why` (empty: that none was run yet).
  void clear(const QString& why = {});

  int frameCount() const;
  int currentFrame() const { return frame_; }
  double frameTime(int index) const;  // [s] (or mode phase) of frame `index`; 0 outside [0, frameCount())
  void setFrame(int index);
  void setPlaying(bool playing);
  bool isPlaying() const;
  void resetCamera();

  // The current view rendered at width × height pixels.
  QImage renderImage(int width_px, int height_px);
  // Asks for a resolution and a file, then saves a PNG.
  void exportPngInteractive();

  // Colour map and range of the coloured quantity (kept for that quantity's later results).
  void setColorSettings(const ColorSettings& settings);
  const ColorSettings& colorSettings() const { return color_settings_; }
  // The range the colours and the colour bar span now (the data's or the user's).
  std::pair<double, double> colorRange() const;
  ColorMapControl* colorControl() const { return color_control_; }
  // Displacements from the reference shape (View3D::reference, drawn as a ghost) drawn × 1, 10 or 100.
  void setMagnification(double factor);
  double magnification() const { return magnification_; }
  QComboBox* magnificationBox() const { return magnify_; }
  // What the view states about its drawing (magnification, drawn thickness), shown in its caption.
  QString drawingNotes() const;
  // The caption at the view's top left: the frame's time or label, then the drawing notes.
  QString captionText() const;

  VtkGlWidget* glWidget() const { return gl_; }
  // Where the model's bounding box (and the water and sea-bed levels drawn with it) falls in the view:
  // {x_min, x_max, y_min, y_max} of its eight projected corners in normalised view coordinates, the view
  // spanning [-1, 1] in each direction. For tests of the framing.
  std::array<double, 4> projectedModelExtent() const;
  // Where the colour bar was last placed, in fractions of the view (from its left and its bottom): the left edge
  // of the bar as a whole (its title's or its strip's, whichever reaches further left), of its strip (the labels
  // are right of it), and the bottom of its title (above the strip). A 2-D section is framed left of the strip, and
  // left of the title too where it reaches up beside it (resetCamera).
  struct ColorBarExtent {
    double left = 0.8, strip_left = 0.8, title_bottom = 0.84;
  };
  ColorBarExtent colorBarExtent() const { return color_bar_; }
  // Number of model actors in the current frame (planes, colour bar and triad not counted).
  int modelActorCount() const { return static_cast<int>(frame_actors_.size()); }

 signals:
  void message(const QString& text);

 protected:
  void changeEvent(QEvent* event) override;  // a new palette (theme) recolours background and text
  void resizeEvent(QResizeEvent* event) override;  // framed anew while the user has not moved the camera

 private:
  void applyPaletteColors();
  void rebuildStatic();
  void applyColorSettings();
  void placeColorBar();  // keeps the bar's title and labels inside the view with a margin
  void drawFrame();
  void updateTimeLabel();
  Bounds3D framingBounds() const;  // the model and the water and sea-bed planes drawn with it

  VtkGlWidget* gl_;
  QSlider* slider_;
  QToolButton* play_;
  QComboBox* magnify_;
  QLabel* time_;
  QLabel* empty_;
  QTimer* timer_;
  ColorMapControl* color_control_;
  std::shared_ptr<const Results> results_;
  int frame_ = 0;
  bool camera_placed_ = false;
  bool user_moved_camera_ = false;  // since the last automatic framing
  Bounds3D framed_bounds_;          // what the camera was last framed for
  vtkSmartPointer<vtkColorTransferFunction> colors_;      // SI values to colours (the model)
  vtkSmartPointer<vtkColorTransferFunction> bar_colors_;  // the same in the colour bar's display unit
  vtkSmartPointer<ColorBarActor> scalar_bar_;
  vtkSmartPointer<vtkTextActor> caption_;
  vtkSmartPointer<vtkOrientationMarkerWidget> triad_;
  std::vector<vtkSmartPointer<vtkActor>> static_actors_;
  std::vector<vtkSmartPointer<vtkActor>> frame_actors_;
  double min_tube_radius_ = 0.0;
  bool have_scalars_ = false;
  ColorBarExtent color_bar_;  // colorBarExtent()
  double data_lo_ = 0.0, data_hi_ = 1.0;  // scalar range of all frames
  double frame_lo_ = 0.0, frame_hi_ = 1.0;  // scalar range of the frame shown
  double magnification_ = 1.0;
  double drawn_thickness_ratio_ = 1.0;  // drawn tube radius / real radius of the thinnest tube (≥ 1)
  int section_axis_ = -1;  // a 2-D section's normal (0 = x, 1 = y; view3d/section_view.hpp), −1 for a 3-D model
  std::string colored_quantity_;          // View3D::scalar_name of the shown results
  ColorSettings color_settings_;
  std::map<std::string, ColorSettings> color_memory_;  // by quantity; also saved with QSettings
};

}  // namespace maris::ui
