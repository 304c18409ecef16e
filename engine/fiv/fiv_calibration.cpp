#include "fiv/fiv_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "core/errors.hpp"
#include "fiv/fiv_limit_cycle.hpp"
#include "fiv/fiv_sweep.hpp"

namespace maris::fiv {

namespace {

// σ of a reference value: the given one, else 5 % of the value (and never zero).
double sigmaOf(const std::optional<double>& sigma, double value) {
  const double s = sigma.value_or(0.05 * std::abs(value));
  return s > 0.0 ? s : 1e-12 + 0.05 * std::abs(value);
}

double costOf(const std::vector<CalibrationResidual>& r) {
  double c = 0.0;
  for (const auto& x : r) c += x.normalised() * x.normalised();
  return c;
}

Eigen::VectorXd vectorOf(const std::vector<CalibrationResidual>& r) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(r.size()));
  for (std::size_t i = 0; i < r.size(); ++i) v[static_cast<Eigen::Index>(i)] = r[i].normalised();
  return v;
}

// Writes coefficient values into a copy of p, clamped to each field's schema range.
FivParameters withCoefficients(const FivParameters& p, const std::vector<std::string>& names, const Eigen::VectorXd& x,
                               const std::vector<Range>& ranges) {
  FivParameters q = p;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const Range& r = ranges[i];
    const double lo = r.min_open ? r.min + 1e-9 * std::max(1.0, std::abs(r.min)) : r.min;
    const double hi = r.max_open ? r.max - 1e-9 * std::max(1.0, std::abs(r.max)) : r.max;
    *coefficientByPath(q, names[i]) = std::clamp(x[static_cast<Eigen::Index>(i)], lo, hi);
  }
  return q;
}

}  // namespace

std::vector<CalibrationResidual> calibrationResiduals(const FivParameters& p, const std::vector<ReferencePoint>& points,
                                                      RunContext& context, long* simulations) {
  const FivModel model = buildFivModel(p);
  const LimitCycleSettings settings = sweepSettingsFrom(p).cycle;
  std::vector<CalibrationResidual> out;
  for (const ReferencePoint& rp : points) {
    State state = seedState(model, p.initial_amplitude_ratio);
    const FivRhs rhs(model, makeOperatingPoint(model, rp.speed, rp.submergence_ratio));
    const LimitCycle c = runToLimitCycle(rhs, state, settings, &context);
    if (simulations) ++*simulations;
    auto add = [&](CalibrationResidual::Quantity q, const std::optional<double>& ref, const std::optional<double>& sig,
                   double model_value) {
      if (!ref) return;
      out.push_back({rp.speed, rp.submergence_ratio, q, *ref, model_value, sigmaOf(sig, *ref)});
    };
    add(CalibrationResidual::Quantity::Amplitude, rp.amplitude, rp.amplitude_sigma, c.amplitude);
    add(CalibrationResidual::Quantity::Frequency, rp.frequency, rp.frequency_sigma, c.frequency);
    add(CalibrationResidual::Quantity::Power, rp.power, rp.power_sigma, c.power_damper);
  }
  return out;
}

