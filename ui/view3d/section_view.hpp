// A model that lies in one vertical plane (a 2-D section such as the seismic reef–seawater model, drawn as a flat
// surface) is a 2-D model: it is seen square-on with an orthographic camera, and its water, sea bed and outer
// boundary are drawn as outlines in its plane, instead of horizontal planes that would be seen edge-on and cut
// through it. Nothing here knows a scene: a model is a section when its shapes have no extent across one
// horizontal axis.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include "view3d/shape_actors.hpp"

class vtkActor;

namespace maris::ui {

// The horizontal axis (0 = x, 1 = y) across which `model` has no extent (at most 1e-6 of its diagonal) while it
// spans the other horizontal axis and z; −1 for a model that is not a vertical section (a solid, a horizontal
// surface, a vertical line).
int sectionNormalAxis(const Bounds3D& model);

// Unit vector from the model towards the camera that sees the section square-on with the other horizontal axis
// to the right and z up: −y for a section in the x–z plane, +x for one in the y–z plane.
Eigen::Vector3d sectionViewDirection(int normal_axis);

// The outlines of a section: the water between the sea bed (or the model's bottom) and the still-water level as a
// translucent band behind the model, the still-water line and the sea-bed line across the model's width (a
// quarter wider on each side) and the model's outer boundary, the lines in front of the model. The water and
// sea bed are left out when not given.
struct SectionOutlines {
  vtkSmartPointer<vtkActor> water_band, water_line, seabed_line, boundary;
  std::vector<vtkSmartPointer<vtkActor>> actors() const;  // those that are drawn
};
SectionOutlines makeSectionOutlines(const Bounds3D& model, int normal_axis, std::optional<double> water_z,
                                    std::optional<double> seabed_z);

}  // namespace maris::ui
