#include "view3d/scene_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QResizeEvent>
#include <QLabel>
#include <QSlider>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkDoubleArray.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkGenericOpenGLRenderWindow.h>

#include "plots/display_units.hpp"
#include "plots/result_plot.hpp"
#include "theme.hpp"
#include "themed_icon.hpp"
#include "view3d/color_bar_actor.hpp"
#include "view3d/color_bar_scale.hpp"
#include "view3d/color_map_control.hpp"
#include "view3d/section_view.hpp"
#include "view3d/shape_actors.hpp"
#include "view3d/vtk_gl_widget.hpp"
#include "widgets/flow_layout.hpp"

namespace maris::ui {

namespace {

// The caption's top-left corner, as fractions of the view's width and height.
constexpr double kCaptionLeft = 0.015, kCaptionTop = 0.98;

// A water or sea-bed plane more than one model size away from the model is not drawn: a scene
// "in air" may put its water level kilometres below, which would shrink the model to a dot.
bool nearModel(double z, const Bounds3D& model) {
  if (model.empty()) return true;
  const double reach = model.diagonal();
  return z >= model.b[4] - reach && z <= model.b[5] + reach;
}

// Another model (a new scenario, a longer riser, another hull) rather than the same one again: its size
// differs by more than 20 % or its centre moved by more than a fifth of its size. The motion within one
// run, and a rerun of the same model, stay below that and keep the user's view.
bool framesAnew(const Bounds3D& framed, const Bounds3D& now) {
  if (framed.empty() || now.empty()) return !now.empty();
  const double size_ratio = now.diagonal() / std::max(framed.diagonal(), 1e-300);
  const double shift = (now.centre() - framed.centre()).norm() / std::max(framed.diagonal(), 1e-300);
  return size_ratio > 1.2 || size_ratio < 1 / 1.2 || shift > 0.2;
}

}  // namespace

SceneView::SceneView(QWidget* parent)
    : QWidget(parent), gl_(new VtkGlWidget(this)), slider_(new QSlider(Qt::Horizontal, this)),
      play_(new QToolButton(this)), magnify_(new QComboBox(this)), time_(new QLabel(this)),
      empty_(new QLabel(tr("No 3D view yet: run the scenario."), this)), timer_(new QTimer(this)),
      color_control_(new ColorMapControl(this)),
      colors_(vtkSmartPointer<vtkColorTransferFunction>::New()),
      bar_colors_(vtkSmartPointer<vtkColorTransferFunction>::New()),
      scalar_bar_(vtkSmartPointer<ColorBarActor>::New()), caption_(vtkSmartPointer<vtkTextActor>::New()),
      triad_(vtkSmartPointer<vtkOrientationMarkerWidget>::New()) {
  vtkRenderer* renderer = gl_->renderer();
  renderer->GradientBackgroundOn();
  // Translucent surfaces (still water, sea bed, a wave surface, a hull) are depth-peeled: without it
  // VTK blends them by a weighted average in which the nearer layer does not dominate, so a wave
  // surface seen through the still-water plane looked washed out. A few peels suffice here.
  renderer->UseDepthPeelingOn();
  renderer->SetMaximumNumberOfPeels(4);
  renderer->SetOcclusionRatio(0.0);

  // The bar has a lookup table of its own: the same colours over the range in the display unit (MPa, kN).
  scalar_bar_->SetLookupTable(bar_colors_);
  scalar_bar_->UseCustomLabelsOn();
  // Vertical at the right edge, labels to its right: it stays clear of sea beds and long
  // models, which fill the lower part of the picture.
  scalar_bar_->SetOrientationToVertical();
  scalar_bar_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  scalar_bar_->GetPositionCoordinate()->SetValue(0.80, 0.12);
  scalar_bar_->SetWidth(0.15);
  scalar_bar_->SetHeight(0.72);
  scalar_bar_->SetBarRatio(0.25);
  scalar_bar_->SetMaximumWidthInPixels(150);
  scalar_bar_->SetTextPositionToSucceedScalarBar();
  scalar_bar_->UnconstrainedFontSizeOn();
  scalar_bar_->SetTextPad(4);
  // The strip starts this far below the title: VTK raises the title by 3/4 of a label's height over the strip's top
  // and puts it TextPad and a frame line above that, so the top label (half a height above the top) keeps the
  // labels' gap from the title.
  scalar_bar_->SetVerticalTitleSeparation(static_cast<int>(ColorBarActor::kLabelGap) + 4 + 1);
  for (vtkTextProperty* text : {scalar_bar_->GetTitleTextProperty(), scalar_bar_->GetLabelTextProperty()}) {
    text->ShadowOff();
    text->ItalicOff();
    text->SetFontSize(13);
  }
  scalar_bar_->GetTitleTextProperty()->SetFontSize(14);
  scalar_bar_->GetLabelTextProperty()->BoldOff();
  caption_->GetTextProperty()->SetFontSize(14);
  caption_->GetTextProperty()->SetVerticalJustificationToTop();
  caption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  caption_->GetPositionCoordinate()->SetValue(kCaptionLeft, kCaptionTop);
  renderer->AddViewProp(caption_);

  auto axes = vtkSmartPointer<vtkAxesActor>::New();
  triad_->SetOrientationMarker(axes);
  triad_->SetInteractor(gl_->interactor());
  triad_->SetViewport(0.0, 0.0, 0.16, 0.22);
  triad_->SetEnabled(1);
  triad_->InteractiveOff();

  play_->setIcon(themedIcon(QStyle::SP_MediaPlay));
  play_->setToolTip(tr("Play / pause the animation"));
  play_->setCheckable(true);
  auto* reset = new QToolButton(this);
  reset->setText(tr("Reset camera"));
  reset->setToolTip(tr("Show the whole model from the default direction (or double-click the view)"));
  auto* save = new QToolButton(this);
  save->setText(tr("Export PNG…"));
  slider_->setEnabled(false);
  time_->setMinimumWidth(time_->fontMetrics().horizontalAdvance(QStringLiteral("t = -0000.000 s (000/000)")));
  empty_->setAlignment(Qt::AlignCenter);
  empty_->setWordWrap(true);  // a longer reason (a study case read from its folder) wraps in a narrow pane

  magnify_->addItem(tr("Displacement × 1"), 1.0);
  magnify_->addItem(tr("Displacement × 10"), 10.0);
  magnify_->addItem(tr("Displacement × 100"), 100.0);
  magnify_->setObjectName(QStringLiteral("magnification"));
  magnify_->setToolTip(tr("Draw the motion from the static shape (the faint ghost) magnified"));
  magnify_->setEnabled(false);

  // The time line on one row (the slider takes the width), the view's settings below it on rows that wrap in a
  // narrow view (a 1366-pixel screen) rather than push the window wider or hide a button.
  auto* timeline = new QHBoxLayout;
  timeline->addWidget(play_);
  timeline->addWidget(slider_, 1);
  timeline->addWidget(time_);
  auto* settings = new FlowLayout(nullptr, 4);
  settings->setObjectName(QStringLiteral("viewSettings"));
  settings->addWidget(magnify_);
  settings->addWidget(color_control_);
  settings->addWidget(reset);
  settings->addWidget(save);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(empty_);
  layout->addWidget(gl_, 1);
  layout->addLayout(timeline);
  layout->addLayout(settings);
  gl_->hide();

  timer_->setInterval(50);
  connect(timer_, &QTimer::timeout, this, [this] {
    if (frameCount() > 1) setFrame((frame_ + 1) % frameCount());
  });
  connect(play_, &QToolButton::toggled, this, &SceneView::setPlaying);
  connect(slider_, &QSlider::valueChanged, this, &SceneView::setFrame);
  color_control_->setEnabled(false);
  connect(color_control_, &ColorMapControl::settingsChanged, this, &SceneView::setColorSettings);
  connect(magnify_, &QComboBox::currentIndexChanged, this,
          [this](int index) { setMagnification(magnify_->itemData(index).toDouble()); });
  connect(reset, &QToolButton::clicked, this, &SceneView::resetCamera);
  connect(gl_, &VtkGlWidget::resetCameraRequested, this, &SceneView::resetCamera);
  connect(gl_, &VtkGlWidget::cameraMovedByUser, this, [this] { user_moved_camera_ = true; });
  connect(save, &QToolButton::clicked, this, &SceneView::exportPngInteractive);
  applyPaletteColors();
}

void SceneView::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::PaletteChange) applyPaletteColors();
}

