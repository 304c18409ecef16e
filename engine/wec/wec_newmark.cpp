// The paper's integration of the augmented formulation (Heo & Koo §2.2, after Shabana & Hussein 2009): a two-loop
// scheme. Per step t_n → t_{n+1}, for every float:
//   outer (explicit Newmark-β, β = 0, γ = ½, on the independent coordinate θ):
//       θ_{n+1} = θ_n + h θ̇_n + ½ h² θ̈_n
//   inner (Newton–Raphson on the position constraints for the dependent coordinates u_d = (x, z)):
//       C_{u_d} Δu_d = −C(u_d, θ_{n+1}),  C_{u_d} = I here, from the Newmark predictor of (x, z)
//   velocities from C_q q̇ = 0 (eq 20): (ẋ, ż) = −C_{u_d}⁻¹ C_θ θ̇ = L θ̇ (−sin θ, cos θ)
//   accelerations and multipliers from the KKT system (eq 22, WecDynamics::rhs; its Baumgarte terms vanish
//   because C = Ċ = 0), and θ̇_{n+1} = θ̇_n + ½ h (θ̈_n + θ̈_{n+1}).
// The last relation is implicit in θ̇_{n+1} (PTO damping and radiation memory depend on velocity), so the velocity
// update is iterated to a fixed point (contraction ≈ ½ h (B_PTO + …)/J ≪ 1). The radiation modal states are
// advanced exactly for a velocity varying linearly over the step (exponential integrator), which keeps them
// stable for any step; the direct convolution extrapolates its memory force as the RK4 path does.
// Constraints then hold at position (to the Newton tolerance), velocity and acceleration level without drift.
#include <cmath>
#include <complex>

#include "core/errors.hpp"
#include "wec/wec_dynamics.hpp"
#include "wec/wec_frequency.hpp"
#include "core/text_format.hpp"

