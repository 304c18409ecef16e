#include "ship/ship_parameters.hpp"

#include <cmath>
#include <filesystem>

#include "core/errors.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"
#include "core/table_reader.hpp"
#include "core/scenario.hpp"
#include "core/text_format.hpp"

namespace maris::ship {

namespace {

constexpr double kMinThickness = 1e-3;  // smallest beam/length and draft/length of a formula hull

// Built-in offsets tables (resources/data/ship, provenance in its README.md) and the Lpp they are written at.
struct BuiltinHull {
  const char* source;
  const char* resource;
  const char* name;
  double length_pp;  // [m]
};
constexpr BuiltinHull kBuiltinHulls[] = {
    {"series60", "data/ship/series60_cb060_offsets.csv", "Series 60 C_B 0.60 (Todd 1963)", 3.048},
    {"kcs", "data/ship/kcs_model_offsets.csv", "KCS (SIMMAN 2014 IGES)", 230.0 / 31.5994},
};

}  // namespace

SchemaBinder<ShipParameters> shipSchemaBinder() {
  using P = ShipParameters;
  SchemaBinder<P> b;
  b.choice("hull.source", &P::hull_source, {"wigley", "parametric", "series60", "kcs", "offsets_file"},
           "Hull: Wigley formula, parametric family, built-in Series 60 / KCS tables, or an offsets CSV");
  b.real("hull.length", &P::length, "m", Range::positive(1000), "Length between perpendiculars Lpp (tables are scaled to it)");
  b.real("hull.beam", &P::beam, "m", Range::positive(200), "Beam B of the wigley/parametric hull");
  b.real("hull.draft", &P::draft, "m", Range::positive(100), "Draft T of the wigley/parametric hull");
  b.real("hull.waterline_exponent", &P::waterline_exponent, "-", Range::closed(1, 20),
         "Parametric hull: waterline exponent p, Y ∝ 1 − |2ξ/L|^p");
  b.real("hull.section_exponent", &P::section_exponent, "-", Range::closed(1, 20),
         "Parametric hull: section exponent q, Y ∝ 1 − |z/T|^q");
  b.dataPath("hull.offsets_file", &P::offsets_file, "Offsets CSV (x_m,z_m,half_breadth_m) when hull.source = offsets_file");
  b.real("hull.offsets_length_pp", &P::offsets_length_pp, "m", Range::positive(1000),
         "Lpp of the offsets file as written (the table is scaled to hull.length)");
  b.real("hull.wetted_surface", &P::wetted_surface, "m^2", Range::nonNegative(1e6),
         "Wetted surface for the coefficients; 0 = computed from the geometry");
  b.real("speed.froude_min", &P::froude_min, "-", Range::closed(0.02, 3), "First Froude number of the sweep");
  b.real("speed.froude_max", &P::froude_max, "-", Range::closed(0.02, 3), "Last Froude number of the sweep");
  b.integer("speed.count", &P::froude_count, "-", Range::closed(2, 5000), "Number of speeds in the sweep");
  b.real("speed.design_froude", &P::design_froude, "-", Range::closed(0.02, 3),
         "Froude number of the scalar results, the wave spectrum and the wave pattern");
  b.choice("water.kind", &P::water, {"fresh", "sea"}, "Fresh water or sea water (salinity 35 g/kg)");
  b.real("water.temperature", &P::temperature, "degC", Range::closed(0, 40), "Water temperature");
  b.real("water.gravity", &P::gravity, "m/s^2", Range::closed(9.7, 9.9), "Gravitational acceleration");
  b.choice("viscous.form_factor_method", &P::form_factor_method, {"input", "holtrop", "prohaska"},
           "Form factor 1+k: the value below, Holtrop's regression from the particulars, or Prohaska's fit to "
           "the measured points");
  b.real("viscous.form_factor", &P::form_factor, "-", Range::closed(1, 2), "Form factor 1+k (R_V = (1+k) R_F)");
  b.real("viscous.correlation_allowance", &P::correlation_allowance, "-", Range::closed(-0.001, 0.002),
         "Correlation allowance C_A added to C_T");
  b.real("viscous.prohaska_froude_max", &P::prohaska_froude_max, "-", Range::closed(0.02, 0.5),
         "Measured points up to this Froude number enter Prohaska's fit C_T/C_F = (1+k) + c Fn^4/C_F");
  b.choice("holtrop.edition", &P::holtrop_edition, {"1984", "1982"},
           "Holtrop's 1984 re-analysis or the original Holtrop & Mennen (1982) formulas");
  b.choice("holtrop.stern_shape", &P::stern_shape, {"pram_gondola", "v_shaped", "normal", "u_shaped"},
           "Holtrop-Mennen afterbody form (C_stern = -25, -10, 0, 10)");
  b.boolean("holtrop.correlation_allowance", &P::holtrop_correlation_allowance,
            "Add Holtrop's correlation allowance R_A (meant for full-scale ships)");
  b.boolean("corrections.tangency", &P::tangency_correction,
            "Boundary-layer tangency correction of the hull slopes (paper eqs 9-11)");
  b.boolean("corrections.wave_number", &P::wave_number_correction,
            "Wave-number (phase) correction k0 -> k0 [1 + 3.7 (s_FS/l_FS - 1)] (paper eq 12)");
  b.boolean("corrections.corrected_prefactor", &P::corrected_prefactor,
            "Use the corrected wave number also in the k0^2 prefactor of the resistance integral");
  b.real("corrections.short_wave_cutoff", &P::short_wave_cutoff, "-", Range::closed(0, 1),
         "Discard waves shorter than this fraction of Lpp (paper section 3.3); 0 = keep all");
  b.real("corrections.trip_position", &P::trip_position, "-", Range::closed(0, 1),
         "Forced laminar-turbulent transition of the boundary layer, fraction of the waterline from the bow");
  b.real("corrections.fore_shoulder", &P::fore_shoulder, "-", Range::closed(0, 0.9),
         "Fore shoulder of the wave-number correction, fraction of Lpp aft of the FP; 0 = where the design "
         "waterline first reaches its maximum half-breadth");
  b.real("full_scale.ship_length", &P::ship_length, "m", Range::nonNegative(1000),
         "Lpp of the full-scale ship for the extrapolation at equal Fn (0 = model only)");
  b.real("full_scale.water_temperature", &P::ship_water_temperature, "degC", Range::closed(0, 40),
         "Sea water temperature of the full-scale ship");
  b.integer("numerics.stations", &P::stations, "-", Range::closed(9, 4001), "Grid stations along the hull (4m+1)");
  b.integer("numerics.waterlines", &P::waterlines, "-", Range::closed(5, 1001), "Grid waterlines (odd)");
  b.real("numerics.relative_tolerance", &P::relative_tolerance, "-", Range::closed(1e-10, 0.1),
         "Relative tolerance of the wave-angle quadrature and tail, per speed");
  b.integer("numerics.threads", &P::threads, "-", Range::closed(0, 256), "Threads for the speed sweep (0 = all cores)");
  b.dataPath("measured.file", &P::measured_file,
             "Optional CSV of measured points: columns froude, c_total; builtin:NAME for a data set shipped in "
             "resources/data/ship (e.g. builtin:kcs_tokyo2015_case21_efd.csv)");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"hull.length", "Length Lpp"},
      {"hull.beam", "Beam B"},
      {"hull.draft", "Draft T"},
      {"hull.waterline_exponent", "Waterline exponent p"},
      {"hull.section_exponent", "Section exponent q"},
      {"hull.wetted_surface", "Wetted surface S"},
      {"speed.froude_min", "First Froude number"},
      {"speed.froude_max", "Last Froude number"},
      {"speed.count", "Speeds"},
      {"speed.design_froude", "Design Froude number Fn"},
      {"water.temperature", "Water temperature"},
      {"viscous.form_factor", "Form factor 1+k"},
      {"viscous.correlation_allowance", "Correlation allowance C_A"},
      {"corrections.trip_position", "Trip position"},
      {"full_scale.ship_length", "Full-scale length Lpp"},
      {"numerics.stations", "Stations"},
      {"numerics.waterlines", "Waterlines"},
  });
  return b;
}

