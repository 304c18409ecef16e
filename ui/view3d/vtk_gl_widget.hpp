// A Qt 6 widget showing a VTK renderer. Debian's VTK Qt module is built for Qt 5, so this is the
// bridge: a QOpenGLWidget (OpenGL 3.2 core) owns a vtkGenericOpenGLRenderWindow that renders into
// its own framebuffers inside Qt's context; paintGL blits VTK's display framebuffer into the
// widget's framebuffer. Mouse and wheel events go to a vtkGenericRenderWindowInteractor with a
// trackball-camera style (left: rotate, middle/shift+left: pan, right/wheel: zoom).
#pragma once

#include <QImage>
#include <QOpenGLWidget>

#include <vtkSmartPointer.h>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;
class vtkRenderer;

namespace maris::ui {

class VtkGlWidget : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkGlWidget(QWidget* parent = nullptr);
  ~VtkGlWidget() override;

  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkGenericRenderWindowInteractor* interactor() const;

  // Renders the current scene at width × height pixels (any size, independent of the widget's)
  // and returns it; a null image if OpenGL is not initialised (widget never shown).
  QImage renderImage(int width_px, int height_px);

  // Wall time of the last paint (VTK render and blit) in milliseconds: what a redraw costs the GUI
  // thread (with a software OpenGL renderer, far more than everything else the GUI does).
  double lastPaintMilliseconds() const { return last_paint_ms_; }
  int paintCount() const { return paint_count_; }

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

 private:
  void forwardMouse(QMouseEvent* event, unsigned long vtk_event);
  void onMakeCurrent(vtkObject*, unsigned long, void*);
  void onIsCurrent(vtkObject*, unsigned long, void* call_data);
  void releaseGraphics();
  void renderVtk();

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  QMetaObject::Connection context_teardown_;  // context aboutToBeDestroyed -> release VTK's GL objects
  bool initialized_ = false;
  double last_paint_ms_ = 0.0;
  int paint_count_ = 0;
};

}  // namespace maris::ui
