#include "ship/ship_study.hpp"

#include <cmath>
#include <memory>

#include "core/errors.hpp"
#include "core/scenario.hpp"

#include "ship/resistance_sweep.hpp"

namespace maris::ship {

namespace {

double sternShapeCoefficient(const std::string& s) {
  if (s == "pram_gondola") return -25.0;
  if (s == "v_shaped") return -10.0;
  if (s == "u_shaped") return 10.0;
  return 0.0;
}

// Prohaska's 1 + k from the measured points with Fn ≤ viscous.prohaska_froude_max (C_F at the model's
// Reynolds number on L_WL, as for the computed curves). Throws InputError when too few points qualify.
ProhaskaFit fitProhaska(const ShipParameters& p, const ShipModel& m) {
  const MeasuredPoints mp = readMeasuredPoints(p.measured_file);
  std::vector<double> fn, ct, cf;
  for (std::size_t i = 0; i < mp.froude.size(); ++i) {
    if (mp.froude[i] <= 0 || mp.froude[i] > p.prohaska_froude_max) continue;
    const double U = mp.froude[i] * std::sqrt(p.gravity * m.hull.length_pp);
    fn.push_back(mp.froude[i]);
    ct.push_back(mp.c_total[i]);
    cf.push_back(ittc57FrictionCoefficient(U * m.particulars.length_wl / m.water.kinematic_viscosity));
  }
  bool distinct = false;
  for (double f : fn) distinct = distinct || f != fn.front();
  if (!distinct)
    throw InputError("parameters.measured.file", Json(p.measured_file).dump(),
                     "Prohaska's fit needs measured points at two or more Froude numbers in (0, " +
                         Json(p.prohaska_froude_max).dump() + "] (viscous.prohaska_froude_max); found " +
                         std::to_string(fn.size()));
  return prohaskaFormFactor(fn, ct, cf);
}

}  // namespace

double waveNumberCorrectionFactor(const ForeShoulder& fs) {
  return fs.distance > 0 ? 1.0 + 3.7 * (fs.arc_length / fs.distance - 1.0) : 1.0;
}

ShipModel buildShipModel(const ShipParameters& p, RunContext& context) {
  ShipModel m;
  context.progress(0.0, "hull geometry");
  m.hull = buildHullForm(p);
  if (m.hull.kind == HullForm::Kind::Offsets && m.hull.offsets.ignored_rows_above_waterline > 0)
    m.notes.push_back("offsets: " + std::to_string(m.hull.offsets.ignored_rows_above_waterline) +
                      " rows above the waterline (z > 0) were ignored");
  m.grid = sampleHull(m.hull, p.stations, p.waterlines);
  m.particulars = computeParticulars(m.grid, m.hull.length_pp);
  m.wetted_surface = p.wetted_surface > 0 ? p.wetted_surface : m.particulars.wetted_surface;
  m.water = waterProperties(p.water == "sea" ? WaterKind::Sea : WaterKind::Fresh, p.temperature);

  // Holtrop–Mennen inputs from the computed particulars (even keel, L = L_WL).
  const HullParticulars& q = m.particulars;
  HoltropHull& h = m.holtrop_hull;
  h.length_wl = q.length_wl;
  h.beam = q.beam_wl;
  h.draft = q.draft;
  h.volume = q.volume;
  h.lcb_percent = q.lcb_percent * q.length_pp / q.length_wl;
  h.midship_coefficient = q.midship_coefficient;
  h.waterplane_coefficient = q.waterplane_area / (q.length_wl * q.beam_wl);
  h.wetted_surface = m.wetted_surface;
  h.bulb_area = q.bulb_area;
  h.bulb_centre_height = q.bulb_centre_height;
  h.transom_area = q.transom_area;
  h.stern_shape = sternShapeCoefficient(p.stern_shape);
  for (auto& note : holtropRangeNotes(h)) m.notes.push_back(note);
  m.holtrop_edition = p.holtrop_edition == "1982" ? HoltropEdition::Original1982 : HoltropEdition::Revised1984;
  m.form_factor = p.form_factor;
  if (p.form_factor_method == "holtrop") m.form_factor = holtropFormFactor(h, m.holtrop_edition);
  if (p.form_factor_method == "prohaska") {
    m.prohaska = fitProhaska(p, m);
    m.form_factor = m.prohaska->form_factor;
  }

  // The paper's corrections.
  m.fore_shoulder = foreShoulder(m.grid, p.fore_shoulder * p.length);
  if (p.wave_number_correction) m.wave_number_factor = waveNumberCorrectionFactor(m.fore_shoulder);
  if (p.tangency_correction) m.tangency = std::make_shared<const TangencyCorrection>(m.grid, p.trip_position);
  m.any_correction = p.tangency_correction || p.wave_number_correction || p.short_wave_cutoff > 0;
  return m;
}

std::unique_ptr<KochinFunction> correctedKochin(const ShipModel& m) {
  if (m.tangency) return std::make_unique<TangencyKochin>(m.tangency, m.water.kinematic_viscosity);
  return std::make_unique<GridKochin>(m.grid);
}

MichellSettings michellSettings(const ShipParameters& p, const ShipModel& m, bool corrected) {
  MichellSettings s;
  s.relative_tolerance = p.relative_tolerance;
  if (!corrected) return s;
  s.wave_number_factor = m.wave_number_factor;
  s.prefactor_uses_corrected_wave_number = p.corrected_prefactor;
  s.short_wave_cutoff = p.short_wave_cutoff;
  s.cutoff_length = m.hull.length_pp;
  return s;
}

ResistanceCurves ResistanceCurves::rows(const std::vector<bool>& keep) const {
  ResistanceCurves r;
  auto copy = [&](const auto& from, auto& to) {
    if (from.empty()) return;
    for (std::size_t i = 0; i < keep.size(); ++i)
      if (keep[i]) to.push_back(from[i]);
  };
  copy(froude, r.froude);
  copy(speed, r.speed);
  copy(michell, r.michell);
  copy(corrected, r.corrected);
  copy(exact, r.exact);
  copy(c_friction, r.c_friction);
  copy(holtrop, r.holtrop);
  return r;
}

ResistanceCurves computeResistanceCurves(const ShipParameters& p, const ShipModel& m, RunContext& context,
                                         const CurvesObserver& observe) {
  ResistanceCurves c;
  const int n = p.froude_count;
  const double L = m.hull.length_pp, g = p.gravity, rho = m.water.density;
  for (int i = 0; i < n; ++i) {
    const double fn = p.froude_min + (p.froude_max - p.froude_min) * i / (n - 1);
    c.froude.push_back(fn);
    c.speed.push_back(fn * std::sqrt(g * L));
  }
  // Friction (Re on the waterline length) and the Holtrop–Mennen comparison: cheap, so before the sweep,
  // which lets partial results carry whole rows.
  for (double U : c.speed) {
    c.c_friction.push_back(ittc57FrictionCoefficient(U * m.particulars.length_wl / m.water.kinematic_viscosity));
    c.holtrop.push_back(holtropMennen(m.holtrop_hull, U, rho, m.water.kinematic_viscosity, g,
                                      p.holtrop_correlation_allowance, m.holtrop_edition));
  }
  // Michell, uncorrected and corrected (grid path), and the closed form for the Wigley hull: one task per
  // speed computes all of them, so rows finish whole.
  const HullGrid& grid = m.grid;
  std::vector<WaveResistanceCurve> curves{
      {[&] { return std::make_unique<GridKochin>(grid); }, michellSettings(p, m, false)}};
  if (m.any_correction) curves.push_back({[&] { return correctedKochin(m); }, michellSettings(p, m, true)});
  if (m.hull.isWigley()) {
    const HullForm& h = m.hull;
    curves.push_back({[&] { return std::make_unique<WigleyKochin>(h.length_pp, h.beam, h.draft); },
                      michellSettings(p, m, false)});
  }
  // Which curve is which in the sweep's output.
  auto assign = [&](ResistanceCurves& to, std::vector<std::vector<WaveResistance>>&& values) {
    std::size_t k = 0;
    to.michell = std::move(values[k++]);
    if (m.any_correction) to.corrected = std::move(values[k++]);
    if (m.hull.isWigley()) to.exact = std::move(values[k++]);
  };
  SweepObserver show;
  if (observe)
    show = [&](const std::vector<std::vector<WaveResistance>>& values, const std::vector<bool>& finished) {
      ResistanceCurves so_far = c;
      assign(so_far, std::vector<std::vector<WaveResistance>>(values));
      observe(so_far.rows(finished));
    };
  assign(c, waveResistanceSweep(curves, c.speed, g, rho, p.threads, &context, "Michell wave resistance", show));
  return c;
}

}  // namespace maris::ship