CalibrationResult calibrate(const FivParameters& p, const std::vector<ReferencePoint>& points, RunContext& context) {
  CalibrationResult res;
  res.names = splitCoefficientList(p.free_coefficients);
  if (points.empty()) throw InputError("calibration.reference_file", "\"" + p.reference_file + "\"", "holds no points");
  const Schema schema = fivBinder().schema();
  std::vector<Range> ranges;
  const std::size_t n = res.names.size();
  Eigen::VectorXd x(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    FivParameters copy = p;
    const double* v = coefficientByPath(copy, res.names[i]);
    if (!v) throw InputError("calibration.free_coefficients", "\"" + res.names[i] + "\"", "is not calibratable");
    x[static_cast<Eigen::Index>(i)] = *v;
    ranges.push_back(schema.find(res.names[i])->range);
    res.initial.push_back(*v);
  }
  // Levenberg–Marquardt with Marquardt's diagonal scaling.
  auto residuals = [&](const Eigen::VectorXd& at) {
    return calibrationResiduals(withCoefficients(p, res.names, at, ranges), points, context, &res.limit_cycles);
  };
  res.residuals_initial = residuals(x);
  std::vector<CalibrationResidual> current = res.residuals_initial;
  double cost = costOf(current), lambda = 1e-2;
  res.cost_initial = cost;
  const auto m = static_cast<Eigen::Index>(current.size());
  Eigen::MatrixXd jac(m, static_cast<Eigen::Index>(n));
  for (int it = 0; it < p.calibration_iterations; ++it) {
    res.iterations = it + 1;
    context.progress(static_cast<double>(it) / p.calibration_iterations, "calibration");
    // Forward differences; 2 % steps stay above the limit-cycle convergence noise (tolerance 1e-3).
    const Eigen::VectorXd r0 = vectorOf(current);
    for (std::size_t j = 0; j < n; ++j) {
      Eigen::VectorXd xp = x;
      const double h = 0.02 * std::max(std::abs(x[static_cast<Eigen::Index>(j)]), 0.05);
      xp[static_cast<Eigen::Index>(j)] += h;
      jac.col(static_cast<Eigen::Index>(j)) = (vectorOf(residuals(xp)) - r0) / h;
    }
    const Eigen::MatrixXd jtj = jac.transpose() * jac;
    const Eigen::VectorXd grad = jac.transpose() * r0;
    bool improved = false;
    for (int tries = 0; tries < 8 && !improved; ++tries) {
      Eigen::MatrixXd a = jtj;
      a.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-12);
      const Eigen::VectorXd step = a.ldlt().solve(-grad);
      FivParameters trial_p = withCoefficients(p, res.names, x + step, ranges);
      Eigen::VectorXd trial_x(static_cast<Eigen::Index>(n));  // the clamped values actually tried
      for (std::size_t i = 0; i < n; ++i) trial_x[static_cast<Eigen::Index>(i)] = *coefficientByPath(trial_p, res.names[i]);
      auto trial = calibrationResiduals(trial_p, points, context, &res.limit_cycles);
      const double trial_cost = costOf(trial);
      if (trial_cost < cost) {
        improved = true;
        const double gain = (cost - trial_cost) / std::max(cost, 1e-300);
        x = trial_x;
        current = std::move(trial);
        cost = trial_cost;
        lambda = std::max(lambda / 3.0, 1e-7);
        if (gain < 1e-4) {  // stalled: done
          res.converged = true;
          it = p.calibration_iterations;
        }
      } else {
        lambda *= 4.0;
      }
    }
    if (!improved) {  // no step lowers the cost: a minimum within the limit-cycle noise
      res.converged = true;
      break;
    }
  }
  if (!std::isfinite(cost))
    throw SolverError("calibration cost Σ((model − reference)/σ)²", std::nan(""), -1,
                      "is not finite (a model value or a reference point is not finite)");
  res.parameters = withCoefficients(p, res.names, x, ranges);
  res.residuals = current;
  res.cost = cost;
  for (std::size_t i = 0; i < n; ++i) res.fitted.push_back(x[static_cast<Eigen::Index>(i)]);
  // Standard errors from the last Jacobian: cov = s² (JᵀJ)⁻¹, s² = cost/(m − n).
  res.standard_error.assign(n, 0.0);
  if (m > static_cast<Eigen::Index>(n)) {
    const Eigen::MatrixXd cov = (jac.transpose() * jac).completeOrthogonalDecomposition().pseudoInverse() *
                                (cost / static_cast<double>(m - static_cast<Eigen::Index>(n)));
    for (std::size_t i = 0; i < n; ++i)
      res.standard_error[i] = std::sqrt(std::max(0.0, cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i))));
  }
  return res;
}

void addCalibrationResults(Results& results, const CalibrationResult& cal) {
  std::ostringstream note;
  if (cal.converged)
    note << "calibrated coefficients (save with --set or into the scenario's parameters):";
  else
    note << "the calibration did not converge within calibration.max_iterations = " << cal.iterations << " (cost "
         << cal.cost_initial << " -> " << cal.cost
         << "); its coefficients are not a fit and are not recommended (allow more iterations or start elsewhere)";
  for (std::size_t i = 0; i < cal.names.size(); ++i) {
    results.addScalar("calibrated_" + cal.names[i], cal.fitted[i], "-",
                      "Fitted " + cal.names[i] + " (was " + std::to_string(cal.initial[i]) + "; ± " +
                          std::to_string(cal.standard_error[i]) + " standard error)");
    if (cal.converged) note << " " << cal.names[i] << "=" << cal.fitted[i];
  }
  results.addScalar("calibration_cost_initial", cal.cost_initial, "-", "Σ((model − reference)/σ)² before the fit");
  results.addScalar("calibration_cost", cal.cost, "-", "Σ((model − reference)/σ)² after the fit");
  results.addScalar("calibration_rms_residual", std::sqrt(cal.cost / std::max<std::size_t>(1, cal.residuals.size())),
                    "-", "RMS of the normalised residuals after the fit");
  results.warnings.push_back(note.str());
  Table t;
  t.name = "calibration_residuals";
  t.title = "Calibration residuals (quantity 0 = amplitude [m], 1 = frequency [Hz], 2 = power [W])";
  std::vector<double> u, h, q, ref, before, after, sig, norm;
  for (std::size_t i = 0; i < cal.residuals.size(); ++i) {
    const auto& r = cal.residuals[i];
    u.push_back(r.speed);
    h.push_back(std::isfinite(r.submergence_ratio) ? r.submergence_ratio : 0.0);
    q.push_back(static_cast<double>(static_cast<int>(r.quantity)));
    ref.push_back(r.reference);
    before.push_back(cal.residuals_initial[i].model);
    after.push_back(r.model);
    sig.push_back(r.sigma);
    norm.push_back(r.normalised());
  }
  t.add("U", "m/s", u);
  t.add("h_star_or_0_for_deep", "-", h);
  t.add("quantity", "-", q);
  t.add("reference", "SI", ref);
  t.add("model_before", "SI", before);
  t.add("model_after", "SI", after);
  t.add("sigma", "SI", sig);
  t.add("normalised_residual_after", "-", norm);
  results.tables.push_back(std::move(t));
}

}  // namespace maris::fiv
