#include "wec/wec_time.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "core/errors.hpp"
#include "wec/wec_frequency.hpp"

namespace maris::wec {

namespace {

// Radiation memory of one mode: modal states inside the state vector, or a direct convolution.
struct ModeMemory {
  const ModalKernel* fit = nullptr;
  int offset = 0;                 // first modal state (state-space only)
  double a_inf = 0.0;             // [kg]
  DirectConvolution convolution;  // direct only
  double mu_prev = 0.0, mu_now = 0.0;  // [N] direct memory force at t_{n−1}, t_n

  double memory(const Eigen::VectorXd& y, bool state_space, double frac) const {
    if (!state_space) return mu_now + frac * (mu_now - mu_prev);
    double mu = 0.0;
    int k = offset;
    for (const auto& m : fit->modes) {
      if (m.paired) {
        mu += 2.0 * (m.residue.real() * y[k] - m.residue.imag() * y[k + 1]);
        k += 2;
      } else {
        mu += m.residue.real() * y[k++];
      }
    }
    return mu;
  }
  // ẇ = p w + v for every mode.
  void derivative(const Eigen::VectorXd& y, double v, Eigen::VectorXd& dy) const {
    int k = offset;
    for (const auto& m : fit->modes) {
      const double pr = m.pole.real(), pi = m.pole.imag();
      if (m.paired) {
        dy[k] = pr * y[k] - pi * y[k + 1] + v;
        dy[k + 1] = pi * y[k] + pr * y[k + 1];
        k += 2;
      } else {
        dy[k] = pr * y[k] + v;
        ++k;
      }
    }
  }
};

// Loads and energies of one float at one instant (diagnostics for the histories).
struct FloatLoads {
  double theta = 0, theta_dt = 0, theta_dtdt = 0, fx = 0, fz = 0, moment = 0;
  double p_pto = 0, p_exc = 0, p_rad = 0, energy = 0;
  double drift_position = 0, drift_velocity = 0;
};

struct FloatSystem {
  const FloatModel* f = nullptr;
  ExcitationSeries excitation;
  int offset = 0;  // first state of this float
  ModeMemory surge, heave;
};

class Simulator {
 public:
  Simulator(const WecModel& model, const WaveField& waves, const TimeDomainOptions& o) : model_(model), waves_(waves), o_(o) {
    int n = 0;
    const int mech = o.augmented ? 6 : 2;
    for (const auto& f : model.floats) {
      FloatSystem s;
      s.f = &f;
      s.excitation = makeExcitation(model, f, waves);
      s.offset = n;
      n += mech;
      for (auto [mem, rad] : {std::pair{&s.surge, &f.surge}, std::pair{&s.heave, &f.heave}}) {
        mem->a_inf = rad->a_inf;
        mem->fit = &rad->fit;
        if (o.state_space) {
          mem->offset = n;
          n += rad->fit.order;
        } else {
          RadiationKernel k;
          k.dt = o.time_step;
          const auto count = static_cast<std::size_t>(rad->kernel.duration() / o.time_step) + 1;
          for (std::size_t j = 0; j < count; ++j) k.values.push_back(rad->kernel.at(o.time_step * static_cast<double>(j)));
          mem->convolution = DirectConvolution(k);
        }
      }
      systems_.push_back(std::move(s));
    }
    size_ = n;
  }

  int size() const { return size_; }

  Eigen::VectorXd initialState() const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(size_);
    for (const auto& s : systems_) {
      const double th = s.f->theta0 + o_.initial_offset;
      if (o_.augmented) {
        y[s.offset] = s.f->hinge_x + s.f->arm_length * std::cos(th);
        y[s.offset + 1] = s.f->hinge_z + s.f->arm_length * std::sin(th);
        y[s.offset + 2] = th;
      } else {
        y[s.offset] = th;
      }
    }
    return y;
  }

  // dy = f(t, y); frac ∈ [0, 1] is the position inside the current step (direct memory extrapolation).
  void rhs(double t, double frac, const Eigen::VectorXd& y, Eigen::VectorXd& dy, std::vector<FloatLoads>* loads) {
    ++evaluations_;
    const double ramp = waves_.ramp(t);
    for (std::size_t i = 0; i < systems_.size(); ++i) {
      FloatLoads l;
      if (o_.augmented)
        augmented(systems_[i], t, ramp, frac, y, dy, l);
      else
        classical(systems_[i], t, ramp, frac, y, dy, l);
      if (loads) (*loads)[i] = l;
    }
  }

