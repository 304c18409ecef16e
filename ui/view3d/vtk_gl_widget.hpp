// A Qt 6 widget showing a VTK renderer. Debian's VTK Qt module is built for Qt 5, so this is the
// bridge. VTK renders with its own framebuffers inside an offscreen OpenGL context of ours
// (QOpenGLContext on a QOffscreenSurface, OpenGL 3.2 core); the picture is read back into a QImage
// that a plain raster widget paints. Why not a QOpenGLWidget: a window holding one composes every
// repaint of every widget (a progress bar, a plot) through OpenGL, which with a software renderer
// cost 25–140 ms per repaint and stalled the GUI thread during live runs (docs/gui.md). Here only
// a 3D redraw touches OpenGL. Mouse and wheel events go to a vtkGenericRenderWindowInteractor with
// a trackball-camera style (left: rotate, middle/shift+left: pan, right/wheel: zoom).
#pragma once

#include <memory>

#include <QImage>
#include <QWidget>

#include <vtkSmartPointer.h>

class QOffscreenSurface;
class QOpenGLContext;
class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;
class vtkRenderer;

namespace maris::ui {

class VtkGlWidget : public QWidget {
  Q_OBJECT
 public:
  explicit VtkGlWidget(QWidget* parent = nullptr);
  ~VtkGlWidget() override;

  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkGenericRenderWindowInteractor* interactor() const;

  // The scene changed: render it anew at the next paint (the widget's repaints otherwise reuse
  // the last picture).
  void requestRender();

  // Renders the current scene at width × height pixels (any size, independent of the widget's)
  // and returns it; a null image if no OpenGL context can be made.
  QImage renderImage(int width_px, int height_px);
  // Renders the scene at the widget's size in device pixels and returns the picture (what the
  // widget shows). The size stays the same from one redraw to the next: a change of size makes VTK
  // allocate its framebuffers and depth-peeling textures anew, which with a software renderer cost
  // more than the redraw itself (docs/gui.md), so the view has one resolution, live runs included.
  QImage grabFramebuffer();

  // Gives the render window the widget's present size (otherwise set at the next paint), so that a camera
  // fitted now (vtkRenderer::ResetCamera uses the window's aspect ratio) fits the picture that will be shown.
  void matchWindowSize();

  // Wall time of the last render for the widget (VTK render and read-back) in milliseconds: what a
  // redraw costs the GUI thread (with a software OpenGL renderer, far more than anything else).
  double lastPaintMilliseconds() const { return last_paint_ms_; }
  int paintCount() const { return paint_count_; }

 signals:
  // A mouse button or the wheel went to the camera (rotate, pan, zoom).
  void cameraMovedByUser();
  // A double click: show the whole model again.
  void resetCameraRequested();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

 private:
  bool makeCurrent();
  void forwardMouse(QMouseEvent* event, unsigned long vtk_event);
  // Hands a widget position (logical pixels, y down) and the modifier keys to the interactor.
  void setEventPosition(const QPointF& position, Qt::KeyboardModifiers modifiers);
  void onMakeCurrent(vtkObject*, unsigned long, void*);
  void onIsCurrent(vtkObject*, unsigned long, void* call_data);
  QSize devicePixelSize() const;
  QImage renderAt(int width_px, int height_px);  // context current, VTK initialised

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  std::unique_ptr<QOffscreenSurface> surface_;
  std::unique_ptr<QOpenGLContext> context_;
  bool initialized_ = false;      // VTK's OpenGL state set up in our context
  bool context_failed_ = false;   // no OpenGL here: the widget says so instead of drawing
  bool stale_ = true;             // the scene changed since image_ was rendered
  QImage image_;                  // the last picture, device pixels
  double last_paint_ms_ = 0.0;
  int paint_count_ = 0;
};

}  // namespace maris::ui