namespace maris::wec {

namespace {

// Exact propagator of ẇ = p w + v(t) over one step for v linear between v_n and v_{n+1}:
//   w_{n+1} = E w_n + φ1 v_n + φ2 (v_{n+1} − v_n),  E = e^{ph}, φ1 = (E − 1)/p, φ2 = (E − 1 − ph)/(p² h).
struct ModePropagator {
  std::complex<double> e, phi1, phi2;
  bool paired = false;
};

std::vector<ModePropagator> propagators(const ModalKernel& fit, double h) {
  std::vector<ModePropagator> out;
  for (const auto& m : fit.modes) {
    const std::complex<double> p = m.pole, e = std::exp(p * h);
    // For |ph| small the closed forms cancel; the series is used there.
    const std::complex<double> ph = p * h;
    const bool small = std::abs(ph) < 1e-4;
    const std::complex<double> phi1 = small ? h * (1.0 + ph / 2.0 + ph * ph / 6.0) : (e - 1.0) / p;
    const std::complex<double> phi2 = small ? h * (0.5 + ph / 6.0 + ph * ph / 24.0) : (e - 1.0 - ph) / (p * p * h);
    out.push_back({e, phi1, phi2, m.paired});
  }
  return out;
}

}  // namespace

double newmarkStabilityStep(const WecModel& model) {
  double fastest = 0.0;
  for (const auto& f : model.floats) {
    const double rx = f.arm_length * std::cos(f.theta0), rz = f.arm_length * std::sin(f.theta0);
    const double j_inf = f.inertia_hinge + f.heave.a_inf * rx * rx + f.surge.a_inf * rz * rz;
    const double k_theta = model.density * model.gravity * f.waterplane_area * rx * rx + f.pto_stiffness;
    fastest = std::max({fastest, std::sqrt(k_theta / j_inf), naturalFrequency(model, f)});
  }
  return fastest > 0.0 ? 2.0 / fastest : 1.0;
}

TimeDomainResult simulateNewmark(const WecModel& model, const IncidentWaves& waves, const TimeDomainOptions& options,
                                 RunContext* context, const TimeDomainObserver& observe) {
  TimeDomainOptions o = options;
  o.augmented = true;
  o.projection = false;  // WecDynamics::project only measures the drift
  WecDynamics sys(model, waves, o);
  const std::size_t nf = model.floats.size();
  const double h = o.time_step;
  const long n_steps = std::lround(o.duration / h);
  TimeDomainResult r;
  r.floats.resize(nf);
  r.stability_step = newmarkStabilityStep(model);
  r.method = "augmented, Newmark two-loop (beta=0, gamma=1/2) h=" + numberText(h) + " s, radiation " +
             (o.state_space ? "state-space" : "direct convolution");

  std::vector<std::vector<ModePropagator>> prop;
  for (const auto& c : sys.channels()) prop.push_back(propagators(*c.fit, h));
  Eigen::VectorXd y = sys.initialState(), dy = Eigen::VectorXd::Zero(sys.size());
  Eigen::VectorXd y_n(sys.size()), dy_n(sys.size()), v_n(2 * nf), v(2 * nf);
  std::vector<double> thd_guess(nf);
  std::vector<FloatLoads> loads(nf);
  HistoryRecorder recorder(r, nf);
  sys.advanceHistory(y);
  sys.rhs(0.0, 0.0, y, dy, &loads);
  constexpr int kMaxIterations = 50;

  for (long n = 0;; ++n) {
    const double t = h * static_cast<double>(n);
    recorder.accumulate(loads, n > 0 ? h : 0.0);
    if (n % o.output_stride == 0 || n == n_steps) {
      recorder.record(t, waves.elevation(0.0, t), loads);
      if (observe && context && n < n_steps && context->wantsPartialResults()) observe(r);
    }
    if (n == n_steps) break;
    y_n = y;
    dy_n = dy;
    sys.velocities(y_n, v_n);
    auto fail = [&](const std::string& what) {
      throw SolverError(what, t + h, n + 1,
                        "augmented Newmark two-loop scheme; the time step " + numberText(h) +
                            " s should stay below its stability limit " + numberText(r.stability_step) + " s");
    };

    // Outer loop: explicit Newmark predictor of θ; inner loop: Newton–Raphson on C(x, z; θ_{n+1}) = 0.
    for (std::size_t i = 0; i < nf; ++i) {
      const FloatModel& f = *sys.floats()[i].f;
      const int k = sys.floats()[i].offset;
      for (int c = 0; c < 3; ++c) y[k + c] = y_n[k + c] + h * y_n[k + 3 + c] + 0.5 * h * h * dy_n[k + 3 + c];
      const double L = f.arm_length, th = y[k + 2];
      const double tol = 1e-13 * (L + std::abs(f.hinge_x) + std::abs(f.hinge_z));
      int it = 0;
      for (;; ++it) {
        const double cx = y[k] - f.hinge_x - L * std::cos(th), cz = y[k + 1] - f.hinge_z - L * std::sin(th);
        if (std::hypot(cx, cz) <= tol) break;
        if (it == kMaxIterations || !std::isfinite(cx + cz)) fail("position constraint of float " + std::to_string(i + 1) + " did not converge");
        y[k] -= cx;  // Δu_d = −C_{u_d}⁻¹ C with C_{u_d} = I
        y[k + 1] -= cz;
      }
      r.max_newton_iterations = std::max(r.max_newton_iterations, it);
      thd_guess[i] = y_n[k + 5] + h * dy_n[k + 5];
    }

    // Velocity loop: θ̇_{n+1} = θ̇_n + ½h(θ̈_n + θ̈_{n+1}) to a fixed point.
    int it = 0;
    for (;; ++it) {
      if (it == kMaxIterations) fail("velocity iteration did not converge");
      for (std::size_t i = 0; i < nf; ++i) {
        const int k = sys.floats()[i].offset;
        const double L = sys.floats()[i].f->arm_length, th = y[k + 2];
        y[k + 5] = thd_guess[i];
        y[k + 3] = -L * std::sin(th) * thd_guess[i];
        y[k + 4] = L * std::cos(th) * thd_guess[i];
      }
      if (o.state_space) {
        sys.velocities(y, v);
        for (std::size_t c = 0; c < sys.channels().size(); ++c) {
          const auto& ch = sys.channels()[c];
          const double vn = v_n[ch.col], dv = v[ch.col] - v_n[ch.col];
          int s = ch.offset;
          for (const auto& m : prop[c]) {
            if (m.paired) {
              const std::complex<double> w = m.e * std::complex<double>(y_n[s], y_n[s + 1]) + m.phi1 * vn + m.phi2 * dv;
              y[s] = w.real();
              y[s + 1] = w.imag();
              s += 2;
            } else {
              y[s] = (m.e * y_n[s] + m.phi1 * vn + m.phi2 * dv).real();
              ++s;
            }
          }
        }
      }
      sys.rhs(t + h, 1.0, y, dy, &loads);
      double change = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < nf; ++i) {
        const int k = sys.floats()[i].offset;
        const double next = y_n[k + 5] + 0.5 * h * (dy_n[k + 5] + dy[k + 5]);
        change = std::max(change, std::abs(next - thd_guess[i]));
        scale = std::max({scale, std::abs(next), h * std::abs(dy_n[k + 5])});
        thd_guess[i] = next;
      }
      if (!std::isfinite(change)) fail("the velocity became non-finite");
      if (change <= 1e-13 * scale) break;
    }
    r.max_velocity_iterations = std::max(r.max_velocity_iterations, it + 1);
    // Local error of the position update: the linear-acceleration (Wilson/Fox–Goodwin) value differs from the
    // Newmark predictor by h²/6 (θ̈_{n+1} − θ̈_n).
    double local = 0.0;
    for (std::size_t i = 0; i < nf; ++i) {
      const int k = sys.floats()[i].offset;
      local = std::max(local, std::abs(dy[k + 5] - dy_n[k + 5]));
    }
    r.error_estimate += h * h / 6.0 * local;
    throwIfNotFinite(y, t + h, n + 1, [&](Eigen::Index k) {
      return "state " + std::to_string(k) + " of the augmented Newmark run (stability limit " +
             numberText(r.stability_step) + " s)";
    });
    sys.project(y, r.max_position_drift, r.max_velocity_drift);
    sys.advanceHistory(y);
    if (context && n % 64 == 0) {
      context->throwIfCancelled();
      context->progress(static_cast<double>(n) / static_cast<double>(n_steps), "time integration (Newmark)");
    }
  }
  r.steps = n_steps;
  r.rhs_evaluations = sys.evaluations();
  return r;
}

}  // namespace maris::wec