std::vector<FieldError> checkShipParameters(const ShipParameters& p) {
  std::vector<FieldError> e;
  auto num = [](double v) { return Json(v).dump(); };
  if (p.froude_min >= p.froude_max)
    e.push_back({"speed.froude_max", num(p.froude_max), "must be greater than speed.froude_min = " + num(p.froude_min)});
  if (p.stations % 4 != 1)
    e.push_back({"numerics.stations", num(p.stations),
                 "must be 4m+1 (e.g. 129, 257, 513): Filon-Simpson needs an odd count on the grid and its coarse half"});
  if (p.waterlines % 2 != 1) e.push_back({"numerics.waterlines", num(p.waterlines), "must be odd (e.g. 41, 51)"});
  if (p.hull_source == "offsets_file" && p.offsets_file.empty())
    e.push_back({"hull.offsets_file", "\"\"", "must name a CSV file when hull.source = offsets_file"});
  if (p.hull_source == "offsets_file" && !p.offsets_file.empty())
    if (auto problem = dataPathProblem(p.offsets_file, "ship"))
      e.push_back({"hull.offsets_file", Json(p.offsets_file).dump(), *problem});
  if (!p.measured_file.empty())
    if (auto problem = dataPathProblem(p.measured_file, "ship"))
      e.push_back({"measured.file", Json(p.measured_file).dump(), *problem});
  if (p.form_factor_method == "prohaska" && p.measured_file.empty())
    e.push_back({"viscous.form_factor_method", "\"prohaska\"",
                 "needs measured.file (the measured C_T points that Prohaska's fit uses)"});
  if ((p.hull_source == "wigley" || p.hull_source == "parametric") && p.draft > p.length)
    e.push_back({"hull.draft", num(p.draft), "must not exceed hull.length = " + num(p.length) + " m (a thin ship)"});
  // A hull thinner than L/1000 is degenerate: its wetted surface, block coefficient and the Holtrop–Mennen
  // regression lose meaning (and underflow for denormal sizes).
  if (p.hull_source == "wigley" || p.hull_source == "parametric") {
    if (p.beam < kMinThickness * p.length)
      e.push_back({"hull.beam", num(p.beam), "must be at least hull.length / 1000 = " + num(kMinThickness * p.length) +
                                                 " m (a thinner hull is degenerate)"});
    if (p.draft < kMinThickness * p.length)
      e.push_back({"hull.draft", num(p.draft), "must be at least hull.length / 1000 = " + num(kMinThickness * p.length) +
                                                   " m (a shallower hull is degenerate)"});
  }
  return e;
}

