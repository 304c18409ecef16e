#include "wec/wec_dynamics.hpp"

#include <algorithm>
#include <cmath>

namespace maris::wec {

double MemoryChannel::memory(const Eigen::VectorXd& y, bool state_space, double frac) const {
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

void MemoryChannel::derivative(const Eigen::VectorXd& y, double v, Eigen::VectorXd& dy) const {
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

WecDynamics::WecDynamics(const WecModel& model, const IncidentWaves& waves, const TimeDomainOptions& o)
    : model_(model), waves_(waves), o_(o) {
  const int nf = static_cast<int>(model.floats.size());
  int n = 0;
  for (const auto& f : model.floats) {
    FloatSystem s;
    s.f = &f;
    s.excitation = makeExcitation(model, f, waves);
    s.offset = n;
    n += o.augmented ? 6 : 2;
    systems_.push_back(std::move(s));
  }
  // Radiation channels: the diagonal of every float, then the off-diagonal entries of coupled coefficients.
  a_inf_ = Eigen::MatrixXd::Zero(2 * nf, 2 * nf);
  auto add = [&](int row, int col, const ModeRadiation& rad) {
    MemoryChannel c;
    c.row = row;
    c.col = col;
    c.fit = &rad.fit;
    a_inf_(row, col) = rad.a_inf;
    if (o.state_space) {
      c.offset = n;
      n += rad.fit.order;
    } else {
      RadiationKernel k;
      k.dt = o.time_step;
      const auto count = static_cast<std::size_t>(rad.kernel.duration() / o.time_step) + 1;
      for (std::size_t j = 0; j < count; ++j) k.values.push_back(rad.kernel.at(o.time_step * static_cast<double>(j)));
      c.convolution = DirectConvolution(k);
    }
    channels_.push_back(std::move(c));
  };
  for (int i = 0; i < nf; ++i) {
    add(2 * i, 2 * i, model.floats[static_cast<std::size_t>(i)].surge);
    add(2 * i + 1, 2 * i + 1, model.floats[static_cast<std::size_t>(i)].heave);
  }
  for (const auto& c : model.cross) add(c.row, c.col, c.mode);
  size_ = n;
  // Constant mass matrix of the augmented formulation.
  if (o.augmented) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(3 * nf, 3 * nf);
    for (int i = 0; i < nf; ++i) {
      const FloatModel& f = model.floats[static_cast<std::size_t>(i)];
      m(3 * i, 3 * i) = m(3 * i + 1, 3 * i + 1) = f.mass;
      m(3 * i + 2, 3 * i + 2) = f.inertia_cg;
      for (int j = 0; j < nf; ++j)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) m(3 * i + a, 3 * j + b) += a_inf_(2 * i + a, 2 * j + b);
    }
    m_inv_ = m.inverse();
    cq_ = Eigen::MatrixXd::Zero(2 * nf, 3 * nf);
    q_.resize(3 * nf);
    acc_.resize(3 * nf);
  } else {
    mat_n_.resize(nf, nf);
    acc_.resize(nf);
  }
  vel_.resize(2 * nf);
  mu_.resize(2 * nf);
  exc_.resize(2 * nf);
  rhs_n_.resize(2 * nf);
  rx_.resize(static_cast<std::size_t>(nf));
  rz_.resize(static_cast<std::size_t>(nf));
}

Eigen::VectorXd WecDynamics::initialState() const {
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

void WecDynamics::velocities(const Eigen::VectorXd& y, Eigen::VectorXd& v) const {
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    const int o = systems_[i].offset, k = 2 * static_cast<int>(i);
    if (o_.augmented) {
      v[k] = y[o + 3];
      v[k + 1] = y[o + 4];
    } else {
      const double L = systems_[i].f->arm_length;
      v[k] = -L * std::sin(y[o]) * y[o + 1];
      v[k + 1] = L * std::cos(y[o]) * y[o + 1];
    }
  }
}

void WecDynamics::rhs(double t, double frac, const Eigen::VectorXd& y, Eigen::VectorXd& dy,
                      std::vector<FloatLoads>* loads) {
  ++evaluations_;
  const double ramp = waves_.ramp(t);
  // Velocities, memory forces (and modal state derivatives), excitation.
  velocities(y, vel_);
  mu_.setZero();
  for (const auto& c : channels_) {
    mu_[c.row] += c.memory(y, o_.state_space, frac);
    if (o_.state_space) c.derivative(y, vel_[c.col], dy);
  }
  for (std::size_t i = 0; i < systems_.size(); ++i)
    systems_[i].excitation.evaluate(t, ramp, exc_[2 * static_cast<int>(i)], exc_[2 * static_cast<int>(i) + 1]);
  if (o_.augmented)
    augmented(t, ramp, y, dy, loads);
  else
    classical(t, ramp, y, dy, loads);
}

void WecDynamics::classical(double, double, const Eigen::VectorXd& y, Eigen::VectorXd& dy,
                            std::vector<FloatLoads>* loads) {
  const int nf = static_cast<int>(systems_.size());
  const double c_w = model_.density * model_.gravity;
  // Centripetal accelerations c_i = −r_i θ̇_i² stored in rhs_n_ temporarily as 2N values.
  Eigen::VectorXd& cen = rhs_n_;
  for (int i = 0; i < nf; ++i) {
    const FloatModel& f = *systems_[static_cast<std::size_t>(i)].f;
    const int o = systems_[static_cast<std::size_t>(i)].offset;
    const double th = y[o], thd = y[o + 1];
    rx_[static_cast<std::size_t>(i)] = f.arm_length * std::cos(th);
    rz_[static_cast<std::size_t>(i)] = f.arm_length * std::sin(th);
    cen[2 * i] = -rx_[static_cast<std::size_t>(i)] * thd * thd;
    cen[2 * i + 1] = -rz_[static_cast<std::size_t>(i)] * thd * thd;
  }
  // Coupled pitch equations J θ̈ = b (paper eq 11 with the A∞ coupling between floats).
  Eigen::VectorXd b(nf);
  for (int i = 0; i < nf; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const FloatModel& f = *systems_[si].f;
    const int o = systems_[si].offset;
    const double tx = -rz_[si], tz = rx_[si];
    const double zf = f.hinge_z + rz_[si];
    double fx = exc_[2 * i] - mu_[2 * i], fz = exc_[2 * i + 1] - mu_[2 * i + 1] - c_w * f.waterplane_area * zf;
    for (int j = 0; j < nf; ++j) {
      const auto sj = static_cast<std::size_t>(j);
      fx -= a_inf_(2 * i, 2 * j) * cen[2 * j] + a_inf_(2 * i, 2 * j + 1) * cen[2 * j + 1];
      fz -= a_inf_(2 * i + 1, 2 * j) * cen[2 * j] + a_inf_(2 * i + 1, 2 * j + 1) * cen[2 * j + 1];
      const double ux = -rz_[sj], uz = rx_[sj];
      mat_n_(i, j) = tx * (a_inf_(2 * i, 2 * j) * ux + a_inf_(2 * i, 2 * j + 1) * uz) +
                     tz * (a_inf_(2 * i + 1, 2 * j) * ux + a_inf_(2 * i + 1, 2 * j + 1) * uz);
    }
    mat_n_(i, i) += f.inertia_hinge;
    const double m_pto = -f.pto_damping * y[o + 1] - f.pto_stiffness * (y[o] - f.theta0);
    b[i] = tx * fx + tz * fz + m_pto;
  }
  if (nf == 1)
    acc_[0] = b[0] / mat_n_(0, 0);
  else
    acc_ = mat_n_.ldlt().solve(b);
  // Translational accelerations, then loads: F_h = Q_hydro − m ü (paper eqs 14–15).
  Eigen::VectorXd udd(2 * nf);
  for (int i = 0; i < nf; ++i) {
    const auto si = static_cast<std::size_t>(i);
    udd[2 * i] = -rz_[si] * acc_[i] + cen[2 * i];
    udd[2 * i + 1] = rx_[si] * acc_[i] + cen[2 * i + 1];
  }
  const Eigen::VectorXd a_udd = a_inf_ * udd, a_vel = a_inf_ * vel_;
  for (int i = 0; i < nf; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const FloatModel& f = *systems_[si].f;
    const int o = systems_[si].offset;
    const double th = y[o], thd = y[o + 1], zf = f.hinge_z + rz_[si];
    dy[o] = thd;
    dy[o + 1] = acc_[i];
    if (!loads) continue;
    const double c_hs = c_w * f.waterplane_area;
    const double m_pto = -f.pto_damping * thd - f.pto_stiffness * (th - f.theta0);
    const double qx = exc_[2 * i] - mu_[2 * i] - a_udd[2 * i];
    const double qz = exc_[2 * i + 1] - mu_[2 * i + 1] - c_hs * zf - a_udd[2 * i + 1];
    const double vx = vel_[2 * i], vz = vel_[2 * i + 1];
    FloatLoads& l = (*loads)[si];
    l.theta = th;
    l.theta_dt = thd;
    l.theta_dtdt = acc_[i];
    l.fx = qx - f.mass * udd[2 * i];
    l.fz = qz - f.mass * udd[2 * i + 1];
    l.moment = rx_[si] * qz - rz_[si] * qx + m_pto;
    l.p_pto = f.pto_damping * thd * thd;
    l.p_exc = exc_[2 * i] * vx + exc_[2 * i + 1] * vz;
    l.p_rad = mu_[2 * i] * vx + mu_[2 * i + 1] * vz;
    l.energy = 0.5 * f.inertia_hinge * thd * thd + 0.5 * (vx * a_vel[2 * i] + vz * a_vel[2 * i + 1]) +
               0.5 * c_hs * zf * zf + 0.5 * f.pto_stiffness * (th - f.theta0) * (th - f.theta0);
  }
}

void WecDynamics::augmented(double, double, const Eigen::VectorXd& y, Eigen::VectorXd& dy,
                            std::vector<FloatLoads>* loads) {
  const int nf = static_cast<int>(systems_.size());
  const double c_w = model_.density * model_.gravity, a = o_.baumgarte_rate;
  Eigen::VectorXd qc(2 * nf), qd(3 * nf);
  // Generalised forces Q, constraint Jacobian C_q and the acceleration right-hand side with Baumgarte terms.
  for (int i = 0; i < nf; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const FloatModel& f = *systems_[si].f;
    const int o = systems_[si].offset;
    const double x = y[o], z = y[o + 1], th = y[o + 2], thd = y[o + 5], L = f.arm_length;
    const double sn = std::sin(th), cs = std::cos(th);
    q_[3 * i] = exc_[2 * i] - mu_[2 * i];
    q_[3 * i + 1] = exc_[2 * i + 1] - mu_[2 * i + 1] - c_w * f.waterplane_area * z;
    q_[3 * i + 2] = -f.pto_damping * thd - f.pto_stiffness * (th - f.theta0);
    cq_(2 * i, 3 * i) = 1.0;
    cq_(2 * i, 3 * i + 2) = L * sn;
    cq_(2 * i + 1, 3 * i + 1) = 1.0;
    cq_(2 * i + 1, 3 * i + 2) = -L * cs;
    qd.segment<3>(3 * i) = y.segment<3>(o + 3);
    const double cx = x - f.hinge_x - L * cs, cz = z - f.hinge_z - L * sn;
    const double cdx = y[o + 3] + L * sn * thd, cdz = y[o + 4] - L * cs * thd;
    qc[2 * i] = -L * cs * thd * thd - 2.0 * a * cdx - a * a * cx;
    qc[2 * i + 1] = -L * sn * thd * thd - 2.0 * a * cdz - a * a * cz;
  }
  // Schur complement: (C_q M⁻¹ C_qᵀ) λ = C_q M⁻¹ Q − Q_c;  q̈ = M⁻¹ (Q − C_qᵀ λ).
  const Eigen::MatrixXd mc = m_inv_ * cq_.transpose();
  const Eigen::MatrixXd schur = cq_ * mc;
  const Eigen::VectorXd m_q = m_inv_ * q_;
  lam_ = schur.llt().solve(cq_ * m_q - qc);
  acc_ = m_q - mc * lam_;
  Eigen::VectorXd udd(2 * nf);
  for (int i = 0; i < nf; ++i) udd.segment<2>(2 * i) = acc_.segment<2>(3 * i);
  const Eigen::VectorXd a_udd = a_inf_ * udd, a_vel = a_inf_ * vel_;
  for (int i = 0; i < nf; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const FloatModel& f = *systems_[si].f;
    const int o = systems_[si].offset;
    dy.segment<3>(o) = qd.segment<3>(3 * i);
    dy.segment<3>(o + 3) = acc_.segment<3>(3 * i);
    if (!loads) continue;
    const double z = y[o + 1], th = y[o + 2], thd = y[o + 5];
    const double c_hs = c_w * f.waterplane_area;
    const double rx = y[o] - f.hinge_x, rz = z - f.hinge_z;
    const double qx = q_[3 * i] - a_udd[2 * i], qz = q_[3 * i + 1] - a_udd[2 * i + 1];
    const double vx = vel_[2 * i], vz = vel_[2 * i + 1];
    FloatLoads& l = (*loads)[si];
    l.theta = th;
    l.theta_dt = thd;
    l.theta_dtdt = acc_[3 * i + 2];
    l.fx = lam_[2 * i];
    l.fz = lam_[2 * i + 1];
    l.moment = rx * qz - rz * qx + q_[3 * i + 2];
    l.p_pto = f.pto_damping * thd * thd;
    l.p_exc = exc_[2 * i] * vx + exc_[2 * i + 1] * vz;
    l.p_rad = mu_[2 * i] * vx + mu_[2 * i + 1] * vz;
    l.energy = 0.5 * (f.mass * (vx * vx + vz * vz) + vx * a_vel[2 * i] + vz * a_vel[2 * i + 1] +
                      f.inertia_cg * thd * thd + c_hs * z * z + f.pto_stiffness * (th - f.theta0) * (th - f.theta0));
  }
}

void WecDynamics::project(Eigen::VectorXd& y, double& drift_p, double& drift_v) const {
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

void WecDynamics::advanceHistory(const Eigen::VectorXd& y) {
  if (o_.state_space) return;
  velocities(y, vel_);
  for (auto& c : channels_) {
    c.convolution.push(vel_[c.col]);
    c.mu_prev = c.mu_now;
    c.mu_now = c.convolution.valueNow();
  }
}

}  // namespace maris::wec
