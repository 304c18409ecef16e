#include "fiv/fiv_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <sstream>

#include <Eigen/Dense>

#include "core/errors.hpp"
#include "core/least_squares.hpp"
#include "fiv/fiv_limit_cycle.hpp"
#include "fiv/fiv_sweep.hpp"
#include "core/text_format.hpp"

namespace maris::fiv {

namespace {

// "galloping.force_scale" as people read it: "Calibrated force scale (galloping)".
std::string calibratedLabel(const std::string& path) {
  std::string text = "Calibrated " + path;
  if (const std::size_t dot = path.rfind('.'); dot != std::string::npos)
    text = "Calibrated " + path.substr(dot + 1) + " (" + path.substr(0, dot) + ")";
  std::replace(text.begin(), text.end(), '_', ' ');
  return text;
}

// σ of a reference value: the given one, else 5 % of the value (and never zero).
double sigmaOf(const std::optional<double>& sigma, double value) {
  const double s = sigma.value_or(0.05 * std::abs(value));
  return s > 0.0 ? s : 1e-12 + 0.05 * std::abs(value);
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
  // Levenberg–Marquardt (core/least_squares.hpp) with Marquardt's diagonal scaling; trial points are clamped
  // to the schema ranges. Differences with 2 % steps stay above the limit-cycle convergence noise (tolerance
  // 1e-3). Every evaluated point's residuals are kept so the accepted one needs no rerun.
  std::vector<std::pair<Eigen::VectorXd, std::vector<CalibrationResidual>>> evaluated;
  LeastSquaresProblem problem;
  problem.residuals = [&](const Eigen::VectorXd& at, Eigen::VectorXd& r) {
    auto values = calibrationResiduals(withCoefficients(p, res.names, at, ranges), points, context, &res.limit_cycles);
    r = vectorOf(values);
    evaluated.emplace_back(at, std::move(values));
    return true;
  };
  // Forward differences, except for a coefficient whose forward step would leave its range: it is differenced
  // backwards. Clamped, the forward point would equal the current one, leaving a zero column, and a
  // coefficient that reached its upper bound could never be moved off it again.
  constexpr double kDifferenceStep = 0.02, kDifferenceFloor = 0.05;
  problem.jacobian = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& r, Eigen::MatrixXd& jac) {
    jac.resize(r.size(), at.size());
    Eigen::VectorXd shifted = at, r_shifted;
    for (Eigen::Index j = 0; j < at.size(); ++j) {
      const Range& range = ranges[static_cast<std::size_t>(j)];
      double h = kDifferenceStep * std::max(std::abs(at[j]), kDifferenceFloor);
      if (at[j] + h > range.max) h = -h;
      shifted[j] = at[j] + h;
      if (!problem.residuals(shifted, r_shifted) || r_shifted.size() != r.size()) return false;
      jac.col(j) = (r_shifted - r) / h;
      shifted[j] = at[j];
    }
    return true;
  };
  problem.trial_point = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& step) {
    FivParameters trial = withCoefficients(p, res.names, at + step, ranges);
    Eigen::VectorXd clamped(static_cast<Eigen::Index>(n));  // the clamped values actually tried
    for (std::size_t i = 0; i < n; ++i) clamped[static_cast<Eigen::Index>(i)] = *coefficientByPath(trial, res.names[i]);
    return clamped;
  };
  LeastSquaresOptions options;
  options.max_iterations = p.calibration_iterations;
  options.max_trials = 8;
  options.initial_damping = 1e-2;
  options.min_damping = 1e-7;
  options.max_damping = std::numeric_limits<double>::infinity();
  options.cost_tolerance = 1e-4;  // a step gaining less than 0.01 % of the cost: stalled, done
  options.progress_stage = "calibration";
  const LeastSquaresReport fit = levenbergMarquardt(problem, x, options, &context);
  auto residualsAt = [&](const Eigen::VectorXd& at) {
    for (const auto& [point, values] : evaluated)
      if (point == at) return values;
    return calibrationResiduals(withCoefficients(p, res.names, at, ranges), points, context, &res.limit_cycles);
  };
  res.residuals_initial = evaluated.front().second;
  res.cost_initial = fit.initial_cost;
  res.iterations = fit.iterations;
  res.converged = fit.converged;
  res.stop_reason = describe(fit.stop);
  x = fit.x;
  const std::vector<CalibrationResidual> current = residualsAt(x);
  const double cost = fit.cost;
  if (!std::isfinite(cost))
    throw SolverError("calibration cost Σ((model − reference)/σ)²", std::nan(""), -1,
                      "is not finite (a model value or a reference point is not finite)");
  const Eigen::MatrixXd& jac = fit.jacobian;
  const auto m = static_cast<Eigen::Index>(current.size());
  res.parameters = withCoefficients(p, res.names, x, ranges);
  res.residuals = current;
  res.cost = cost;
  for (std::size_t i = 0; i < n; ++i) res.fitted.push_back(x[static_cast<Eigen::Index>(i)]);
  // Standard errors from the last Jacobian: cov = s² (JᵀJ)⁻¹, s² = cost/(m − n).
  res.standard_error.assign(n, 0.0);
  if (m > static_cast<Eigen::Index>(n) && jac.rows() == m) {
    const Eigen::MatrixXd cov = (jac.transpose() * jac).completeOrthogonalDecomposition().pseudoInverse() *
                                (cost / static_cast<double>(m - static_cast<Eigen::Index>(n)));
    for (std::size_t i = 0; i < n; ++i)
      res.standard_error[i] = std::sqrt(std::max(0.0, cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i))));
  }
  return res;
}