  // Projects (x, z, ẋ, ż) onto the hinge constraints; returns the drift removed.
  void project(Eigen::VectorXd& y, double& drift_p, double& drift_v) const {
    for (const auto& s : systems_) {
      const int o = s.offset;
      const double L = s.f->arm_length, th = y[o + 2], thd = y[o + 5];
      const double cx = y[o] - s.f->hinge_x - L * std::cos(th), cz = y[o + 1] - s.f->hinge_z - L * std::sin(th);
      const double vx = y[o + 3] + L * std::sin(th) * thd, vz = y[o + 4] - L * std::cos(th) * thd;
      drift_p = std::max(drift_p, std::hypot(cx, cz));
      drift_v = std::max(drift_v, std::hypot(vx, vz));
      if (!o_.projection) continue;
      y[o] -= cx;
      y[o + 1] -= cz;
      y[o + 3] -= vx;
      y[o + 4] -= vz;
    }
  }

  // Direct convolution: append the velocities of the completed step.
  void advanceHistory(const Eigen::VectorXd& y) {
    if (o_.state_space) return;
    for (auto& s : systems_) {
      double vx, vz;
      velocities(s, y, vx, vz);
      for (auto [mem, v] : {std::pair{&s.surge, vx}, std::pair{&s.heave, vz}}) {
        mem->convolution.push(v);
        mem->mu_prev = mem->mu_now;
        mem->mu_now = mem->convolution.valueNow();
      }
    }
  }

  long evaluations() const { return evaluations_; }

 private:
  void velocities(const FloatSystem& s, const Eigen::VectorXd& y, double& vx, double& vz) const {
    const int o = s.offset;
    if (o_.augmented) {
      vx = y[o + 3];
      vz = y[o + 4];
    } else {
      const double L = s.f->arm_length;
      vx = -L * std::sin(y[o]) * y[o + 1];
      vz = L * std::cos(y[o]) * y[o + 1];
    }
  }

  void classical(FloatSystem& s, double t, double ramp, double frac, const Eigen::VectorXd& y, Eigen::VectorXd& dy,
                 FloatLoads& l) {
    const FloatModel& f = *s.f;
    const int o = s.offset;
    const double th = y[o], thd = y[o + 1];
    const double rx = f.arm_length * std::cos(th), rz = f.arm_length * std::sin(th);
    const double vx = -rz * thd, vz = rx * thd;
    double fe_x = 0.0, fe_z = 0.0;
    s.excitation.evaluate(t, ramp, fe_x, fe_z);
    const double mu_x = s.surge.memory(y, o_.state_space, frac), mu_z = s.heave.memory(y, o_.state_space, frac);
    const double c_hs = model_.density * model_.gravity * f.waterplane_area;
    const double zf = f.hinge_z + rz;
    const double m_pto = -f.pto_damping * thd - f.pto_stiffness * (th - f.theta0);
    // Paper eq 11 / 16–17.
    const double J = f.inertia_hinge + s.heave.a_inf * rx * rx + s.surge.a_inf * rz * rz;
    const double thdd = (rx * (fe_z - mu_z - c_hs * zf) - rz * (fe_x - mu_x) +
                         rx * rz * (s.heave.a_inf - s.surge.a_inf) * thd * thd + m_pto) / J;
    dy[o] = thd;
    dy[o + 1] = thdd;
    if (o_.state_space) {
      s.surge.derivative(y, vx, dy);
      s.heave.derivative(y, vz, dy);
    }
    // Hinge reaction (paper eqs 14–15): F_h = Q_hydro − m ü.
    const double ax = -rz * thdd - rx * thd * thd, az = rx * thdd - rz * thd * thd;
    const double qx = fe_x - mu_x - s.surge.a_inf * ax, qz = fe_z - mu_z - c_hs * zf - s.heave.a_inf * az;
    l.theta = th;
    l.theta_dt = thd;
    l.theta_dtdt = thdd;
    l.fx = qx - f.mass * ax;
    l.fz = qz - f.mass * az;
    l.moment = rx * qz - rz * qx + m_pto;
    l.p_pto = f.pto_damping * thd * thd;
    l.p_exc = fe_x * vx + fe_z * vz;
    l.p_rad = mu_x * vx + mu_z * vz;
    l.energy = 0.5 * f.inertia_hinge * thd * thd + 0.5 * (s.surge.a_inf * vx * vx + s.heave.a_inf * vz * vz) +
               0.5 * c_hs * zf * zf + 0.5 * f.pto_stiffness * (th - f.theta0) * (th - f.theta0);
  }

