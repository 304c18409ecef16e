#include "ship/ship_plausibility.hpp"

#include <string>

#include "core/text_format.hpp"

namespace maris::ship {

namespace {

// Thin-ship (Michell) theory linearises in the beam: for L/B below about 8 it over-predicts the humps and
// hollows of C_W, which is what the corrections of Bašić, Blagojević & Andrun address (docs/ship.md, Known
// limits; the KCS, L/B = 7.1, is 17–128 % high uncorrected against the Tokyo 2015 tank data).
constexpr double kThinShipLengthBeam = 8.0;
// On offsets tables the default 257-station grid leaves C_W errors up to 0.2 % at Fn 0.06 with an estimate
// that only just covers them (measured on the Series 60 against 1025×201, docs/ship.md): below Fn 0.08 the
// grid needs at least 513 stations.
constexpr double kLowFroudeOnTables = 0.08;
constexpr int kStationsForLowFroude = 513;
constexpr int kCheckGridStations = 65, kCheckGridWaterlines = 13;  // enough for B_WL of a table to 1 %

std::string num(double v) { return formatText("%.4g", v); }

// Waterline beam B_WL: the input for the formula hulls, measured on a coarse sample of a table.
double waterlineBeam(const ShipParameters& p) {
  if (p.hull_source == "wigley" || p.hull_source == "parametric") return p.beam;
  const HullForm hull = buildHullForm(p);
  return computeParticulars(sampleHull(hull, kCheckGridStations, kCheckGridWaterlines), hull.length_pp).beam_wl;
}

}  // namespace

std::vector<FieldError> shipPlausibility(const ShipParameters& p) {
  std::vector<FieldError> w;
  const bool formula = p.hull_source == "wigley" || p.hull_source == "parametric";
  double beam = 0.0;
  try {
    beam = waterlineBeam(p);
  } catch (const InputError&) {
    beam = 0.0;  // an unreadable table is an error of the run, not a plausibility warning
  }
  if (beam > 0 && p.length / beam < kThinShipLengthBeam)
    w.push_back({formula ? "hull.beam" : "hull.source", formula ? num(p.beam) : "\"" + p.hull_source + "\"",
                 "L/B = " + num(p.length / beam) +
                     " is below 8: thin-ship (Michell) theory over-predicts the humps of C_W for hulls this "
                     "full; the paper's corrections (corrections.*) reduce the excess"});
  if (!formula && p.froude_min < kLowFroudeOnTables && p.stations < kStationsForLowFroude)
    w.push_back({"speed.froude_min", num(p.froude_min),
                 "below Fn 0.08 an offsets hull needs numerics.stations ≥ 513 (now " + std::to_string(p.stations) +
                     "): the grid error there is as large as its estimate"});
  return w;
}

}  // namespace maris::ship
