// No vtk_glew.h here: the VTK headers used below need no GL declarations, and the GL constants
// (GL_LEQUAL, ...) come from Qt's <qopengl.h>, which must not follow GLEW.
#include "view3d/vtk_gl_widget.hpp"

#include <algorithm>
#include <cstring>

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
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

namespace {
// VTK's OpenGL2 backend needs a 3.2 core context; it renders into framebuffers of its own, so the
// surface's own buffers are never drawn to.
QSurfaceFormat vtkFormat() {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setSamples(0);
  return format;
}
}  // namespace

VtkGlWidget::VtkGlWidget(QWidget* parent)
    : QWidget(parent), window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      renderer_(vtkSmartPointer<vtkRenderer>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New()) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(false);
  // Every pixel is painted from the picture: Qt need not clear the background first.
  setAttribute(Qt::WA_OpaquePaintEvent);

  window_->AddRenderer(renderer_);
  window_->SetReadyForRendering(false);
  window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &VtkGlWidget::onMakeCurrent);
  window_->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &VtkGlWidget::onIsCurrent);
  interactor_->SetRenderWindow(window_);
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor_->SetInteractorStyle(style);
  // The interactor asks for a repaint instead of rendering outside paintEvent.
  interactor_->EnableRenderOff();
  interactor_->AddObserver(vtkCommand::RenderEvent, this, &VtkGlWidget::onMakeCurrent);
  interactor_->Initialize();
}

vtkRenderer* VtkGlWidget::renderer() const { return renderer_; }
vtkGenericOpenGLRenderWindow* VtkGlWidget::renderWindow() const { return window_; }
vtkGenericRenderWindowInteractor* VtkGlWidget::interactor() const { return interactor_; }

VtkGlWidget::~VtkGlWidget() {
  if (initialized_ && makeCurrent()) {
    window_->ReleaseGraphicsResources(window_);
    context_->doneCurrent();
  }
  initialized_ = false;
  window_->RemoveAllObservers();
  interactor_->RemoveAllObservers();
}

void VtkGlWidget::requestRender() {
  stale_ = true;
  update();
}

void VtkGlWidget::onMakeCurrent(vtkObject* caller, unsigned long event, void*) {
  if (event == vtkCommand::RenderEvent && caller == interactor_.Get()) {
    requestRender();
    return;
  }
  if (initialized_ && QOpenGLContext::currentContext() != context_.get()) context_->makeCurrent(surface_.get());
}

void VtkGlWidget::onIsCurrent(vtkObject*, unsigned long, void* call_data) {
  auto* current = static_cast<bool*>(call_data);
  *current = initialized_ && context_ && QOpenGLContext::currentContext() == context_.get();
}

bool VtkGlWidget::makeCurrent() {
  if (context_failed_) return false;
  if (!context_) {
    surface_ = std::make_unique<QOffscreenSurface>();
    surface_->setFormat(vtkFormat());
    surface_->create();
    context_ = std::make_unique<QOpenGLContext>();
    context_->setFormat(vtkFormat());
    if (!surface_->isValid() || !context_->create() || !context_->makeCurrent(surface_.get())) {
      context_failed_ = true;
      context_.reset();
      surface_.reset();
      qWarning("3D view: no OpenGL 3.2 context available, the view stays empty");
      return false;
    }
  } else if (!context_->makeCurrent(surface_.get())) {
    return false;
  }
  if (!initialized_) {
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
    const QSize size = devicePixelSize();
    window_->SetSize(size.width(), size.height());
    interactor_->SetSize(size.width(), size.height());
  }
  return true;
}

QSize VtkGlWidget::devicePixelSize() const {
  const qreal dpr = devicePixelRatioF();
  return {std::max(1, static_cast<int>(width() * dpr)), std::max(1, static_cast<int>(height() * dpr))};
}