void SceneView::applyPaletteColors() {
  const DrawingColors c = drawingColors(palette());
  vtkRenderer* renderer = gl_->renderer();
  renderer->SetBackground(c.view_bottom.redF(), c.view_bottom.greenF(), c.view_bottom.blueF());
  renderer->SetBackground2(c.view_top.redF(), c.view_top.greenF(), c.view_top.blueF());
  // Text on a light background is near-black, on a dark one the palette's text colour.
  const QColor text = isDark(palette()) ? c.foreground : QColor::fromRgbF(0.1f, 0.1f, 0.1f);
  // Text drawn over the model (a colour bar label beside a brown sea bed, the caption over a tall riser) stays
  // readable: every label sits on a box of the view's background colour, mostly opaque.
  const QColor backdrop = QColor::fromRgbF((c.view_top.redF() + c.view_bottom.redF()) / 2,
                                           (c.view_top.greenF() + c.view_bottom.greenF()) / 2,
                                           (c.view_top.blueF() + c.view_bottom.blueF()) / 2);
  for (vtkTextProperty* p : {scalar_bar_->GetTitleTextProperty(), scalar_bar_->GetLabelTextProperty(),
                             caption_->GetTextProperty()}) {
    p->SetColor(text.redF(), text.greenF(), text.blueF());
    p->SetBackgroundColor(backdrop.redF(), backdrop.greenF(), backdrop.blueF());
    p->SetBackgroundOpacity(0.8);
  }
  gl_->requestRender();
}

