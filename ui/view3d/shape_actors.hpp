// Turns the engine's drawable shapes (core/results.hpp Shape3D) into VTK actors: tubes along
// polylines with per-point scalar colours, spheres, hemispheres (closed by a flat disc), boxes,
// structured surfaces, polylines and point clouds; plus the still-water and sea-bed planes.
// Nothing here knows a scene: every model is drawn from what its Results say.
#pragma once

#include <array>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/results.hpp"

class vtkActor;
class vtkScalarsToColors;

namespace maris::ui {

// Axis-aligned bounds [xmin, xmax, ymin, ymax, zmin, zmax]; empty() until a point is added.
struct Bounds3D {
  std::array<double, 6> b{1, -1, 1, -1, 1, -1};
  bool empty() const { return b[0] > b[1]; }
  void add(const Eigen::Vector3d& p, double pad = 0.0);
  double diagonal() const;
  Eigen::Vector3d centre() const;
};

// Bounds of every shape of every frame (animated models keep one stable frame of reference), with the
// displacements from View3D::reference magnified by `magnification` (magnifiedShape).
Bounds3D viewBounds(const View3D& view, double magnification = 1.0);

// `shape` with its displacement from its reference (the View3D::reference shape of the same name, kind and
// point count) multiplied by `magnification`; the shape itself when it has no reference or at 1.
Shape3D magnifiedShape(const Shape3D& shape, const View3D& view, double magnification);

// Min and max of the scalars of one frame; false if it has none.
bool frameScalarRange(const Frame3D& frame, double& lo, double& hi);
// Min and max of all scalars of all frames; false if there are none.
bool scalarRange(const View3D& view, double& lo, double& hi);

struct ShapeStyle {
  vtkScalarsToColors* colors = nullptr;  // colour map for per-point scalars (may be null)
  double min_tube_radius = 0.0;          // [m] thin tubes are drawn at least this thick to stay visible
};

// One actor per shape; null for a shape with too few points to draw.
vtkSmartPointer<vtkActor> makeShapeActor(const Shape3D& shape, const ShapeStyle& style);

// A horizontal rectangle at height z covering `bounds` (enlarged by `margin` × its size).
vtkSmartPointer<vtkActor> makeHorizontalPlane(const Bounds3D& bounds, double z, double margin,
                                              const Eigen::Vector3d& rgb, double opacity);

}  // namespace maris::ui