  void augmented(FloatSystem& s, double t, double ramp, double frac, const Eigen::VectorXd& y, Eigen::VectorXd& dy,
                 FloatLoads& l) {
    const FloatModel& f = *s.f;
    const int o = s.offset;
    const double x = y[o], z = y[o + 1], th = y[o + 2], xd = y[o + 3], zd = y[o + 4], thd = y[o + 5];
    const double L = f.arm_length, sn = std::sin(th), cs = std::cos(th);
    double fe_x = 0.0, fe_z = 0.0;
    s.excitation.evaluate(t, ramp, fe_x, fe_z);
    const double mu_x = s.surge.memory(y, o_.state_space, frac), mu_z = s.heave.memory(y, o_.state_space, frac);
    const double c_hs = model_.density * model_.gravity * f.waterplane_area;
    const double m_pto = -f.pto_damping * thd - f.pto_stiffness * (th - f.theta0);
    // Generalised forces and mass matrix (diagonal).
    const Eigen::Vector3d q(fe_x - mu_x, fe_z - mu_z - c_hs * z, m_pto);
    const Eigen::Vector3d m_inv(1.0 / (f.mass + s.surge.a_inf), 1.0 / (f.mass + s.heave.a_inf), 1.0 / f.inertia_cg);
    // Constraint Jacobian, C, Ċ and the acceleration right-hand side with Baumgarte terms.
    Eigen::Matrix<double, 2, 3> cq;
    cq << 1.0, 0.0, L * sn, 0.0, 1.0, -L * cs;
    const Eigen::Vector2d c(x - f.hinge_x - L * cs, z - f.hinge_z - L * sn);
    const Eigen::Vector2d cd = cq * Eigen::Vector3d(xd, zd, thd);
    const double a = o_.baumgarte_rate;
    const Eigen::Vector2d qc = Eigen::Vector2d(-L * cs * thd * thd, -L * sn * thd * thd) - 2.0 * a * cd - a * a * c;
    // Schur complement: (C_q M⁻¹ C_qᵀ) λ = C_q M⁻¹ Q − Q_c;  q̈ = M⁻¹ (Q − C_qᵀ λ).
    const Eigen::Matrix2d schur = cq * m_inv.asDiagonal() * cq.transpose();
    const Eigen::Vector2d lambda = schur.inverse() * (cq * m_inv.cwiseProduct(q) - qc);
    const Eigen::Vector3d qdd = m_inv.cwiseProduct(q - cq.transpose() * lambda);
    dy[o] = xd;
    dy[o + 1] = zd;
    dy[o + 2] = thd;
    dy.segment<3>(o + 3) = qdd;
    if (o_.state_space) {
      s.surge.derivative(y, xd, dy);
      s.heave.derivative(y, zd, dy);
    }
    const double rx = x - f.hinge_x, rz = z - f.hinge_z;
    const double qx = q[0] - s.surge.a_inf * qdd[0], qz = q[1] - s.heave.a_inf * qdd[1];
    l.theta = th;
    l.theta_dt = thd;
    l.theta_dtdt = qdd[2];
    l.fx = lambda[0];
    l.fz = lambda[1];
    l.moment = rx * qz - rz * qx + m_pto;
    l.p_pto = f.pto_damping * thd * thd;
    l.p_exc = fe_x * xd + fe_z * zd;
    l.p_rad = mu_x * xd + mu_z * zd;
    l.energy = 0.5 * ((f.mass + s.surge.a_inf) * xd * xd + (f.mass + s.heave.a_inf) * zd * zd +
                      f.inertia_cg * thd * thd + c_hs * z * z + f.pto_stiffness * (th - f.theta0) * (th - f.theta0));
  }

  const WecModel& model_;
  const WaveField& waves_;
  TimeDomainOptions o_;
  std::vector<FloatSystem> systems_;
  int size_ = 0;
  long evaluations_ = 0;
};

}  // namespace

double rk4StabilityStep(const WecModel& model, const TimeDomainOptions& options) {
  double fastest = 0.0;  // [1/s] largest |λ| scaled to the RK4 real-axis limit 2.785
  for (const auto& f : model.floats) {
    if (options.state_space)
      for (const auto* fit : {&f.surge.fit, &f.heave.fit})
        for (const auto& m : fit->modes) fastest = std::max(fastest, std::abs(m.pole) / 2.785);
    fastest = std::max(fastest, naturalFrequency(model, f) / 2.828);
  }
  if (options.augmented) fastest = std::max(fastest, options.baumgarte_rate / 2.785);
  return fastest > 0.0 ? 1.0 / fastest : 1.0;
}