SceneView::~SceneView() {
  timer_->stop();
  triad_->SetEnabled(0);
}

int SceneView::frameCount() const { return results_ ? static_cast<int>(results_->view.frames.size()) : 0; }

double SceneView::frameTime(int index) const {
  return index >= 0 && index < frameCount() ? results_->view.frames[index].time : 0.0;
}

void SceneView::clear(const QString& why) {
  setPlaying(false);
  empty_->setText(why.isEmpty() ? tr("No 3D view yet: run the scenario.") : why);
  results_.reset();
  vtkRenderer* renderer = gl_->renderer();
  for (auto& a : frame_actors_) renderer->RemoveActor(a);
  for (auto& a : static_actors_) renderer->RemoveActor(a);
  frame_actors_.clear();
  static_actors_.clear();
  renderer->RemoveViewProp(scalar_bar_);
  camera_placed_ = false;
  gl_->hide();
  empty_->show();
  slider_->setEnabled(false);
  time_->clear();
}

void SceneView::showResults(std::shared_ptr<const Results> results) {
  if (!results || results->view.empty()) {
    if (!results_) clear();
    return;
  }
  results_ = std::move(results);
  empty_->hide();
  gl_->show();
  rebuildStatic();
  const QSignalBlocker blocker(slider_);
  slider_->setRange(0, frameCount() - 1);
  slider_->setEnabled(frameCount() > 1);
  play_->setEnabled(frameCount() > 1);
  frame_ = std::min(frame_, frameCount() - 1);
  slider_->setValue(frame_);
  drawFrame();
  // Framed anew for another model, and (unless the user placed the camera) whenever the model no longer fits:
  // part of it outside the picture, or filling less than half of it.
  bool fits = true;
  if (camera_placed_ && !user_moved_camera_) {
    const auto e = projectedModelExtent();
    fits = e[0] >= -1 && e[1] <= 1 && e[2] >= -1 && e[3] <= 1 && std::max(e[1] - e[0], e[3] - e[2]) >= 1.0;
  }
  if (!camera_placed_ || !fits || framesAnew(framed_bounds_, framingBounds())) resetCamera();
}

void SceneView::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  placeColorBar();
  // The fit depends on the view's aspect ratio: a view first framed while hidden or small is framed again.
  if (results_ && camera_placed_ && !user_moved_camera_) resetCamera();
}

