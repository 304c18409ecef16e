#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/checked_count.hpp"

#include "seismic/free_field_synthesis.hpp"
#include "seismic/seismic_inputs.hpp"
#include "seismic/seismic_solve.hpp"
#include "core/text_format.hpp"

namespace maris::seismic {

std::function<double(double)> incidentFunction(const SeismicParameters& p, double arrival) {
  const double a = p.input_amplitude;
  if (p.input_kind == "pulse") {
    const double length = p.pulse_duration;
    return [=](double t) { return a * bsplinePulse(t - arrival, length); };
  }
  if (p.input_kind == "ricker") {
    // Centred 1.5/f_p after the arrival: the wavelet is below 1e-9 of its peak before that.
    const double f = p.ricker_peak_frequency, centre = arrival + 1.5 / f;
    return [=](double t) { return a * rickerWavelet(t, f, centre); };
  }
  const double dt = 0.002;
  const auto rec = std::make_shared<Accelerogram>(
      loadAccelerogram(p.accelerogram_file, dt, p.accelerogram_peak_acceleration, "input.accelerogram_file"));
  return [rec, arrival, dt](double t) {
    const double s = (t - arrival) / dt;
    if (s <= 0.0) return 0.0;
    const auto& d = rec->displacement;
    const std::size_t k = static_cast<std::size_t>(s);
    if (k + 1 >= d.size()) return d.back();
    return d[k] + (s - k) * (d[k + 1] - d[k]);
  };
}

std::vector<double> incidentHistory(const SeismicParameters& p, double dt, int n, double arrival) {
  const auto u0 = incidentFunction(p, arrival);
  std::vector<double> u(n);
  for (int k = 0; k < n; ++k) u[k] = u0(k * dt);
  return u;
}

double arrivalAtOrigin(const SeismicParameters& p, const FreeField& field) {
  const ModelExtent box = modelExtent(p);
  // Beyond the SV critical angle the free field has a precursor (see FreeFieldSynthesis): 1 s more
  // lead lets it decay before the FE model starts from rest at t = 0.
  const double precursor_lead = field.reflectedPEvanescent() ? 1.0 : 0.0;
  return 0.05 + precursor_lead + std::abs(field.horizontalSlowness()) * box.half_width +
         field.incidentVerticalSlowness() * box.seabed_depth;
}

void addFreeFieldResults(const SeismicParameters& p, const FreeField& field, Results& results, RunContext& ctx) {
  ctx.progress(0.0, "free field");
  const double h = field.water().depth;
  const double deg = 180.0 / std::numbers::pi;
  if (field.type() == WaveType::SV) {
    results.addScalar("sv_critical_angle", FreeField::criticalAngleSv(field.solid()) * deg, "deg",
                      "SV incidence limit asin(vs/vp) of the seabed", "SV critical angle");
    results.addScalar("reflected_p_evanescent", field.reflectedPEvanescent() ? 1.0 : 0.0, "-",
                      "1 when SV is beyond the critical angle: the reflected P is evanescent (complex Snell's law)", "Reflected P evanescent (1 = yes)");
    if (field.reflectedPEvanescent())
      ctx.warn("SV at " + std::to_string(field.angle() * deg) + " deg is beyond the critical angle " +
               numberText(FreeField::criticalAngleSv(field.solid()) * deg) +
               " deg: the reflected P is evanescent and the free field contains the input's Hilbert transform, "
               "whose precursor reaches before the arrival (the paper stops at the critical angle)");
  }
  if (h > 0.0) {
    const double sin_f = field.horizontalSlowness() * field.water().sound_speed;
    results.addScalar("water_resonance_frequency", field.water().sound_speed / (4.0 * h * std::sqrt(1.0 - sin_f * sin_f)),
                      "Hz", "First water-column resonance c_f/(4h cos θ_f): the seabed's vertical motion vanishes", "Water-layer resonance f");
  }

  // Transfer functions per unit incident displacement, 0–2 f_cut.
  Table transfer{"free_field_transfer", "Free-field amplitude per unit incident displacement", {}};
  std::vector<double> f_col, bx, by, ay;  // added to the table at the end (Table::add may reallocate)
  double worst_energy = 0.0;
  const int count = 400;
  for (int i = 1; i <= count; ++i) {
    const double f = 2.0 * p.cutoff_frequency * i / count;
    const Complex w(2.0 * std::numbers::pi * f, 0.0);
    const auto a = field.solve(w);
    const auto b = field.solidAt(a, w, 0.0, 0.0);
    f_col.push_back(f);
    bx.push_back(std::abs(b.ux));
    by.push_back(std::abs(b.uy));
    ay.push_back(h > 0.0 ? std::abs(field.waterAt(a, w, 0.0, h).uy) : std::abs(b.uy));
    worst_energy = std::max(worst_energy, std::abs(field.energyResidual(a)));
  }
  transfer.add("frequency", "Hz", f_col, "Frequency f");
  transfer.add("seabed_ux", "m/m", bx, "Seabed u_x");
  transfer.add("seabed_uy", "m/m", by, "Seabed u_y");
  transfer.add("surface_uy", "m/m", ay, "Surface u_y");
  results.addScalar("free_field_energy_residual", worst_energy, "-",
                    "Largest |reflected/incident energy flux − 1| over the transfer-function frequencies", "Free-field energy residual");
  results.tables.push_back(std::move(transfer));
  results.plots.push_back({"free_field_transfer", "Free-field transfer functions (B seabed, A water surface)",
                           "free_field_transfer", "frequency", {"seabed_ux", "seabed_uy", "surface_uy"}, false, false,
                           "", {}});

  // Histories at B (0, 0) and A (0, h) by Fourier synthesis.
  const double dt = std::min(0.002, 1.0 / (40.0 * p.cutoff_frequency));
  const int n = static_cast<int>(
      checkedCount(p.duration / dt, kMaxStoredSamples, "parameters.solver.cutoff_frequency", "free-field samples")) + 1;
  const auto u0 = incidentHistory(p, dt, n, arrivalAtOrigin(p, field));
  const FreeFieldSynthesis synthesis(field, u0, 0.0, dt);
  const auto seabed = synthesis.solid(0.0);
  Table hist{"free_field_histories", "Free-field displacement histories", {}};
  auto& t = hist.add("time", "s", {}, "Time").values;
  for (int k = 0; k < n; ++k) t.push_back(k * dt);
  hist.add("incident", "m", u0, "Incident u₀");
  hist.add("seabed_ux", "m", seabed.ux, "Seabed u_x");
  hist.add("seabed_uy", "m", seabed.uy, "Seabed u_y");
  std::vector<std::string> ys{"incident", "seabed_ux", "seabed_uy"};
  auto peak = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
  };
  results.addScalar("free_field_seabed_peak_ux", peak(seabed.ux), "m", "Peak |u_x| of the free field at the seabed (B)", "Free-field peak u_x at B");
  results.addScalar("free_field_seabed_peak_uy", peak(seabed.uy), "m", "Peak |u_y| of the free field at the seabed (B)", "Free-field peak u_y at B");
  if (field.reflectedPEvanescent()) {
    // The FE model starts from rest: what the precursor leaves at t = 0 is an initial-state error.
    const double start = std::max(std::abs(seabed.ux.front()), std::abs(seabed.uy.front()));
    const double offset = start / std::max({peak(seabed.ux), peak(seabed.uy), 1e-300});
    results.addScalar("free_field_precursor_at_start", offset, "-",
                      "Free-field displacement at B at t = 0 over its peak (evanescent case; the FE starts at rest)", "Free-field precursor at start");
    if (offset > 0.01)
      ctx.warn("the free-field precursor at t = 0 is " + numberText(100.0 * offset) +
               " % of the peak at the seabed: use a zero-mean input (Ricker) or a later arrival");
  }
  if (h > 0.0) {
    const auto surface = synthesis.water(h);
    hist.add("surface_uy", "m", surface.uy, "Surface u_y");
    ys.push_back("surface_uy");
    results.addScalar("free_field_surface_peak_uy", peak(surface.uy), "m",
                      "Peak |u_y| of the free field at the water surface (A)", "Free-field peak u_y at A");
  }
  results.tables.push_back(std::move(hist));
  results.plots.push_back(
      {"free_field_histories", "Free-field displacement at B and A", "free_field_histories", "time", ys, false, false, "", {}});
  ctx.progress(0.05, "free field");
}

}  // namespace maris::seismic
