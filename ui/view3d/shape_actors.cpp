#include "view3d/shape_actors.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkDiskSource.h>
#include <vtkDoubleArray.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkScalarsToColors.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTubeFilter.h>

namespace maris::ui {

void Bounds3D::add(const Eigen::Vector3d& p, double pad) {
  if (!p.allFinite()) return;
  const bool first = empty();
  for (int i = 0; i < 3; ++i) {
    const double lo = p[i] - pad, hi = p[i] + pad;
    b[2 * i] = first ? lo : std::min(b[2 * i], lo);
    b[2 * i + 1] = first ? hi : std::max(b[2 * i + 1], hi);
  }
}

double Bounds3D::diagonal() const {
  if (empty()) return 1.0;
  return std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
}

Eigen::Vector3d Bounds3D::centre() const {
  if (empty()) return Eigen::Vector3d::Zero();
  return {0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])};
}

Shape3D magnifiedShape(const Shape3D& shape, const View3D& view, double magnification) {
  if (magnification == 1.0) return shape;
  for (const Shape3D& ref : view.reference) {
    if (ref.name != shape.name || ref.kind != shape.kind || ref.points.size() != shape.points.size()) continue;
    Shape3D out = shape;
    for (std::size_t i = 0; i < out.points.size(); ++i)
      out.points[i] = ref.points[i] + magnification * (shape.points[i] - ref.points[i]);
    return out;
  }
  return shape;
}

Bounds3D viewBounds(const View3D& view, double magnification) {
  Bounds3D bounds;
  auto add = [&](const Shape3D& shape) {
    double pad = shape.radius;
    if (shape.kind == Shape3D::Kind::Box) pad = 0.5 * shape.size.maxCoeff();
    for (const auto& p : shape.points) bounds.add(p, pad);
  };
  for (const auto& frame : view.frames)
    for (const auto& shape : frame.shapes) add(magnification == 1.0 ? shape : magnifiedShape(shape, view, magnification));
  return bounds;
}

bool frameScalarRange(const Frame3D& frame, double& lo, double& hi) {
  bool any = false;
  for (const auto& shape : frame.shapes)
    for (double s : shape.scalars) {
      if (!std::isfinite(s)) continue;
      lo = any ? std::min(lo, s) : s;
      hi = any ? std::max(hi, s) : s;
      any = true;
    }
  return any;
}

bool scalarRange(const View3D& view, double& lo, double& hi) {
  bool any = false;
  for (const auto& frame : view.frames) {
    double frame_lo = 0, frame_hi = 0;
    if (!frameScalarRange(frame, frame_lo, frame_hi)) continue;
    lo = any ? std::min(lo, frame_lo) : frame_lo;
    hi = any ? std::max(hi, frame_hi) : frame_hi;
    any = true;
  }
  return any;
}

namespace {

vtkSmartPointer<vtkPoints> toPoints(const std::vector<Eigen::Vector3d>& points) {
  auto out = vtkSmartPointer<vtkPoints>::New();
  out->SetDataTypeToDouble();
  for (const auto& p : points) out->InsertNextPoint(p.x(), p.y(), p.z());
  return out;
}

bool perPointScalars(const Shape3D& shape, const ShapeStyle& style) {
  return style.colors && !shape.scalars.empty() && shape.scalars.size() == shape.points.size();
}

void attachScalars(vtkPolyData* poly, const Shape3D& shape) {
  auto values = vtkSmartPointer<vtkDoubleArray>::New();
  values->SetName("scalars");
  for (double s : shape.scalars) values->InsertNextValue(s);
  poly->GetPointData()->SetScalars(values);
}

// A polyline through the shape's points, with its scalars.
vtkSmartPointer<vtkPolyData> polylineData(const Shape3D& shape, bool with_scalars) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(toPoints(shape.points));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->InsertNextCell(static_cast<vtkIdType>(shape.points.size()));
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(shape.points.size()); ++i) lines->InsertCellPoint(i);
  poly->SetLines(lines);
  if (with_scalars) attachScalars(poly, shape);
  return poly;
}