void SceneView::rebuildStatic() {
  vtkRenderer* renderer = gl_->renderer();
  for (auto& a : static_actors_) renderer->RemoveActor(a);
  static_actors_.clear();
  const View3D& view = results_->view;
  const Bounds3D bounds = viewBounds(view);
  // Thin members (a 0.5 m riser in a 1 km scene) are drawn at least 2 % of the scene size thick (1 % radius):
  // thick enough to see, and to see their colour, in a view a few hundred pixels high. The caption says by how
  // much the thinnest tube is drawn thicker than it is.
  min_tube_radius_ = 0.01 * bounds.diagonal();
  double thinnest = 0;
  for (const auto& frame : view.frames)
    for (const auto& shape : frame.shapes)
      if (shape.kind == Shape3D::Kind::Tube && shape.radius > 0)
        thinnest = thinnest == 0 ? shape.radius : std::min(thinnest, shape.radius);
  drawn_thickness_ratio_ = thinnest > 0 ? std::max(1.0, min_tube_radius_ / thinnest) : 1.0;
  magnify_->setEnabled(!view.reference.empty());
  // The static shape as a faint ghost: what the motion (and its magnification) is measured from.
  for (Shape3D ghost : view.reference) {
    ghost.scalars.clear();
    ghost.color = {0.55, 0.55, 0.55};
    ghost.opacity = 0.3;
    ShapeStyle style;
    style.min_tube_radius = min_tube_radius_;
    if (auto actor = makeShapeActor(ghost, style)) {
      renderer->AddActor(actor);
      static_actors_.push_back(actor);
    }
  }
  data_lo_ = 0.0;
  data_hi_ = 1.0;
  have_scalars_ = scalarRange(view, data_lo_, data_hi_);
  if (data_hi_ <= data_lo_) data_hi_ = data_lo_ + (data_lo_ == 0.0 ? 1.0 : std::abs(data_lo_) * 1e-6);
  // Another quantity brings back what the user chose for it (or the defaults).
  if (view.scalar_name != colored_quantity_) {
    colored_quantity_ = view.scalar_name;
    const auto kept = color_memory_.find(colored_quantity_);
    if (kept != color_memory_.end())
      color_settings_ = kept->second;
    else
      color_settings_ = loadColorSettings(colored_quantity_).value_or(ColorSettings{});
  }
  applyColorSettings();
  color_control_->setEnabled(have_scalars_);
  renderer->RemoveViewProp(scalar_bar_);
  if (have_scalars_) renderer->AddViewProp(scalar_bar_);
  // A 2-D section: seen square-on, its water, sea bed and boundary outlined in its plane (horizontal planes
  // would be seen edge-on, through the model).
  section_axis_ = sectionNormalAxis(bounds);
  if (section_axis_ >= 0) {
    auto near = [&](const std::optional<double>& z) { return z && nearModel(*z, bounds) ? z : std::nullopt; };
    for (const auto& actor :
         makeSectionOutlines(bounds, section_axis_, near(view.water_level_z), near(view.seabed_z)).actors()) {
      renderer->AddActor(actor);
      static_actors_.push_back(actor);
    }
    return;
  }
  Bounds3D ground = bounds;
  if (view.water_level_z && nearModel(*view.water_level_z, bounds)) {
    auto water = makeHorizontalPlane(ground, *view.water_level_z, 0.25, {0.25, 0.55, 0.85}, 0.22);
    renderer->AddActor(water);
    static_actors_.push_back(water);
  }
  if (view.seabed_z && nearModel(*view.seabed_z, bounds)) {
    auto seabed = makeHorizontalPlane(ground, *view.seabed_z, 0.25, {0.62, 0.52, 0.38}, 0.9);
    renderer->AddActor(seabed);
    static_actors_.push_back(seabed);
  }
}

