// Work–precision of the shared integrators: run time against error at t1 for RK4 (several steps),
// DOPRI5 (several tolerances) and generalized-α (several steps, ρ∞ = 0.8 and 1), on
//   - the harmonic oscillator x'' + 4x = 0, x(0) = 1, v(0) = 0.5, t ∈ [0, 20] s (closed-form reference);
//   - Van der Pol, μ = 5, x(0) = 2, v(0) = 0, t ∈ [0, 10] s (reference: RK4 at h = 2.5e-5, whose own
//     error is checked by Richardson extrapolation and printed).
// Usage: bench_ode_work_precision [out.csv]   (default ode_work_precision.csv). Writes CSV (names row,
// units row, data) and prints a table. Timings are wall time per run, averaged over ≥ 50 ms of repeats.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/closed_forms.hpp"
#include "core/ode.hpp"
#include "core/scenario.hpp"

namespace {

using maris::OdeOptions;
using maris::OdeStats;
using maris::RunContext;

struct Problem {
  std::string name;
  double t1;
  Eigen::Vector2d y0;
  maris::OdeRhs rhs;
  maris::SecondOrderSystem second_order;
  Eigen::Vector2d reference;  // (x, v) at t1
};

struct Row {
  std::string problem, method, parameter_name;
  double parameter;
  long steps, rhs_evaluations;
  double error, error_estimate, seconds;
};

// Runs `once` repeatedly for at least 50 ms and returns seconds per run.
double timePerRun(const std::function<void()>& once) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  long runs = 0;
  double elapsed = 0.0;
  do {
    once();
    ++runs;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < 0.05);
  return elapsed / static_cast<double>(runs);
}

Problem oscillator() {
  const double omega = 2.0;
  Problem p;
  p.name = "harmonic_oscillator";
  p.t1 = 20.0;
  p.y0 = {1.0, 0.5};
  p.rhs = [omega](double, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
    d[0] = y[1];
    d[1] = -omega * omega * y[0];
  };
  p.second_order.size = 1;
  p.second_order.residual = [omega](double, const Eigen::VectorXd& q, const Eigen::VectorXd&,
                                    const Eigen::VectorXd& a, Eigen::VectorXd& r) { r[0] = a[0] + omega * omega * q[0]; };
  const maris::OscillatorState exact = maris::harmonicOscillator(omega, 1.0, 0.5, p.t1);
  p.reference = {exact.position, exact.velocity};
  return p;
}

Eigen::Vector2d rk4Solution(const Problem& p, double h) {
  Eigen::VectorXd y = p.y0;
  OdeOptions o;
  o.t1 = p.t1;
  o.step = h;
  RunContext ctx;
  maris::integrateRk4(p.rhs, y, o, ctx);
  return y;
}

Problem vanDerPol() {
  const double mu = 5.0;
  Problem p;
  p.name = "van_der_pol_mu5";
  p.t1 = 10.0;
  p.y0 = {2.0, 0.0};
  p.rhs = [mu](double, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
    d[0] = y[1];
    d[1] = mu * (1.0 - y[0] * y[0]) * y[1] - y[0];
  };
  p.second_order.size = 1;
  p.second_order.residual = [mu](double, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                                 Eigen::VectorXd& r) { r[0] = a[0] - mu * (1.0 - q[0] * q[0]) * v[0] + q[0]; };
  p.reference = rk4Solution(p, 2.5e-5);
  const double richardson = (p.reference - rk4Solution(p, 5e-5)).cwiseAbs().maxCoeff() / 15.0;
  std::printf("Van der Pol reference: RK4 h = 2.5e-5, Richardson error estimate %.2e\n", richardson);
  return p;
}

void runAll(const Problem& p, std::vector<Row>& rows) {
  auto error_of = [&](const Eigen::Vector2d& y) { return (y - p.reference).cwiseAbs().maxCoeff(); };
  for (double h : {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001}) {
    Eigen::Vector2d y;
    OdeStats stats;
    const double seconds = timePerRun([&] {
      Eigen::VectorXd state = p.y0;
      OdeOptions o;
      o.t1 = p.t1;
      o.step = h;
      RunContext ctx;
      stats = maris::integrateRk4(p.rhs, state, o, ctx);
      y = state;
    });
    rows.push_back({p.name, "rk4", "step", h, stats.steps, stats.rhs_evaluations, error_of(y), stats.error_estimate, seconds});
  }
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    Eigen::Vector2d y;
    OdeStats stats;
    const double seconds = timePerRun([&] {
      Eigen::VectorXd state = p.y0;
      OdeOptions o;
      o.t1 = p.t1;
      o.step = 0.0;
      o.rtol = o.atol = tol;
      RunContext ctx;
      stats = maris::integrateDopri5(p.rhs, state, o, ctx);
      y = state;
    });
    rows.push_back({p.name, "dopri5", "tolerance", tol, stats.steps, stats.rhs_evaluations, error_of(y), stats.error_estimate, seconds});
  }
  for (double rho : {0.8, 1.0}) {
    for (double h : {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001}) {
      Eigen::Vector2d y;
      OdeStats stats;
      const double seconds = timePerRun([&] {
        Eigen::VectorXd q = p.y0.head(1), v = p.y0.tail(1);
        OdeOptions o;
        o.t1 = p.t1;
        o.step = h;
        o.rtol = 1e-10;
        o.atol = 1e-12;
        maris::GeneralizedAlphaOptions alpha;
        alpha.rho_inf = rho;
        RunContext ctx;
        stats = maris::integrateGeneralizedAlpha(p.second_order, q, v, o, alpha, ctx);
        y = {q[0], v[0]};
      });
      rows.push_back({p.name, rho == 1.0 ? "generalized_alpha_rho1" : "generalized_alpha_rho0.8", "step", h,
                      stats.steps, stats.rhs_evaluations, error_of(y), stats.error_estimate, seconds});
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "ode_work_precision.csv";
  std::vector<Row> rows;
  runAll(oscillator(), rows);
  runAll(vanDerPol(), rows);

  std::string csv = "problem,method,parameter_name,parameter,steps,rhs_evaluations,error,error_estimate,time\n"
                    "-,-,-,s or -,-,-,state units,-,s\n";
  std::printf("%-20s %-26s %-10s %10s %9s %10s %11s %11s %11s\n", "problem", "method", "param", "value", "steps",
              "rhs evals", "error", "estimate", "time [s]");
  for (const Row& r : rows) {
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%s,%.6g,%ld,%ld,%.6e,%.6e,%.6e\n", r.problem.c_str(), r.method.c_str(),
                  r.parameter_name.c_str(), r.parameter, r.steps, r.rhs_evaluations, r.error, r.error_estimate,
                  r.seconds);
    csv += line;
    std::printf("%-20s %-26s %-10s %10.3g %9ld %10ld %11.3e %11.3e %11.3e\n", r.problem.c_str(), r.method.c_str(),
                r.parameter_name.c_str(), r.parameter, r.steps, r.rhs_evaluations, r.error, r.error_estimate,
                r.seconds);
  }
  maris::writeFileAtomic(out, csv);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}