// Rotation taking +z onto `direction`, then translation to `centre`.
vtkSmartPointer<vtkTransform> orientZTo(const Eigen::Vector3d& centre, const Eigen::Vector3d& direction) {
  auto t = vtkSmartPointer<vtkTransform>::New();
  t->Translate(centre.x(), centre.y(), centre.z());
  const Eigen::Vector3d z(0, 0, 1);
  const Eigen::Vector3d d = direction.norm() > 0 ? direction.normalized() : z;
  const Eigen::Vector3d axis = z.cross(d);
  const double angle_deg = std::atan2(axis.norm(), z.dot(d)) * 180.0 / M_PI;
  if (axis.norm() > 1e-12)
    t->RotateWXYZ(angle_deg, axis.x(), axis.y(), axis.z());
  else if (z.dot(d) < 0)
    t->RotateWXYZ(180.0, 1, 0, 0);
  return t;
}

vtkSmartPointer<vtkPolyData> hemisphereData(const Shape3D& shape) {
  auto cap = vtkSmartPointer<vtkSphereSource>::New();
  cap->SetRadius(shape.radius);
  cap->SetStartPhi(0.0);  // phi is measured from the +z pole
  cap->SetEndPhi(90.0);
  cap->SetThetaResolution(40);
  cap->SetPhiResolution(20);
  auto lid = vtkSmartPointer<vtkDiskSource>::New();
  lid->SetInnerRadius(0.0);
  lid->SetOuterRadius(shape.radius);
  lid->SetCircumferentialResolution(40);
  auto both = vtkSmartPointer<vtkAppendPolyData>::New();
  both->AddInputConnection(cap->GetOutputPort());
  both->AddInputConnection(lid->GetOutputPort());
  auto place = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  place->SetTransform(orientZTo(shape.points.front(), shape.direction));
  place->SetInputConnection(both->GetOutputPort());
  place->Update();
  return place->GetOutput();
}

vtkSmartPointer<vtkPolyData> surfaceData(const Shape3D& shape, bool with_scalars) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(toPoints(shape.points));
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  const int nu = shape.grid_u, nv = shape.grid_v;
  for (int v = 0; v + 1 < nv; ++v)
    for (int u = 0; u + 1 < nu; ++u) {
      const vtkIdType ids[4] = {v * nu + u, v * nu + u + 1, (v + 1) * nu + u + 1, (v + 1) * nu + u};
      quads->InsertNextCell(4, ids);
    }
  poly->SetPolys(quads);
  if (with_scalars) attachScalars(poly, shape);
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(poly);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->Update();
  return normals->GetOutput();
}

vtkSmartPointer<vtkPolyData> pointsData(const Shape3D& shape, bool with_scalars) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(toPoints(shape.points));
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(shape.points.size()); ++i) verts->InsertNextCell(1, &i);
  poly->SetVerts(verts);
  if (with_scalars) attachScalars(poly, shape);
  return poly;
}

}  // namespace