QImage VtkGlWidget::renderAt(int width_px, int height_px) {
  window_->SetSize(width_px, height_px);
  vtkOpenGLState* state = window_->GetState();
  state->Reset();
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);
  window_->SetReadyForRendering(true);
  window_->Render();
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  const int status = window_->GetRGBACharPixelData(0, 0, width_px - 1, height_px - 1, 1, pixels);
  window_->SetReadyForRendering(false);
  state->Pop();
  if (status == VTK_ERROR || pixels->GetNumberOfValues() < static_cast<vtkIdType>(width_px) * height_px * 4) return {};
  // OpenGL rows run bottom-up. Translucent planes leave alpha < 1 in VTK's picture; the view is
  // opaque, so alpha is ignored (RGBX).
  QImage image(width_px, height_px, QImage::Format_RGBX8888);
  const unsigned char* src = pixels->GetPointer(0);
  for (int y = 0; y < height_px; ++y)
    std::memcpy(image.scanLine(height_px - 1 - y), src + static_cast<std::size_t>(y) * width_px * 4,
                static_cast<std::size_t>(width_px) * 4);
  return image.convertToFormat(QImage::Format_RGB32);
}

QImage VtkGlWidget::renderImage(int width_px, int height_px) {
  if (width_px <= 0 || height_px <= 0 || !makeCurrent()) return {};
  const int old_w = window_->GetSize()[0], old_h = window_->GetSize()[1];
  QImage image = renderAt(width_px, height_px);
  window_->SetSize(old_w, old_h);
  context_->doneCurrent();
  return image;
}

void VtkGlWidget::matchWindowSize() {
  const QSize size = devicePixelSize();
  const int* now = window_->GetSize();
  if (now[0] == size.width() && now[1] == size.height()) return;
  if (!makeCurrent()) return;
  window_->SetSize(size.width(), size.height());
  interactor_->SetSize(size.width(), size.height());
  context_->doneCurrent();
}

QImage VtkGlWidget::grabFramebuffer() {
  const QSize size = devicePixelSize();
  if (!makeCurrent()) return {};
  QElapsedTimer clock;
  clock.start();
  interactor_->SetSize(size.width(), size.height());
  image_ = renderAt(size.width(), size.height());
  context_->doneCurrent();
  last_paint_ms_ = clock.nsecsElapsed() * 1e-6;
  ++paint_count_;
  stale_ = false;
  image_.setDevicePixelRatio(devicePixelRatioF());
  return image_;
}

void VtkGlWidget::paintEvent(QPaintEvent*) {
  if (stale_ || image_.isNull() || image_.size() != devicePixelSize()) grabFramebuffer();
  QPainter painter(this);
  if (image_.isNull()) {
    painter.fillRect(rect(), palette().window());
    painter.drawText(rect(), Qt::AlignCenter, tr("No OpenGL: the 3D view cannot be drawn here."));
    return;
  }
  painter.drawImage(rect(), image_);
}

void VtkGlWidget::setEventPosition(const QPointF& position, Qt::KeyboardModifiers modifiers) {
  // VTK's pixels are device pixels, counted from the bottom.
  const QPointF p = position * devicePixelRatioF();
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x()), static_cast<int>(p.y()),
                                        (modifiers & Qt::ControlModifier) ? 1 : 0,
                                        (modifiers & Qt::ShiftModifier) ? 1 : 0);
}

void VtkGlWidget::forwardMouse(QMouseEvent* event, unsigned long vtk_event) {
  setEventPosition(event->position(), event->modifiers());
  interactor_->InvokeEvent(vtk_event, event);
}

void VtkGlWidget::mousePressEvent(QMouseEvent* event) {
  emit cameraMovedByUser();
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
  // A double click asks for the view that shows everything (the owner frames the model).
  if (event->button() == Qt::LeftButton) emit resetCameraRequested();
}

void VtkGlWidget::wheelEvent(QWheelEvent* event) {
  emit cameraMovedByUser();
  setEventPosition(event->position(), event->modifiers());
  const int delta = event->angleDelta().y();
  if (delta > 0) interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
  if (delta < 0) interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
  event->accept();
}

}  // namespace maris::ui
