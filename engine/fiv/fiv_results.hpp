// Turns FIV solutions into Results: the sweep table (A*, f*, P, ⟨Fẏ⟩, η, residuals per h*, up and
// down), the paper's points as reference tables, plots, the detail point's histories and spectra,
// and the animated 3D view of the cylinder on its springs under the free surface.
#pragma once

#include <string>
#include <vector>

#include "core/results.hpp"
#include "fiv/fiv_limit_cycle.hpp"
#include "fiv/fiv_reference.hpp"
#include "fiv/fiv_sweep.hpp"

namespace maris::fiv {

// Table "sweep" (one row per speed), per-h* scalars (onset speeds, maxima) and the curve plots,
// with reference markers from the tables addReferenceTables() writes.
void addSweepResults(Results& results, const FivModel& model, const SweepResult& sweep, bool has_reference);

// Tables "paper_amplitude", "paper_frequency", "paper_power" (x columns U and U_star, U* with this
// model's f_n). The power table also carries η implied by the paper's P and A at that point.
void addReferenceTables(Results& results, const FivModel& model, const std::vector<ReferencePoint>& points);

// The detail point: scalars, table "detail_history", table "detail_spectrum" (y and lift), the 3D view.
struct DetailPoint {
  OperatingPoint point;
  LimitCycle cycle;
  History history;
  double clearance = 0.0;  // [m] h − D/2 (∞ for deep)
};
void addDetailResults(Results& results, const FivModel& model, const DetailPoint& detail, int animation_frames);

// The 3D frames: the cylinder (a box) on two springs, anchored below, the free surface at z = 0.
View3D buildCylinderView(const FivModel& model, const DetailPoint& detail, int frames);

}  // namespace maris::fiv