void SceneView::applyColorSettings() {
  const auto [lo, hi] = colorRange();
  fillColorMap(colors_, color_settings_.map, lo, hi);
  if (!results_) {
    color_control_->showSettings(color_settings_, data_lo_, data_hi_);
    return;
  }
  // The bar reads in an engineering unit with ticks on a 1–2–5 grid; the title wraps to the bar's strip
  // (~15 % of the view): a long quantity name ("modal amplitude (displacement, or twist for torsion modes)")
  // would run off the right edge.
  // A unit chosen in View ▸ Units is kept; otherwise the prefix that reads best for the data's range. The range
  // fields of the Colours control are in that unit, and so is the bar of a fixed range (as it was typed); an
  // automatic bar picks the prefix that reads best for the range it shows.
  const std::string& si_unit = results_->view.scalar_unit;
  const bool chosen = displayUnitChosen(si_unit);
  const ColorBarScale data_scale = colorBarScale(data_lo_, data_hi_, si_unit);
  const DisplayUnit field_unit = chosen ? displayUnit(si_unit) : DisplayUnit{data_scale.factor, data_scale.unit};
  color_control_->showSettings(color_settings_, data_lo_, data_hi_, field_unit);
  const ColorBarScale scale = chosen || !color_settings_.automatic
                                  ? colorBarScaleIn(lo, hi, field_unit.factor, field_unit.unit)
                                  : colorBarScale(lo, hi, si_unit);
  fillColorMap(bar_colors_, color_settings_.map, lo * scale.factor, hi * scale.factor);
  auto ticks = vtkSmartPointer<vtkDoubleArray>::New();
  for (double t : scale.ticks) ticks->InsertNextValue(t);
  scalar_bar_->SetCustomLabels(ticks);
  scalar_bar_->SetLabelFormat(scale.label_format.c_str());
  const QString range = !color_settings_.automatic ? tr("fixed range")
                        : color_settings_.per_frame ? tr("range of this frame")
                                                    : tr("range of all frames");
  const QString title = wrapAtSpaces(axisLabel(results_->view.scalar_name, scale.unit), 22) + QStringLiteral("\n") + range;
  scalar_bar_->SetTitle(title.toStdString().c_str());
  placeColorBar();
}

void SceneView::placeColorBar() {
  // VTK centres the title over the bar's strip (0.15 of the view, at most 150 px) and lets a title wider than the
  // strip overhang both sides; the tick labels start beside the colours (a quarter of the strip) and may reach
  // past the strip in a narrow view. Both measured here, the strip moves left until they keep 8 px from the right
  // edge.
  constexpr double kPreferredLeft = 0.80, kStripFraction = 0.15, kMaxStripPx = 150, kMarginPx = 8;
  constexpr double kBarBottom = 0.12, kBarHeight = 0.72;  // of the view's height, where nothing is in the way
  const double view_px = gl_->width() * gl_->devicePixelRatioF();
  const int dpi = gl_->renderWindow()->GetDPI();
  auto textWidth = [&](vtkTextProperty* property, const std::string& text) {
    int box[4] = {0, 0, 0, 0};
    if (text.empty() || !vtkTextRenderer::GetInstance()->GetBoundingBox(property, text, box, dpi)) return 0.0;
    return static_cast<double>(box[1] - box[0]);
  };
  const char* title = scalar_bar_->GetTitle();
  double title_px = title && *title ? textWidth(scalar_bar_->GetTitleTextProperty(), title) : 0.0;
  if (title_px > 0) title_px += 2.0 * scalar_bar_->GetTextPad();
  double label_px = 0;
  if (vtkDoubleArray* ticks = scalar_bar_->GetCustomLabels())
    for (vtkIdType i = 0; i < ticks->GetNumberOfTuples(); ++i) {
      char text[64];
      std::snprintf(text, sizeof text, scalar_bar_->GetLabelFormat(), ticks->GetValue(i));
      label_px = std::max(label_px, textWidth(scalar_bar_->GetLabelTextProperty(), text));
    }
  const double strip_px = std::min(kStripFraction * view_px, kMaxStripPx);
  const double labels_px = std::ceil(strip_px * scalar_bar_->GetBarRatio()) + ColorBarActor::kLabelGap + label_px;
  const double left = colorBarLeft(view_px, strip_px, title_px, labels_px, kMarginPx, kPreferredLeft);
  scalar_bar_->GetPositionCoordinate()->SetValue(left, kBarBottom);
  const double title_left = left * view_px + 0.5 * strip_px - 0.5 * std::max(strip_px, title_px);
  if (view_px > 0) color_bar_.left = std::min(left, title_left / view_px);
  color_bar_.strip_left = left;
  // The caption (top left; four lines over a ship's wave pattern) and the bar's title (top right) share the top of
  // a narrow view: where the caption reaches over to the title's left edge, the bar ends two margins below it.
  double top = kBarBottom + kBarHeight;
  const double view_h = gl_->height() * gl_->devicePixelRatioF();
  const char* caption = caption_->GetInput();
  int box[4] = {0, 0, 0, 0};
  if (view_h > 0 && caption && *caption &&
      vtkTextRenderer::GetInstance()->GetBoundingBox(caption_->GetTextProperty(), std::string(caption), box, dpi)) {
    const double caption_right = kCaptionLeft * view_px + (box[1] - box[0]);
    const double caption_bottom = kCaptionTop * view_h - (box[3] - box[2]);
    if (caption_right + kMarginPx > title_left) top = std::min(top, (caption_bottom - 2 * kMarginPx) / view_h);
  }
  scalar_bar_->SetHeight(std::max(kBarHeight / 2, top - kBarBottom));
  // The title is drawn inside the bar's box, at its top, a separation above the strip.
  int title_box[4] = {0, 0, 0, 0};
  const double title_h = title && *title && vtkTextRenderer::GetInstance()->GetBoundingBox(
                                                scalar_bar_->GetTitleTextProperty(), std::string(title), title_box, dpi)
                             ? title_box[3] - title_box[2] + 2.0 * scalar_bar_->GetTextPad() +
                                   scalar_bar_->GetVerticalTitleSeparation()
                             : 0.0;
  color_bar_.title_bottom = kBarBottom + scalar_bar_->GetHeight() - (view_h > 0 ? title_h / view_h : 0.0);
  gl_->requestRender();
}

