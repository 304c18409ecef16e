// The current acting on the riser: a profile of speed and heading against depth below the still-water level,
// linear between rows. current.type = linear (speed_surface at the water level, speed_seabed at the sea bed, one
// heading) is the two-row case of the same profile, evaluated by the same arithmetic as before the table existed,
// so its results are bit for bit those of the linear formula.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/errors.hpp"
#include "core/schema_binder.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

struct CurrentProfile {
  double water_level = 0.0;     // [m] global z of depth 0; above it the current is zero
  std::vector<double> depth;    // [m] below the water level, strictly increasing (one row: uniform)
  std::vector<double> speed;    // [m/s]
  std::vector<double> heading;  // [rad] from +x towards +y
  double max_speed = 0.0;       // [m/s] largest |speed| (scales the static residual)
  // (cos, sin) of each row's heading, set by buildCurrentProfile: between two rows of the same heading `at` takes
  // these instead of a remainder, a cosine and a sine at every Gauss point (the same numbers, 15 % of a riser's
  // right-hand side).
  std::vector<Eigen::Vector2d> direction;
  // Shorter-arc heading change from each row to the next, remainder(heading[k+1] − heading[k], 2π) (one fewer
  // entry than the rows), set by buildCurrentProfile: `at` then takes no remainder per Gauss point.
  std::vector<double> heading_step;

  // Velocity [m/s] at height z: zero above the water level; above the first row and below the last the end row
  // holds; in between speed and heading are linear in depth, the heading along the shorter arc.
  Eigen::Vector3d at(double z) const;
};

// The profile of validated parameters (type linear: rows at depth 0 and at the sea bed, or one row when the sea bed
// is not below the water level).
CurrentProfile buildCurrentProfile(const RiserParameters& p);

// current.type and current.profile (called by riserBinder), their checks (by checkRiserParameters), and the
// upgrade of files written before the table existed (type linear added, results unchanged).
void bindCurrentProfile(SchemaBinder<RiserParameters>& b);
void checkCurrentProfile(const RiserParameters& p, std::vector<FieldError>& errors);
void upgradeCurrentProfile(Json& parameters, std::vector<std::string>& notes);

}  // namespace maris::riser
