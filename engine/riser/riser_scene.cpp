#include "riser/riser_scene.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/scene.hpp"
#include "riser/riser_envelope.hpp"
#include "riser/riser_results.hpp"
#include "riser/riser_statics.hpp"

namespace maris::riser {
namespace {

std::string formatTime(double t) {
  std::ostringstream s;
  s << t;
  std::string out = s.str();
  std::replace(out.begin(), out.end(), '.', '_');
  return out;
}

// Classical RK4 with constant step, as the paper integrates. A private loop until the shared
// integrators (core/ode.hpp) are on main: it renormalises quaternions after every step, which a
// general-purpose integrator does not know to do.
struct Rk4 {
  Eigen::VectorXd k1, k2, k3, k4, tmp;
  void step(const RiserModel& m, RiserWorkspace& ws, double t, double h, Eigen::VectorXd& y) {
    evaluateRhs(m, ws, t, y, k1);
    tmp = y + 0.5 * h * k1;
    evaluateRhs(m, ws, t + 0.5 * h, tmp, k2);
    tmp = y + 0.5 * h * k2;
    evaluateRhs(m, ws, t + 0.5 * h, tmp, k3);
    tmp = y + h * k3;
    evaluateRhs(m, ws, t + h, tmp, k4);
    y += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    normaliseState(m, y);
  }
};

}  // namespace

Results solveRiser(const RiserParameters& p, RunContext& context) {
  const RiserModel model = buildRiserModel(p);
  // Initial shape: static equilibrium or the built-in straight/arc shape.
  StaticSolution statics{model.initial_orientation, model.initial_top, Vec3::Zero(), 0, 0, 0.0};
  if (p.solve_statics) statics = solveStatics(model, context);
  Eigen::VectorXd y = restState(model, statics.orientation, statics.top);

  // Step: the user's, or half the RK4 stability limit 2.8/ω_max, and fine enough for the top motion.
  const double omega_max = highestFrequencyEstimate(model);
  double h = p.time_step > 0 ? p.time_step : 1.4 / omega_max;
  if (p.time_step <= 0 && model.motion_amplitude.norm() > 0) h = std::min(h, p.motion_period / 40);
  const long steps = p.end_time > 0 ? std::max(1L, static_cast<long>(std::ceil(p.end_time / h - 1e-9))) : 0;
  if (steps > 0) h = p.end_time / steps;
  const double stabilisation = steps > 0 ? 0.1 / h : 0.0;

  RiserRecorder recorder(model, p, stabilisation);
  recorder.sample(0.0, y, true, std::string("profile_static"));
  // Natural frequencies about the static state (dense eigenproblem: only for moderate sizes).
  RiserModes modes;
  if (p.solve_statics && 3 * (model.n + 1) <= 600) {
    context.progress(0.0, "natural frequencies");
    modes = computeModes(model, statics, 6);
    recorder.addModes(modes);
  }
  SolverStats stats;
  stats.method = "RK4, constant step h = " + std::to_string(h) + " s, " +
                 (model.formulation == Formulation::Joint ? "joint" : "absolute") + " coordinates" +
                 (model.torsion ? " with torsion" : " without torsion");
  if (steps > 0) {
    RiserWorkspace ws = makeWorkspace(model, stabilisation);
    Rk4 rk;
    const long history_every = std::max(1L, steps / 2000);
    const int frames = std::max(1, p.frame_count);
    std::vector<long> profile_steps;
    for (double ts : p.stress_times)
      if (ts <= p.end_time) profile_steps.push_back(std::lround(ts / h));
    long next_frame = 1;
    for (long k = 1; k <= steps; ++k) {
      const double t0 = (k - 1) * h;
      rk.step(model, ws, t0, h, y);
      if (!y.allFinite())
        throwIfNotFinite(y, k * h, k, [&](Eigen::Index i) { return stateComponentName(model, i); });
      context.throwIfCancelled();
      context.progress(static_cast<double>(k) / steps, "time integration");
      const bool frame = k * frames >= next_frame * steps;
      if (frame) ++next_frame;
      std::optional<std::string> profile;
      for (std::size_t s = 0; s < profile_steps.size(); ++s)
        if (profile_steps[s] == k) profile = "profile_t" + formatTime(p.stress_times[s]);
      if (frame || profile || k % history_every == 0 || k == steps) recorder.sample(k * h, y, frame, profile);
    }
    stats.steps = steps;
    stats.rhs_evaluations = 4 * steps;
  }
  Results results = recorder.finish(stats, statics.iterations, statics.residual);
  addEnvelope(model, results);
  // Without a time history the 3D view animates the mode shapes instead (one period per mode).
  if (steps == 0 && !modes.frequencies.empty()) {
    results.view.frames.clear();
    appendModeFrames(model, statics, modes, 24, results.view);
  }
  return results;
}

}  // namespace maris::riser

namespace maris {

SceneDefinition makeRiserScene() {
  return makeScene<riser::RiserParameters>(
      "riser", "Riser / cable dynamics",
      "Risers, cables and mooring lines by the segment method (Adamiec-Wójcik, Brzozowska & Wojciech, "
      "Acta Mechanica 231, 2020): n+1 rigid segments joined by rotary spring-damping elements for bending "
      "and torsion, in joint or absolute coordinates; gravity, buoyancy, Morison drag against a depth-varying "
      "current, prescribed top motion or a tensioner, pinned/clamped/free/spring bottom, point loads; static "
      "equilibrium by Newton's method, dynamics by RK4 with an O(n) block-tridiagonal reaction solve.",
      riser::riserBinder(), riser::checkRiserParameters, riser::solveRiser);
}

}  // namespace maris