vtkSmartPointer<vtkActor> makeShapeActor(const Shape3D& shape, const ShapeStyle& style) {
  using Kind = Shape3D::Kind;
  const bool scalars = perPointScalars(shape, style);
  vtkSmartPointer<vtkPolyData> data;
  switch (shape.kind) {
    case Kind::Tube: {
      if (shape.points.size() < 2) return nullptr;
      auto tube = vtkSmartPointer<vtkTubeFilter>::New();
      tube->SetInputData(polylineData(shape, scalars));
      tube->SetRadius(std::max(shape.radius, style.min_tube_radius));
      tube->SetNumberOfSides(20);
      tube->CappingOn();
      tube->Update();
      data = tube->GetOutput();
      break;
    }
    case Kind::Polyline:
      if (shape.points.size() < 2) return nullptr;
      data = polylineData(shape, scalars);
      break;
    case Kind::Sphere: {
      if (shape.points.empty()) return nullptr;
      auto sphere = vtkSmartPointer<vtkSphereSource>::New();
      sphere->SetCenter(shape.points.front().data());
      sphere->SetRadius(shape.radius);
      sphere->SetThetaResolution(32);
      sphere->SetPhiResolution(20);
      sphere->Update();
      data = sphere->GetOutput();
      break;
    }
    case Kind::Hemisphere:
      if (shape.points.empty()) return nullptr;
      data = hemisphereData(shape);
      break;
    case Kind::Box: {
      if (shape.points.empty()) return nullptr;
      auto box = vtkSmartPointer<vtkCubeSource>::New();
      box->SetCenter(shape.points.front().data());
      box->SetXLength(shape.size.x());
      box->SetYLength(shape.size.y());
      box->SetZLength(shape.size.z());
      box->Update();
      data = box->GetOutput();
      break;
    }
    case Kind::Surface:
      if (shape.grid_u < 2 || shape.grid_v < 2 ||
          shape.points.size() != static_cast<std::size_t>(shape.grid_u) * static_cast<std::size_t>(shape.grid_v))
        return nullptr;
      data = surfaceData(shape, scalars);
      break;
    case Kind::Points:
      if (shape.points.empty()) return nullptr;
      data = pointsData(shape, scalars);
      break;
  }
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* prop = actor->GetProperty();
  if (scalars) {
    mapper->SetLookupTable(style.colors);
    mapper->SetScalarModeToUsePointData();
    mapper->UseLookupTableScalarRangeOn();
    mapper->ScalarVisibilityOn();
  } else {
    mapper->ScalarVisibilityOff();
    Eigen::Vector3d rgb = shape.color;
    // A solid with a single scalar takes that scalar's colour.
    if (style.colors && shape.scalars.size() == 1) style.colors->GetColor(shape.scalars.front(), rgb.data());
    prop->SetColor(rgb.x(), rgb.y(), rgb.z());
  }
  prop->SetOpacity(std::clamp(shape.opacity, 0.0, 1.0));
  prop->SetSpecular(0.25);
  prop->SetSpecularPower(20.0);
  if (shape.kind == Kind::Polyline) prop->SetLineWidth(2.5f);
  if (shape.kind == Kind::Points) {
    prop->SetPointSize(8.0f);
    prop->RenderPointsAsSpheresOn();
  }
  return actor;
}

vtkSmartPointer<vtkActor> makeHorizontalPlane(const Bounds3D& bounds, double z, double margin,
                                              const Eigen::Vector3d& rgb, double opacity) {
  const double sx = std::max(bounds.b[1] - bounds.b[0], 0.2 * bounds.diagonal());
  const double sy = std::max(bounds.b[3] - bounds.b[2], 0.2 * bounds.diagonal());
  const Eigen::Vector3d c = bounds.centre();
  const double hx = 0.5 * sx * (1.0 + 2.0 * margin), hy = 0.5 * sy * (1.0 + 2.0 * margin);
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(c.x() - hx, c.y() - hy, z);
  plane->SetPoint1(c.x() + hx, c.y() - hy, z);
  plane->SetPoint2(c.x() - hx, c.y() + hy, z);
  plane->SetResolution(1, 1);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb.x(), rgb.y(), rgb.z());
  actor->GetProperty()->SetOpacity(opacity);
  // Seen at a grazing angle a headlight leaves a horizontal plane nearly black: mostly ambient
  // light keeps the sea bed sand-coloured and the water blue from any viewpoint.
  actor->GetProperty()->SetAmbient(0.6);
  actor->GetProperty()->SetDiffuse(0.4);
  actor->GetProperty()->SetSpecular(0.0);
  actor->PickableOff();
  return actor;
}

}  // namespace maris::ui
