// Valid seismic parameters that are doubtful for what the model covers; warnings, never refusals.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "seismic/seismic_parameters.hpp"

namespace maris::seismic {

// An input (Ricker or B-spline pulse) with spectral content above the frequency the mesh resolves, and a
// simulated time too short for the incident wave to pass the top of the model.
std::vector<FieldError> seismicPlausibility(const SeismicParameters& p);

// Highest frequency [Hz] at which the input's displacement amplitude spectrum is still 1 % of its peak:
// Ricker |U| ∝ (f/f_p)² exp(−(f/f_p)²); cubic B-spline pulse of duration T |U| ∝ sinc⁴(fT/4). 0 for a record.
double inputBandEdge(const SeismicParameters& p);

}  // namespace maris::seismic
