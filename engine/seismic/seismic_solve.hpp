// Stages of a seismic run, called by the scene (seismic_scene.cpp): input history, free-field report,
// finite-element runs and their post-processing.
#pragma once

#include <vector>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "seismic/free_field.hpp"
#include "seismic/seismic_parameters.hpp"

namespace maris::seismic {

// Incident displacement at the origin [m], sampled at t_k = k·dt (k < n), leaving zero at `arrival` [s].
// Throws InputError for an unreadable accelerogram.
std::vector<double> incidentHistory(const SeismicParameters& p, double dt, int n, double arrival);

// Time [s] at which the incident wave reaches the origin, chosen so that it reaches the model's
// first corner (bottom, upstream side) 0.05 s after t = 0.
double arrivalAtOrigin(const SeismicParameters& p, const FreeField& field);

// Free-field transfer functions, histories at the seabed (B) and water surface (A), energy check.
void addFreeFieldResults(const SeismicParameters& p, const FreeField& field, Results& results, RunContext& ctx);

// The whole run: free field, then the finite-element model(s) and their post-processing.
Results solveSeismic(const SeismicParameters& p, RunContext& ctx);

}  // namespace maris::seismic