std::pair<double, double> SceneView::colorRange() const {
  if (color_settings_.automatic && color_settings_.per_frame) return {frame_lo_, frame_hi_};
  if (color_settings_.automatic || !(color_settings_.max > color_settings_.min)) return {data_lo_, data_hi_};
  return {color_settings_.min, color_settings_.max};
}

void SceneView::setColorSettings(const ColorSettings& settings) {
  color_settings_ = settings;
  color_memory_[colored_quantity_] = settings;
  saveColorSettings(colored_quantity_, settings);
  applyColorSettings();
  // Solids of one scalar take their colour when their actor is made: rebuild the frame.
  drawFrame();
}

void SceneView::drawFrame() {
  vtkRenderer* renderer = gl_->renderer();
  for (auto& a : frame_actors_) renderer->RemoveActor(a);
  frame_actors_.clear();
  if (!results_ || frame_ < 0 || frame_ >= frameCount()) return;
  ShapeStyle style;
  style.colors = have_scalars_ ? colors_.Get() : nullptr;
  style.min_tube_radius = min_tube_radius_;
  const Frame3D& frame = results_->view.frames[frame_];
  if (have_scalars_ && color_settings_.automatic && color_settings_.per_frame) {
    // Each frame its own range: the colours and the bar follow the frame shown.
    frame_lo_ = data_lo_;
    frame_hi_ = data_hi_;
    if (frameScalarRange(frame, frame_lo_, frame_hi_) && !(frame_hi_ > frame_lo_))
      frame_hi_ = frame_lo_ + (frame_lo_ == 0.0 ? 1.0 : std::abs(frame_lo_) * 1e-6);
    applyColorSettings();
  }
  for (const Shape3D& drawn : frame.shapes) {
    const Shape3D shape = magnifiedShape(drawn, results_->view, magnification_);
    if (auto actor = makeShapeActor(shape, style)) {
      renderer->AddActor(actor);
      frame_actors_.push_back(actor);
    }
  }
  renderer->ResetCameraClippingRange();
  updateTimeLabel();
  gl_->requestRender();
}

void SceneView::updateTimeLabel() {
  if (!results_ || frameCount() == 0) return;
  const Frame3D& frame = results_->view.frames[frame_];
  const QString text = frame.label.empty() ? QStringLiteral("t = %1 s").arg(frame.time, 0, 'g', 6)
                                           : QString::fromStdString(frame.label);
  // A static result (one frame) has no time worth showing, but its own label (what the picture is) it shows.
  const bool animated = frameCount() > 1;
  time_->setText(animated ? QStringLiteral("%1 (%2/%3)").arg(text).arg(frame_ + 1).arg(frameCount()) : QString());
  QStringList lines;
  if (animated || !frame.label.empty()) lines << text;
  const QString notes = drawingNotes();
  if (!notes.isEmpty()) lines << notes;
  caption_->SetInput(lines.join('\n').toStdString().c_str());
  placeColorBar();  // a longer caption may reach the bar's title
}

QString SceneView::captionText() const {
  const char* text = caption_->GetInput();
  return text ? QString::fromUtf8(text) : QString();
}

