// The ship resistance study: parameters → hull model → resistance curves. Stages:
//   buildShipModel        hull form, sampled grid, particulars, water, form factor, corrections' inputs;
//   computeResistanceCurves  Michell (uncorrected), corrected Michell, exact Wigley, ITTC-57, Holtrop–Mennen;
//   buildShipResults      tables, plots, 3-D view and scalars.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "ship/boundary_layer.hpp"
#include "ship/holtrop_mennen.hpp"
#include "ship/michell_resistance.hpp"
#include "ship/ship_parameters.hpp"
#include "ship/viscous_resistance.hpp"

namespace maris::ship {

struct ShipModel {
  HullForm hull;
  HullGrid grid;                 // the Michell grid (numerics.stations × numerics.waterlines)
  std::shared_ptr<const TangencyCorrection> tangency;  // boundary-layer correction (null when off)
  HullParticulars particulars;
  double wetted_surface = 0;     // [m²] S of the coefficients (override or computed)
  WaterProperties water;
  double form_factor = 1;        // [-] 1 + k used for C_T
  double wave_number_factor = 1; // [-] k̂0/k0 (1 when the correction is off)
  ForeShoulder fore_shoulder;
  HoltropHull holtrop_hull;
  HoltropEdition holtrop_edition = HoltropEdition::Revised1984;
  std::optional<ProhaskaFit> prohaska;  // set when the form factor comes from Prohaska's fit
  bool any_correction = false;
  std::vector<std::string> notes;  // warnings for the user
};

ShipModel buildShipModel(const ShipParameters& p, RunContext& context);

// k̂0/k0 = 1 + 3.7 (s_FS/l_FS − 1), the paper's eq 12 (3.7 as printed; sign '+': k̂0 > k0 delays the hump).
double waveNumberCorrectionFactor(const ForeShoulder& fore_shoulder);

struct ResistanceCurves {
  std::vector<double> froude, speed;          // [-], [m/s]
  std::vector<WaveResistance> michell;        // uncorrected Michell, grid path
  std::vector<WaveResistance> corrected;      // with the enabled corrections (empty when none)
  std::vector<WaveResistance> exact;          // closed-form Wigley Kochin function (empty for other hulls)
  std::vector<double> c_friction;             // [-] ITTC-57
  std::vector<HoltropResistance> holtrop;

  // The rows i with keep[i] (keep.size() == froude.size()), in the same order.
  ResistanceCurves rows(const std::vector<bool>& keep) const;
};

// Sees the rows finished so far (whole rows, in Froude-number order) while the sweep runs.
using CurvesObserver = std::function<void(const ResistanceCurves& rows_so_far)>;

// Kochin function of the corrected hull (tangency-corrected when enabled, else the plain grid).
std::unique_ptr<KochinFunction> correctedKochin(const ShipModel& m);

// Michell settings of the corrected computation (wave-number factor, cutoff) or of the plain one.
MichellSettings michellSettings(const ShipParameters& p, const ShipModel& m, bool corrected);

// The sweep over Froude numbers. `observe` (optional) is called from the calling thread with the rows finished
// so far whenever the context wants partial results; the curves returned do not depend on it.
ResistanceCurves computeResistanceCurves(const ShipParameters& p, const ShipModel& m, RunContext& context,
                                         const CurvesObserver& observe = {});

Results buildShipResults(const ShipParameters& p, const ShipModel& m, const ResistanceCurves& c, RunContext& context);

// Partial results while the sweep runs, for live plots: the resistance-curve table of the rows finished so far
// (its rows equal the finished run's bit for bit), the measured points, every plot of buildShipResults (the
// design-speed tables, wave spectrum and boundary layer, come only with the final results, so those plots stay
// empty until then), the particulars and the hull in the 3-D view (without the wave pattern). Construct once per
// run: it reads the measured file and samples the hull for display. Keeps references to `p` and `m`.
class PartialShipResults {
 public:
  PartialShipResults(const ShipParameters& p, const ShipModel& m);
  std::shared_ptr<const Results> build(const ResistanceCurves& rows_so_far) const;

 private:
  const ShipParameters& p_;
  const ShipModel& m_;
  MeasuredPoints measured_;
  Results fixed_;  // scalars and 3-D view, the same in every partial
};

}  // namespace maris::ship
