// Current profile of the riser (contract in riser/riser_current.hpp).
#include "riser/riser_current.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/angles.hpp"
#include "core/text_format.hpp"

namespace maris::riser {
namespace {

using P = RiserParameters;

SchemaBinder<CurrentProfileRow> profileRowBinder() {
  SchemaBinder<CurrentProfileRow> b;
  b.real("depth", &CurrentProfileRow::depth, "m", Range::nonNegative(1e5), "Depth below environment.water_level");
  b.real("speed", &CurrentProfileRow::speed, "m/s", Range::closed(-20, 20), "Current speed at this depth");
  b.real("heading_deg", &CurrentProfileRow::heading_deg, "deg", Range::closed(-360, 360),
         "Direction the current flows towards, from +x towards +y");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"depth", "Depth"},
      {"speed", "Speed"},
      {"heading_deg", "Heading"},
  });
  return b;
}

// The rows' (cos, sin) and the shorter-arc steps between them, once per profile.
void setCurrentDirections(CurrentProfile& c) {
  for (double h : c.heading) c.direction.emplace_back(std::cos(h), std::sin(h));
  for (std::size_t k = 1; k < c.heading.size(); ++k)
    c.heading_step.push_back(std::remainder(c.heading[k] - c.heading[k - 1], 2 * std::numbers::pi));
}

}  // namespace

Eigen::Vector3d CurrentProfile::at(double z) const {
  if (z > water_level) return Eigen::Vector3d::Zero();
  const double below = water_level - z;
  double s = speed[0], h = heading[0];
  if (depth.size() > 1) {
    // Interval [depth_k, depth_k+1] holding `below`, the first or last one outside the rows; f clamped to [0, 1].
    // For two rows at 0 and the sea bed this is the linear profile's f = (water_level − z)/depth and
    // s_0 + f (s_1 − s_0), operation for operation.
    const auto above = std::upper_bound(depth.begin(), depth.end(), below);
    const auto index = static_cast<std::size_t>(above - depth.begin());
    const std::size_t k = std::clamp<std::size_t>(index, 1, depth.size() - 1) - 1;
    const double f = std::clamp((below - depth[k]) / (depth[k + 1] - depth[k]), 0.0, 1.0);
    s = speed[k] + f * (speed[k + 1] - speed[k]);
    if (heading[k + 1] == heading[k] && direction.size() == heading.size())
      return s * Eigen::Vector3d(direction[k].x(), direction[k].y(), 0.0);
    const double step = heading_step.size() + 1 == heading.size()
                            ? heading_step[k]
                            : std::remainder(heading[k + 1] - heading[k], 2 * std::numbers::pi);
    h = heading[k] + f * step;
  } else if (direction.size() == 1) {
    return s * Eigen::Vector3d(direction[0].x(), direction[0].y(), 0.0);
  }
  return s * Eigen::Vector3d(std::cos(h), std::sin(h), 0.0);
}

CurrentProfile buildCurrentProfile(const RiserParameters& p) {
  CurrentProfile c;
  c.water_level = p.water_level;
  if (p.current_type == "table") {
    for (const CurrentProfileRow& r : p.current_profile) {
      c.depth.push_back(r.depth);
      c.speed.push_back(r.speed);
      c.heading.push_back(radiansFromDegrees(r.heading_deg));
      c.max_speed = std::max(c.max_speed, std::abs(r.speed));
    }
    setCurrentDirections(c);
    return c;
  }
  const double direction = radiansFromDegrees(p.current_direction_deg), depth = p.water_level - p.seabed_level;
  c.depth.push_back(0.0);
  c.speed.push_back(p.current_speed_surface);
  c.heading.push_back(direction);
  if (depth > 0) {  // else the surface speed holds everywhere, as the linear formula's f = 0 gave
    c.depth.push_back(depth);
    c.speed.push_back(p.current_speed_seabed);
    c.heading.push_back(direction);
  }
  c.max_speed = std::max(std::abs(p.current_speed_surface), std::abs(p.current_speed_seabed));
  setCurrentDirections(c);
  return c;
}

void bindCurrentProfile(SchemaBinder<RiserParameters>& b) {
  b.choice("current.type", &P::current_type, {"linear", "table"},
           "Current profile: linear from speed_surface at the water level to speed_seabed at the sea bed along "
           "direction_deg, or the table current.profile");
  b.table("current.profile", &P::current_profile, profileRowBinder(), 0, 1000,
          "Current against depth (current.type = table): rows of increasing depth below the water level, speed and "
          "heading linear in between (heading along the shorter arc), the end rows held beyond, zero above the water");
}

void checkCurrentProfile(const RiserParameters& p, std::vector<FieldError>& e) {
  if (p.current_type != "table") return;
  if (p.current_profile.empty())
    e.push_back({"current.profile", "0 rows", "current.type = table needs at least 1 row"});
  for (std::size_t k = 1; k < p.current_profile.size(); ++k)
    if (!(p.current_profile[k].depth > p.current_profile[k - 1].depth))
      e.push_back({"current.profile[" + std::to_string(k) + "].depth", numberText(p.current_profile[k].depth),
                   "must be greater than the previous row's depth " + numberText(p.current_profile[k - 1].depth)});
}

void upgradeCurrentProfile(Json& parameters, std::vector<std::string>& notes) {
  auto current = parameters.find("current");
  if (current == parameters.end() || !current->is_object() || current->contains("type")) return;
  (*current)["type"] = "linear";
  if (!current->contains("profile")) (*current)["profile"] = Json::array();
  notes.push_back("current.type = linear added (the linear profile between current.speed_surface and "
                  "current.speed_seabed, as before; save the scenario to keep it)");
}

}  // namespace maris::riser