QString SceneView::drawingNotes() const {
  QStringList notes;
  if (results_ && !results_->view.reference.empty())
    notes << (magnification_ == 1.0 ? tr("grey ghost: static shape")
                                    : tr("displacement × %1 from the static shape (grey ghost)").arg(magnification_));
  // Thin members are drawn thicker than they are; say so once it is more than a rounding.
  if (section_axis_ >= 0) notes << tr("2-D model: seen square-on to its plane, without perspective");
  if (drawn_thickness_ratio_ > 1.5) notes << tr("tubes drawn up to %1 × their diameter").arg(std::round(drawn_thickness_ratio_));
  return notes.join('\n');
}

void SceneView::setMagnification(double factor) {
  if (!(factor >= 1.0) || factor == magnification_) return;
  magnification_ = factor;
  const int index = magnify_->findData(factor);
  if (index >= 0 && magnify_->currentIndex() != index) {
    const QSignalBlocker blocker(magnify_);
    magnify_->setCurrentIndex(index);
  }
  if (!results_) return;
  drawFrame();
  // A magnified motion may reach outside the old framing.
  if (!user_moved_camera_ || framesAnew(framed_bounds_, framingBounds())) resetCamera();
}

void SceneView::setFrame(int index) {
  if (!results_ || index < 0 || index >= frameCount()) return;
  frame_ = index;
  if (slider_->value() != index) {
    const QSignalBlocker blocker(slider_);
    slider_->setValue(index);
  }
  drawFrame();
}

