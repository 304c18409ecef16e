// Turns the wec computations into Results: tables, plot specifications and the animated 3D view.
// Column names carry the float number (1-based): "rao_1", "hinge_fz_2".
#pragma once

#include <vector>

#include "core/results.hpp"
#include "wec/wec_frequency.hpp"
#include "wec/wec_response.hpp"
#include "wec/wec_time.hpp"

namespace maris::wec {

// Frequency sweep: |Θ|/a [rad/m], phase [deg], |F_h,x|, |F_h,z| [N/m], |M_y| [N·m/m], mean power per a²,
// capture width and its bound, optimal PTO damping; per float.
Table frequencyTable(const std::vector<double>& omega, const std::vector<std::vector<FrequencyResponse>>& response);
// Time-domain RAO points with the same column names as frequencyTable (drawn as reference markers).
Table timeDomainRaoTable(const std::vector<SteadyResponse>& points, std::size_t float_count);
// Time histories; `suffix` distinguishes formulations ("" classical, "_aug" augmented).
void appendHistory(Table& table, const TimeDomainResult& td, const std::vector<double>& theta0, const std::string& suffix,
                   bool with_time);
// The "time_history" table of the first `rows` recorded instants of `main` and, if given, of the augmented run
// (columns with suffix "_aug"); rows ≤ the length of each run. A partial table's rows equal the final one's.
Table historyTable(const TimeDomainResult& main, const TimeDomainResult* augmented, const std::vector<double>& theta0,
                   std::size_t rows);
// Kernels and their modal fits for float 1.
Table kernelTable(const FloatModel& f);
// A(ω), B(ω), |X(ω)| of float 1 on the sweep.
Table hydroTable(const WecModel& model, const std::vector<double>& omega);

std::vector<PlotSpec> wecPlots(std::size_t float_count, bool have_td_points, bool have_augmented);
// Column of the power matrix for significant height hs [m]: "power_hs_1p5m".
std::string powerMatrixColumn(double hs);
// Power matrix against peak period, one curve per significant height.
PlotSpec powerMatrixPlot(const std::vector<double>& hs, const std::string& spectrum);
// Hinge reaction spectra of every float (table "response_spectra").
PlotSpec responseSpectraPlot(std::size_t float_count);

// Jacket legs (boxes), hinges (spheres), arms (tubes), hemispheres moving with θ(t), wave surface.
View3D wecView(const WecModel& model, const IncidentWaves& waves, const TimeDomainResult& td, int frames);

}  // namespace maris::wec
