#include "view3d/section_view.hpp"

#include <algorithm>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace maris::ui {

int sectionNormalAxis(const Bounds3D& model) {
  if (model.empty()) return -1;
  const double diagonal = model.diagonal(), flat = 1e-6 * diagonal, spans = 1e-3 * diagonal;
  auto extent = [&](int axis) { return model.b[2 * axis + 1] - model.b[2 * axis]; };
  if (!(diagonal > 0.0) || extent(2) <= spans) return -1;
  if (extent(1) <= flat && extent(0) > spans) return 1;
  if (extent(0) <= flat && extent(1) > spans) return 0;
  return -1;
}

Eigen::Vector3d sectionViewDirection(int normal_axis) {
  return normal_axis == 0 ? Eigen::Vector3d(1.0, 0.0, 0.0) : Eigen::Vector3d(0.0, -1.0, 0.0);
}

std::vector<vtkSmartPointer<vtkActor>> SectionOutlines::actors() const {
  std::vector<vtkSmartPointer<vtkActor>> out;
  for (const auto& a : {water_band, water_line, seabed_line, boundary})
    if (a) out.push_back(a);
  return out;
}

namespace {

// Points in the section's plane: `h` along its horizontal axis, `z` up, `depth` towards the camera.
struct SectionFrame {
  int normal_axis;
  Eigen::Vector3d toward;  // unit, from the model to the camera
  double plane;            // the model's coordinate along the normal
  Eigen::Vector3d at(double h, double z, double depth) const {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p[normal_axis == 0 ? 1 : 0] = h;
    p[2] = z;
    p[normal_axis] = plane;
    return p + depth * toward;
  }
};

vtkSmartPointer<vtkActor> flatActor(vtkPolyData* data, const Eigen::Vector3d& rgb, double opacity, double line_width) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->SetColor(rgb.x(), rgb.y(), rgb.z());
  property->SetOpacity(opacity);
  property->SetLineWidth(static_cast<float>(line_width));
  // Lines and the band keep their colour whatever the light: outlines, not lit surfaces.
  property->SetLighting(false);
  actor->PickableOff();
  return actor;
}

// A polyline through `points` (closed when `closed`).
vtkSmartPointer<vtkActor> lineActor(const std::vector<Eigen::Vector3d>& points, bool closed, const Eigen::Vector3d& rgb,
                                    double width) {
  auto pts = vtkSmartPointer<vtkPoints>::New();
  for (const auto& p : points) pts->InsertNextPoint(p.x(), p.y(), p.z());
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const auto n = static_cast<vtkIdType>(points.size());
  lines->InsertNextCell(closed ? n + 1 : n);
  for (vtkIdType i = 0; i < n; ++i) lines->InsertCellPoint(i);
  if (closed) lines->InsertCellPoint(0);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pts);
  data->SetLines(lines);
  return flatActor(data, rgb, 1.0, width);
}

}  // namespace

SectionOutlines makeSectionOutlines(const Bounds3D& model, int normal_axis, std::optional<double> water_z,
                                    std::optional<double> seabed_z) {
  SectionOutlines out;
  if (normal_axis != 0 && normal_axis != 1) return out;
  const int h_axis = normal_axis == 0 ? 1 : 0;
  const double h0 = model.b[2 * h_axis], h1 = model.b[2 * h_axis + 1], z0 = model.b[4], z1 = model.b[5];
  const double offset = 2e-3 * model.diagonal();  // in front of (or behind) the model, so neither hides the other
  const SectionFrame f{normal_axis, sectionViewDirection(normal_axis), model.b[2 * normal_axis]};
  const double reach = 0.25 * (h1 - h0), left = h0 - reach, right = h1 + reach;
  if (water_z) {
    const double bottom = seabed_z ? std::min(*seabed_z, *water_z) : z0;
    auto pts = vtkSmartPointer<vtkPoints>::New();
    for (const auto& p : {f.at(left, bottom, -offset), f.at(right, bottom, -offset), f.at(right, *water_z, -offset),
                          f.at(left, *water_z, -offset)})
      pts->InsertNextPoint(p.x(), p.y(), p.z());
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->InsertNextCell(4);
    for (vtkIdType i = 0; i < 4; ++i) polys->InsertCellPoint(i);
    auto band = vtkSmartPointer<vtkPolyData>::New();
    band->SetPoints(pts);
    band->SetPolys(polys);
    out.water_band = flatActor(band, {0.25, 0.55, 0.85}, 0.18, 1.0);
    out.water_line = lineActor({f.at(left, *water_z, offset), f.at(right, *water_z, offset)}, false, {0.1, 0.4, 0.85}, 2.5);
  }
  if (seabed_z)
    out.seabed_line = lineActor({f.at(left, *seabed_z, offset), f.at(right, *seabed_z, offset)}, false, {0.55, 0.4, 0.2}, 2.5);
  out.boundary = lineActor({f.at(h0, z0, offset), f.at(h1, z0, offset), f.at(h1, z1, offset), f.at(h0, z1, offset)}, true,
                           {0.25, 0.25, 0.25}, 1.5);
  return out;
}

}  // namespace maris::ui
