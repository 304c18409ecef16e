#include "seismic/seismic_outline.hpp"

#include "seismic/fe_mesh.hpp"

namespace maris::seismic {

std::vector<Shape3D> reefLayerOutlines(const SeismicParameters& p) {
  std::vector<Shape3D> out;
  if (p.model != "reef" || p.layers.empty()) return out;
  // Heights of the layer boundaries, from the flat (top) down to the sea bed (0).
  std::vector<double> heights{0.0};
  for (const auto& layer : p.layers) heights.front() += layer.thickness;
  for (const auto& layer : p.layers) heights.push_back(heights.back() - layer.thickness);
  heights.back() = 0.0;  // the sum and the differences may part by a rounding

  Shape3D outline;
  outline.kind = Shape3D::Kind::Polyline;
  outline.name = "reef outline";
  outline.color = {0.15, 0.15, 0.15};
  for (auto it = heights.rbegin(); it != heights.rend(); ++it)
    outline.points.emplace_back(-reefHalfWidth(p, *it), 0.0, *it);
  for (double h : heights) outline.points.emplace_back(reefHalfWidth(p, h), 0.0, h);
  out.push_back(std::move(outline));

  for (std::size_t k = 1; k + 1 < heights.size(); ++k) {
    Shape3D boundary;
    boundary.kind = Shape3D::Kind::Polyline;
    boundary.name = "layer interface";
    boundary.color = {0.3, 0.3, 0.3};
    const double half = reefHalfWidth(p, heights[k]);
    boundary.points = {{-half, 0.0, heights[k]}, {half, 0.0, heights[k]}};
    out.push_back(std::move(boundary));
  }
  return out;
}

}  // namespace maris::seismic
