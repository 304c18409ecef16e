// Calibration of the model's free coefficients to reference points (the paper's numbers or user
// data) by weighted least squares: minimise Σ ((model − reference)/σ)² over amplitude, frequency
// and power residuals with Levenberg–Marquardt, forward-difference Jacobian, coefficients kept in
// their schema ranges. Each reference point is simulated from near rest, as the CFD runs were.
#pragma once

#include <string>
#include <vector>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "fiv/fiv_parameters.hpp"
#include "fiv/fiv_reference.hpp"

namespace maris::fiv {

// One residual of the fit.
struct CalibrationResidual {
  double speed = 0.0;              // [m/s]
  double submergence_ratio = 0.0;  // [-] (infinite: deep)
  enum class Quantity { Amplitude, Frequency, Power } quantity = Quantity::Amplitude;
  double reference = 0.0;          // [m], [Hz] or [W]
  double model = 0.0;              // same unit
  double sigma = 0.0;              // same unit, the weight 1/σ
  double normalised() const { return (model - reference) / sigma; }
};

struct CalibrationResult {
  FivParameters parameters;               // input with the fitted coefficients written in
  std::vector<std::string> names;         // fitted parameter paths
  std::vector<double> initial, fitted;    // values before and after
  std::vector<double> standard_error;     // from (JᵀJ)⁻¹ scaled by the residual variance (0 if m <= n)
  std::vector<CalibrationResidual> residuals_initial, residuals;  // before and after
  double cost_initial = 0.0, cost = 0.0;  // Σ normalised residual²
  int iterations = 0;                     // Levenberg–Marquardt iterations (Jacobian evaluations)
  bool converged = false;                 // the last step gained less than 0.01 % of the cost
  std::string stop_reason;                // why the fit stopped (core/least_squares.hpp describe())
  long limit_cycles = 0;                  // simulations run
};

// Residuals of `p` against `points` (one simulation per point from the seed state).
std::vector<CalibrationResidual> calibrationResiduals(const FivParameters& p, const std::vector<ReferencePoint>& points,
                                                      RunContext& context, long* simulations = nullptr);

// Fits the coefficients named in p.free_coefficients. Throws InputError for unknown names or no data.
CalibrationResult calibrate(const FivParameters& p, const std::vector<ReferencePoint>& points, RunContext& context);

// Scalars calibrated_<path> and table "calibration_residuals"; a fit that did not converge is a warning. Returns,
// for a converged fit, the note with the values to save (for the run's method line), else "".
std::string addCalibrationResults(Results& results, const CalibrationResult& calibration);

}  // namespace maris::fiv
