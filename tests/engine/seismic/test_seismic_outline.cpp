// The reef's outline and layer interfaces drawn in the 3D view, against the closed form of the default reef: a flat
// of 800 m on layers of 100 m (45°), 200 m (40°) and 300 m (35°), each flank widening by thickness / tan(slope).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "seismic/seismic_outline.hpp"

namespace maris::seismic {
namespace {

double widening(double thickness, double slope_deg) { return thickness / std::tan(slope_deg * std::numbers::pi / 180.0); }

TEST(SeismicOutline, DefaultReefOutlineAndInterfacesInTheSectionPlane) {
  const SeismicParameters p;
  const std::vector<Shape3D> shapes = reefLayerOutlines(p);
  ASSERT_EQ(shapes.size(), 3u);  // the outline and the two interfaces between three layers
  const double h1 = 400.0 + widening(100, 45), h2 = h1 + widening(200, 40), h3 = h2 + widening(300, 35);
  const std::vector<Eigen::Vector3d> outline{{-h3, 0, 0},  {-h2, 0, 300}, {-h1, 0, 500}, {-400, 0, 600},
                                             {400, 0, 600}, {h1, 0, 500},  {h2, 0, 300},  {h3, 0, 0}};
  EXPECT_EQ(shapes[0].kind, Shape3D::Kind::Polyline);
  ASSERT_EQ(shapes[0].points.size(), outline.size());
  for (std::size_t i = 0; i < outline.size(); ++i)
    EXPECT_LT((shapes[0].points[i] - outline[i]).norm(), 1e-9) << "outline point " << i;
  EXPECT_LT((shapes[1].points[0] - Eigen::Vector3d(-h1, 0, 500)).norm(), 1e-9);
  EXPECT_LT((shapes[1].points[1] - Eigen::Vector3d(h1, 0, 500)).norm(), 1e-9);
  EXPECT_LT((shapes[2].points[0] - Eigen::Vector3d(-h2, 0, 300)).norm(), 1e-9);
  EXPECT_LT((shapes[2].points[1] - Eigen::Vector3d(h2, 0, 300)).norm(), 1e-9);
  // In the wave field's plane (y = 0): the 3D view still sees a flat section.
  for (const Shape3D& s : shapes)
    for (const auto& q : s.points) EXPECT_EQ(q.y(), 0.0);
}

TEST(SeismicOutline, BoxHasNoReef) {
  SeismicParameters p;
  p.model = "box";
  EXPECT_TRUE(reefLayerOutlines(p).empty());
}

}  // namespace
}  // namespace maris::seismic