HullForm buildHullForm(const ShipParameters& p) {
  if (p.hull_source == "wigley") return makeParametricHull(p.length, p.beam, p.draft);
  if (p.hull_source == "parametric")
    return makeParametricHull(p.length, p.beam, p.draft, p.waterline_exponent, p.section_exponent);
  if (p.hull_source == "offsets_file") {
    const std::string text = readDataText(p.offsets_file, "ship", "parameters.hull.offsets_file");
    auto table = parseOffsetsCsv(text, "parameters.hull.offsets_file", p.offsets_file);
    // The table is scaled by hull.length / hull.offsets_length_pp: an Lpp far from the stations' span (e.g. the
    // default 1 m left for a 7.3 m model) would scale the hull into nonsense.
    const double span = table.stations.back().x - table.stations.front().x;
    if (!(span >= 0.5 * p.offsets_length_pp && span <= 2.0 * p.offsets_length_pp))
      throw InputError("parameters.hull.offsets_length_pp", Json(p.offsets_length_pp).dump(),
                       formatText("but the stations of %s span %.6g m: give the Lpp the table is drawn at (within a "
                                  "factor 2 of that span)", echoText(p.offsets_file).c_str(), span));
    return makeOffsetsHull(std::filesystem::path(p.offsets_file).filename().string(), std::move(table),
                           p.offsets_length_pp, p.length / p.offsets_length_pp);
  }
  for (const auto& b : kBuiltinHulls) {
    if (p.hull_source != b.source) continue;
    const auto text = builtinResource(b.resource);
    if (!text) throw InputError("parameters.hull.source", Json(p.hull_source).dump(), "built-in table is missing");
    return makeOffsetsHull(b.name, parseOffsetsCsv(*text, "parameters.hull.source", b.resource), b.length_pp, p.length / b.length_pp);
  }
  throw InputError("parameters.hull.source", Json(p.hull_source).dump(), "unknown hull source");
}

MeasuredPoints readMeasuredPoints(const std::string& path) {
  TableSpec spec{"parameters.measured.file", path, "columns froude and c_total (others ignored)"};
  spec.empty_cells = true;
  const TextTable csv = readTable(path, "ship", spec);
  const int froude = csv.column("froude"), ct = csv.column("c_total");
  if (froude < 0 || ct < 0) throw InputError({tableError(spec, 0, "expected a names row with columns froude and c_total")});
  MeasuredPoints m;
  std::vector<FieldError> errors;
  for (const auto& row : csv.rows) {
    for (int c : {froude, ct})
      if (!row.cells[c]) errors.push_back(tableError(spec, row.line, "expected a number, found an empty cell", &csv, c));
    if (!row.cells[froude] || !row.cells[ct]) continue;
    m.froude.push_back(*row.cells[froude]);
    m.c_total.push_back(*row.cells[ct]);
  }
  if (!errors.empty()) throw InputError(std::move(errors));
  return m;
}

}  // namespace maris::ship
