// The riser benches' model and state for timing one evaluation: a built-in scenario at n segments in joint or
// absolute coordinates, and its static shape set in motion, so that drag, spring dampers and the velocity terms all
// do work: segment i turns at 0.02 (sin 0.7i, cos 1.3i, sin 0.4i) rad/s; in absolute coordinates its origin moves
// at 0.05 (cos 0.5i, sin 0.9i, 0.1 cos i) m/s. `statics_iterations`, when given, receives the Newton iterations the
// static shape took (a faster right-hand side that changes rounding must not make them grow).
#pragma once

#include <cmath>
#include <string>

#include "core/resources.hpp"
#include "core/scenario.hpp"
#include "riser/riser_dynamics.hpp"
#include "riser/riser_statics.hpp"

namespace maris::bench {

inline riser::RiserModel builtinRiserModel(const std::string& scenario, int n, bool joint) {
  const std::string path = "scenarios/riser/" + scenario + ".json";
  riser::RiserParameters p =
      riser::riserBinder().read(scenarioFromText(std::string(*builtinResource(path)), path).parameters);
  p.segment_count = n;
  p.formulation = joint ? "joint" : "absolute";
  return riser::buildRiserModel(p);
}

inline Eigen::VectorXd movingState(const riser::RiserModel& m, int* statics_iterations = nullptr) {
  using riser::Vec3;
  RunContext ctx;
  const riser::StaticSolution s = riser::solveStatics(m, ctx);
  if (statics_iterations) *statics_iterations = s.iterations;
  Eigen::VectorXd y = riser::restState(m, s.orientation, s.top);
  for (int i = m.first_dynamic; i <= m.last_dynamic; ++i) {
    const double a = i;
    y.segment<3>(riser::angularVelocityStateOffset(m, i)) =
        0.02 * Vec3(std::sin(0.7 * a), std::cos(1.3 * a), std::sin(0.4 * a));
    if (m.formulation == riser::Formulation::Absolute)
      y.segment<3>(riser::velocityStateOffset(m, i)) =
          0.05 * Vec3(std::cos(0.5 * a), std::sin(0.9 * a), 0.1 * std::cos(a));
  }
  return y;
}

}  // namespace maris::bench