TimeDomainResult simulateTimeDomain(const WecModel& model, const WaveField& waves, const TimeDomainOptions& o,
                                    RunContext* context) {
  Simulator sim(model, waves, o);
  const std::size_t nf = model.floats.size();
  TimeDomainResult r;
  r.floats.resize(nf);
  r.stability_step = rk4StabilityStep(model, o);
  r.method = std::string(o.augmented ? "augmented" : "classical") + ", RK4 h=" + std::to_string(o.time_step) +
             " s, radiation " + (o.state_space ? "state-space" : "direct convolution");
  const double h = o.time_step;
  const long n_steps = std::lround(o.duration / h);
  Eigen::VectorXd y = sim.initialState(), k1(sim.size()), k2(sim.size()), k3(sim.size()), k4(sim.size()), tmp(sim.size());
  std::vector<FloatLoads> loads(nf), prev(nf);
  std::vector<double> e_pto(nf, 0.0), w_exc(nf, 0.0), w_rad(nf, 0.0);
  sim.advanceHistory(y);

  auto record = [&](double t) {
    r.time.push_back(t);
    r.wave_at_origin.push_back(waves.elevation(0.0, t));
    for (std::size_t i = 0; i < nf; ++i) {
      auto& hst = r.floats[i];
      const auto& l = loads[i];
      hst.theta.push_back(l.theta);
      hst.theta_dt.push_back(l.theta_dt);
      hst.theta_dtdt.push_back(l.theta_dtdt);
      hst.hinge_fx.push_back(l.fx);
      hst.hinge_fz.push_back(l.fz);
      hst.moment_y.push_back(l.moment);
      hst.pto_power.push_back(l.p_pto);
      hst.pto_energy.push_back(e_pto[i]);
      hst.excitation_work.push_back(w_exc[i]);
      hst.radiation_work.push_back(w_rad[i]);
      hst.mechanical_energy.push_back(l.energy);
    }
  };

  for (long n = 0;; ++n) {
    const double t = h * static_cast<double>(n);
    sim.rhs(t, 0.0, y, k1, &loads);
    // Energy bookkeeping by the trapezoid rule between recorded instants.
    if (n > 0)
      for (std::size_t i = 0; i < nf; ++i) {
        e_pto[i] += 0.5 * h * (prev[i].p_pto + loads[i].p_pto);
        w_exc[i] += 0.5 * h * (prev[i].p_exc + loads[i].p_exc);
        w_rad[i] += 0.5 * h * (prev[i].p_rad + loads[i].p_rad);
      }
    prev = loads;
    if (n % o.output_stride == 0 || n == n_steps) record(t);
    if (n == n_steps) break;
    // One RK4 step.
    tmp = y + 0.5 * h * k1;
    sim.rhs(t + 0.5 * h, 0.5, tmp, k2, nullptr);
    tmp = y + 0.5 * h * k2;
    sim.rhs(t + 0.5 * h, 0.5, tmp, k3, nullptr);
    tmp = y + h * k3;
    sim.rhs(t + h, 1.0, tmp, k4, nullptr);
    y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (o.augmented) sim.project(y, r.max_position_drift, r.max_velocity_drift);
    throwIfNotFinite(y, t + h, n + 1, [&](Eigen::Index k) {
      std::string what = "state " + std::to_string(k);
      if (h > r.stability_step) what += " (time step above the estimated RK4 stability limit " +
                                        std::to_string(r.stability_step) + " s)";
      return what;
    });
    sim.advanceHistory(y);
    if (context && n % 64 == 0) {
      context->throwIfCancelled();
      context->progress(static_cast<double>(n) / static_cast<double>(n_steps), "time integration");
    }
  }
  r.steps = n_steps;
  r.rhs_evaluations = sim.evaluations();
  return r;
}

Complex harmonicAmplitude(const std::vector<double>& t, const std::vector<double>& s, double omega, int periods) {
  const double period = 2.0 * std::numbers::pi / omega;
  const double dt = t[1] - t[0];
  const auto per_period = static_cast<std::size_t>(std::lround(period / dt));
  const std::size_t count = per_period * static_cast<std::size_t>(periods);
  const std::size_t start = t.size() - count;
  Complex sum(0.0, 0.0);
  for (std::size_t i = start; i < t.size(); ++i) sum += s[i] * std::polar(1.0, -omega * t[i]);
  return 2.0 * sum / static_cast<double>(count);
}

}  // namespace maris::wec
