// No vtk_glew.h here: the VTK headers used below need no GL declarations, and the GL constants
// (GL_LEQUAL, GL_DRAW_FRAMEBUFFER, ...) come from Qt's <qopengl.h>, which must not follow GLEW.
#include "view3d/vtk_gl_widget.hpp"

#include <cstring>

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <qopengl.h>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

namespace maris::ui {

VtkGlWidget::VtkGlWidget(QWidget* parent)
    : QOpenGLWidget(parent), window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      renderer_(vtkSmartPointer<vtkRenderer>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New()) {
  // VTK's OpenGL2 backend needs a 3.2 core context.
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setSamples(0);
  setFormat(format);
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(false);

  window_->AddRenderer(renderer_);
  window_->SetReadyForRendering(false);
  window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &VtkGlWidget::onMakeCurrent);
  window_->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &VtkGlWidget::onIsCurrent);
  interactor_->SetRenderWindow(window_);
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor_->SetInteractorStyle(style);
  // The interactor asks for a repaint instead of rendering outside paintGL.
  interactor_->EnableRenderOff();
  interactor_->AddObserver(vtkCommand::RenderEvent, this, &VtkGlWidget::onMakeCurrent);
  interactor_->Initialize();
}

vtkRenderer* VtkGlWidget::renderer() const { return renderer_; }
vtkGenericOpenGLRenderWindow* VtkGlWidget::renderWindow() const { return window_; }
vtkGenericRenderWindowInteractor* VtkGlWidget::interactor() const { return interactor_; }

VtkGlWidget::~VtkGlWidget() {
  QObject::disconnect(context_teardown_);
  makeCurrent();
  releaseGraphics();
  doneCurrent();
  window_->RemoveAllObservers();
  interactor_->RemoveAllObservers();
}

void VtkGlWidget::onMakeCurrent(vtkObject* caller, unsigned long event, void*) {
  if (event == vtkCommand::RenderEvent && caller == interactor_.Get()) {
    update();
    return;
  }
  // Only the context: Qt's makeCurrent() would also rebind the widget's framebuffer under VTK.
  if (initialized_ && context() && QOpenGLContext::currentContext() != context()) makeCurrent();
}

void VtkGlWidget::onIsCurrent(vtkObject*, unsigned long, void* call_data) {
  auto* current = static_cast<bool*>(call_data);
  *current = initialized_ && context() && QOpenGLContext::currentContext() == context();
}

void VtkGlWidget::releaseGraphics() {
  if (!initialized_) return;
  window_->ReleaseGraphicsResources(window_);
  initialized_ = false;
}

void VtkGlWidget::initializeGL() {
  // The context goes away when the widget moves to another window: free VTK's GL objects first.
  // Disconnected in the destructor: QOpenGLWidget's own destructor emits it after ours has run.
  QObject::disconnect(context_teardown_);
  context_teardown_ = connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
    makeCurrent();
    releaseGraphics();
    doneCurrent();
  });
  window_->SetOwnContext(false);
  window_->SetFrameBlitModeToNoBlit();
  window_->SetIsCurrent(true);
  window_->SetSupportsOpenGL(true);
  window_->SetIsDirect(true);
  window_->SetForceMaximumHardwareLineWidth(1);
  window_->SetAlphaBitPlanes(1);  // depth peeling of translucent surfaces needs an alpha channel
  window_->SetMultiSamples(0);
  window_->SetMapped(true);
  initialized_ = true;
  window_->OpenGLInitContext();
  const qreal dpr = devicePixelRatioF();
  window_->SetSize(static_cast<int>(width() * dpr), static_cast<int>(height() * dpr));
}

void VtkGlWidget::resizeGL(int w, int h) {
  const qreal dpr = devicePixelRatioF();
  const int pw = static_cast<int>(w * dpr), ph = static_cast<int>(h * dpr);
  window_->SetSize(pw, ph);
  interactor_->SetSize(pw, ph);
}

void VtkGlWidget::renderVtk() {
  vtkOpenGLState* state = window_->GetState();
  state->Reset();
  state->Push();
  // Qt leaves GL_LESS; VTK expects GL_LEQUAL.
  state->vtkglDepthFunc(GL_LEQUAL);
  window_->SetReadyForRendering(true);
  window_->Render();
  window_->SetReadyForRendering(false);
  state->Pop();
}