void SceneView::setPlaying(bool playing) {
  if (playing && frameCount() > 1)
    timer_->start();
  else
    timer_->stop();
  const QSignalBlocker blocker(play_);
  play_->setChecked(timer_->isActive());
  play_->setIcon(themedIcon(timer_->isActive() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

bool SceneView::isPlaying() const { return timer_->isActive(); }

Bounds3D SceneView::framingBounds() const {
  if (!results_) return {};
  Bounds3D bounds = viewBounds(results_->view, magnification_);
  // The still-water and sea-bed planes belong in the picture when they are drawn.
  const Bounds3D model = bounds;
  for (const auto& z : {results_->view.water_level_z, results_->view.seabed_z})
    if (z && nearModel(*z, model)) bounds.add(Eigen::Vector3d(model.centre().x(), model.centre().y(), *z));
  return bounds;
}

std::array<double, 4> SceneView::projectedModelExtent() const {
  std::array<double, 4> extent{1e300, -1e300, 1e300, -1e300};
  const Bounds3D bounds = framingBounds();
  if (bounds.empty()) return {0, 0, 0, 0};
  gl_->matchWindowSize();
  vtkRenderer* renderer = gl_->renderer();
  for (int corner = 0; corner < 8; ++corner) {
    renderer->SetWorldPoint(bounds.b[corner & 1], bounds.b[2 + ((corner >> 1) & 1)], bounds.b[4 + ((corner >> 2) & 1)], 1.0);
    renderer->WorldToView();
    double view[3];
    renderer->GetViewPoint(view);
    extent[0] = std::min(extent[0], view[0]);
    extent[1] = std::max(extent[1], view[0]);
    extent[2] = std::min(extent[2], view[1]);
    extent[3] = std::max(extent[3], view[1]);
  }
  return extent;
}

void SceneView::resetCamera() {
  if (!results_) return;
  gl_->matchWindowSize();
  const Bounds3D bounds = framingBounds();
  const Eigen::Vector3d c = bounds.centre();
  // An oblique view from the front-right and slightly above, z up; a 2-D section square-on, without perspective.
  const Eigen::Vector3d from =
      section_axis_ >= 0 ? sectionViewDirection(section_axis_) : Eigen::Vector3d(0.55, -1.0, 0.35).normalized();
  vtkCamera* camera = gl_->renderer()->GetActiveCamera();
  camera->SetParallelProjection(section_axis_ >= 0);
  camera->SetFocalPoint(c.x(), c.y(), c.z());
  const Eigen::Vector3d eye = c + from * bounds.diagonal() * 2.0;
  camera->SetPosition(eye.x(), eye.y(), eye.z());
  camera->SetViewUp(0, 0, 1);
  // Zoom below narrows the view angle; starting from VTK's default each time keeps repeated framings alike.
  camera->SetViewAngle(30.0);
  camera->SetWindowCenter(0.0, 0.0);
  gl_->renderer()->ResetCamera(bounds.b.data());
  // ResetCamera fits the bounding sphere, which leaves a long model (a hull, a 2-D section, a riser seen
  // across) small in a wide view. Fit the projected box instead: zoom until it fills the free part of the
  // view (the right ~20 % holds the colour bar, the top the caption), then shift it to that part's centre. A 2-D
  // section, a flat box as wide as its picture, would run under the bar where a narrow view moved the bar left: it
  // ends a margin left of the bar's strip as placed for this width, and left of the bar's title too when it reaches
  // up beside the title (keeping at least about half the view). A 3-D model keeps the fixed share: its box's corners
  // are mostly empty space, and a tall riser needs the width.
  const double left = -0.95, top = 0.80, bottom = -0.95;
  constexpr double kFill = 0.92;
  auto fit = [&](double right) {
    for (int pass = 0; pass < 3; ++pass) {  // perspective makes one zoom step inexact: refine twice
      camera->SetWindowCenter(0.0, 0.0);
      const auto e = projectedModelExtent();
      const double half_x = 0.5 * (e[1] - e[0]), half_y = 0.5 * (e[3] - e[2]);
      const double zoom = std::min(half_x > 0 ? 0.5 * (right - left) * kFill / half_x : 1e3,
                                   half_y > 0 ? 0.5 * (top - bottom) * kFill / half_y : 1e3);
      if (std::isfinite(zoom) && zoom > 0 && std::abs(zoom - 1.0) > 1e-3) camera->Zoom(std::clamp(zoom, 0.05, 20.0));
    }
    camera->SetWindowCenter(0.0, 0.0);
    const auto e = projectedModelExtent();
    camera->SetWindowCenter(0.5 * (e[0] + e[1]) - 0.5 * (left + right), 0.5 * (e[2] + e[3]) - 0.5 * (top + bottom));
  };
  const bool section_beside_bar = have_scalars_ && section_axis_ >= 0;
  // A margin left of an edge at `fraction` of the view's width, in the view's [-1, 1].
  auto leftOf = [](double fraction) { return std::clamp(2.0 * fraction - 1.0 - 0.03, 0.0, 0.95); };
  fit(section_beside_bar ? leftOf(color_bar_.strip_left) : have_scalars_ ? 0.55 : 0.95);
  if (section_beside_bar && color_bar_.left < color_bar_.strip_left) {
    const auto e = projectedModelExtent();
    if (e[3] > 2.0 * color_bar_.title_bottom - 1.0 && e[1] > leftOf(color_bar_.left)) fit(leftOf(color_bar_.left));
  }
  gl_->renderer()->ResetCameraClippingRange();
  camera_placed_ = true;
  user_moved_camera_ = false;
  framed_bounds_ = bounds;
  gl_->requestRender();
}

QImage SceneView::renderImage(int width_px, int height_px) { return gl_->renderImage(width_px, height_px); }

void SceneView::exportPngInteractive() {
  if (!results_) {
    emit message(tr("Nothing to export: run the scenario first."));
    return;
  }
  const QSize here = gl_->size() * gl_->devicePixelRatioF();
  const QStringList sizes{QStringLiteral("%1 × %2 (as shown)").arg(here.width()).arg(here.height()),
                          QStringLiteral("1920 × 1080"), QStringLiteral("2560 × 1440"), QStringLiteral("3840 × 2160")};
  bool ok = false;
  const QString choice = QInputDialog::getItem(this, tr("Export 3D view"), tr("Resolution"), sizes, 1, false, &ok);
  if (!ok) return;
  const QStringList parts = choice.section(QLatin1Char(' '), 0, 2).split(QStringLiteral(" × "));
  const int w = parts.value(0).toInt(), h = parts.value(1).toInt();
  const QString file = QFileDialog::getSaveFileName(this, tr("Export 3D view"), QStringLiteral("view_3d.png"),
                                                    QStringLiteral("PNG image (*.png)"));
  if (file.isEmpty()) return;
  const QImage image = renderImage(w, h);
  if (!image.isNull() && image.save(file, "PNG"))
    emit message(tr("Exported %1 (%2 × %3)").arg(file).arg(w).arg(h));
  else
    emit message(tr("Could not export the 3D view to %1").arg(file));
}

}  // namespace maris::ui
