// Convergence of the bending stress with the segment count (paper Sect. 9, case 5: "σ_b(L/2) against n"): the
// whole time history repeated at several n, the first probe's bending stress tabulated against n.
//
// The probe's stress is interpolated between the joints that bracket it (riser_results), so it converges at
// second order in n; at its nearest joint, up to Δ/2 away, it converged at first order (case 5, J3, σ_b(L/2) at
// 24 s: 10.18, 10.36, 10.70, 10.85, 10.94, 10.98 MPa at n = 10 … 400, differences halving with Δ).
#pragma once

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "riser/riser_parameters.hpp"

namespace maris::riser {

// Runs p at each n of p.convergence_segment_counts (under a harmonic top motion by generalized-α with its step from
// p.convergence_tolerance, otherwise with p's solver settings; the rest of p unchanged) and appends table
// "bending_stress_vs_segments": segment_count, the first probe's largest bending stress over the run and its value
// at each stress time in (0, end_time], the integrator's error estimate (generalized-α: the expected probe error),
// steps and wall time; with two rows or more also "bending_stress_difference_vs_segments" (relative difference of
// each row's values from the finest n's) with log–log plots. Reports progress per
// row, honours cancellation, passes on each row's warnings naming its n; a row that fails throws SolverError
// naming its n. Does nothing when the list is empty.
void addStressConvergence(const RiserParameters& p, Results& results, RunContext& context);

}  // namespace maris::riser