std::string addCalibrationResults(Results& results, const CalibrationResult& cal) {
  std::ostringstream note;
  if (cal.converged)
    note << "calibrated coefficients (save with --set or into the scenario's parameters):";
  else
    note << "the calibration did not converge (" << cal.stop_reason << " after " << cal.iterations
         << " of calibration.max_iterations; cost " << cal.cost_initial << " -> " << cal.cost
         << "); its coefficients are not a fit and are not recommended (allow more iterations or start elsewhere)";
  for (std::size_t i = 0; i < cal.names.size(); ++i) {
    results.addScalar("calibrated_" + cal.names[i], cal.fitted[i], "-",
                      "Fitted " + cal.names[i] + " (was " + numberText(cal.initial[i]) + "; ± " +
                          numberText(cal.standard_error[i]) + " standard error)",
                      calibratedLabel(cal.names[i]));
    if (cal.converged) note << " " << cal.names[i] << "=" << cal.fitted[i];
  }
  results.addScalar("calibration_cost_initial", cal.cost_initial, "-", "Σ((model − reference)/σ)² before the fit", "Calibration cost before");
  results.addScalar("calibration_cost", cal.cost, "-", "Σ((model − reference)/σ)² after the fit", "Calibration cost");
  results.addScalar("calibration_iterations", cal.iterations, "-",
                    "Levenberg–Marquardt iterations; " + std::string(cal.converged ? "converged" : "not converged") +
                        " (" + cal.stop_reason + ")", "Calibration iterations");
  results.addScalar("calibration_rms_residual", std::sqrt(cal.cost / std::max<std::size_t>(1, cal.residuals.size())),
                    "-", "RMS of the normalised residuals after the fit", "Calibration RMS residual");
  // A converged fit is the run's result, not a warning: its coefficients go to the method line (and scalars).
  if (!cal.converged) results.warnings.push_back(note.str());
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
  t.add("U", "m/s", u, "Current speed U");
  t.add("h_star_or_0_for_deep", "-", h, "h* (0: deep)");
  t.add("quantity", "-", q, "Quantity (1 A*, 2 f*, 3 P)");
  t.add("reference", "SI", ref, "Reference value");
  t.add("model_before", "SI", before, "Model before the fit");
  t.add("model_after", "SI", after, "Model after the fit");
  t.add("sigma", "SI", sig, "σ");
  t.add("normalised_residual_after", "-", norm, "Normalised residual after the fit");
  results.tables.push_back(std::move(t));
  return cal.converged ? note.str() : std::string();
}

}  // namespace maris::fiv