void VtkGlWidget::paintGL() {
  if (!initialized_) return;
  QElapsedTimer clock;
  clock.start();
  renderVtk();
  const int* size = window_->GetSize();
  vtkOpenGLState* state = window_->GetState();
  state->PushDrawFramebufferBinding();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  state->vtkglViewport(0, 0, size[0], size[1]);
  state->vtkglScissor(0, 0, size[0], size[1]);
  window_->BlitDisplayFramebuffer(0, 0, 0, size[0], size[1], 0, 0, size[0], size[1], GL_COLOR_BUFFER_BIT,
                                  GL_NEAREST);
  // Translucent planes leave alpha < 1 in VTK's image; Qt would blend the widget with what lies
  // behind it and shift the colours. The widget is opaque: set alpha to 1 everywhere.
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->PopDrawFramebufferBinding();
  context()->functions()->glFinish();  // the clock must see the renderer's work, not its queueing
  last_paint_ms_ = clock.nsecsElapsed() * 1e-6;
  ++paint_count_;
}

QImage VtkGlWidget::renderImage(int width_px, int height_px) {
  if (!initialized_ || width_px <= 0 || height_px <= 0) return {};
  makeCurrent();
  const int old_w = window_->GetSize()[0], old_h = window_->GetSize()[1];
  window_->SetSize(width_px, height_px);
  renderVtk();
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  window_->SetReadyForRendering(true);
  const int status = window_->GetRGBACharPixelData(0, 0, width_px - 1, height_px - 1, 1, pixels);
  window_->SetReadyForRendering(false);
  window_->SetSize(old_w, old_h);
  doneCurrent();
  update();
  if (status == VTK_ERROR || pixels->GetNumberOfValues() < static_cast<vtkIdType>(width_px) * height_px * 4) return {};
  // OpenGL rows run bottom-up.
  QImage image(width_px, height_px, QImage::Format_RGBA8888);
  const unsigned char* src = pixels->GetPointer(0);
  for (int y = 0; y < height_px; ++y)
    std::memcpy(image.scanLine(height_px - 1 - y), src + static_cast<std::size_t>(y) * width_px * 4,
                static_cast<std::size_t>(width_px) * 4);
  return image.convertToFormat(QImage::Format_RGB32);
}

void VtkGlWidget::forwardMouse(QMouseEvent* event, unsigned long vtk_event) {
  const qreal dpr = devicePixelRatioF();
  const QPointF p = event->position() * dpr;
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x()), static_cast<int>(p.y()),
                                        (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                        (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
  interactor_->InvokeEvent(vtk_event, event);
}

void VtkGlWidget::mousePressEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton: forwardMouse(event, vtkCommand::LeftButtonPressEvent); break;
    case Qt::MiddleButton: forwardMouse(event, vtkCommand::MiddleButtonPressEvent); break;
    case Qt::RightButton: forwardMouse(event, vtkCommand::RightButtonPressEvent); break;
    default: break;
  }
}

void VtkGlWidget::mouseReleaseEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton: forwardMouse(event, vtkCommand::LeftButtonReleaseEvent); break;
    case Qt::MiddleButton: forwardMouse(event, vtkCommand::MiddleButtonReleaseEvent); break;
    case Qt::RightButton: forwardMouse(event, vtkCommand::RightButtonReleaseEvent); break;
    default: break;
  }
}

void VtkGlWidget::mouseMoveEvent(QMouseEvent* event) { forwardMouse(event, vtkCommand::MouseMoveEvent); }

void VtkGlWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  // A double click resets the view to show everything.
  if (event->button() == Qt::LeftButton) {
    renderer_->ResetCamera();
    update();
  }
}

void VtkGlWidget::wheelEvent(QWheelEvent* event) {
  const qreal dpr = devicePixelRatioF();
  const QPointF p = event->position() * dpr;
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x()), static_cast<int>(p.y()), 0, 0);
  const int delta = event->angleDelta().y();
  if (delta > 0) interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
  if (delta < 0) interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
  event->accept();
}

}  // namespace maris::ui
