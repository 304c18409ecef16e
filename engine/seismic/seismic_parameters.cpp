#include "seismic/seismic_parameters.hpp"

#include <cmath>
#include <numbers>

#include "core/text_format.hpp"

namespace maris::seismic {

namespace {

SchemaBinder<ReefLayer> layerBinder() {
  SchemaBinder<ReefLayer> b;
  b.real("thickness", &ReefLayer::thickness, "m", Range::positive(5000.0), "Vertical thickness of the layer");
  b.real("slope_deg", &ReefLayer::slope_deg, "deg", Range::closed(5.0, 90.0), "Flank slope from the horizontal");
  b.real("density", &ReefLayer::density, "kg/m^3", Range::closed(500.0, 5000.0), "Rock density");
  b.real("vs", &ReefLayer::vs, "m/s", Range::closed(50.0, 6000.0), "S-wave speed");
  b.real("vp", &ReefLayer::vp, "m/s", Range::closed(100.0, 12000.0), "P-wave speed");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"thickness", "Thickness"},
      {"slope_deg", "Flank slope"},
      {"density", "Rock density"},
      {"vs", "S-wave speed v_s"},
      {"vp", "P-wave speed v_p"},
  });
  return b;
}

}  // namespace

SchemaBinder<SeismicParameters> seismicBinder() {
  using P = SeismicParameters;
  SchemaBinder<P> b;
  b.choice("model.kind", &P::model, {"reef", "box"}, "Layered reef on the seabed, or the flat verification box");
  b.boolean("model.include_water", &P::include_water, "Water layer present (false: sloping platform)");
  b.boolean("model.compare_without_water", &P::compare_without_water,
            "Also run without water and report the seawater deviation");
  b.choice("incidence.wave_type", &P::wave_type, {"P", "SV"}, "Incident plane wave type");
  b.real("incidence.angle_deg", &P::angle_deg, "deg", Range::open(-89.0, 89.0),
         "Incidence angle from the vertical; > 0 travels towards +x");
  b.realList("incidence.sweep_angles_deg", &P::sweep_angles_deg, "deg", Range::open(-89.0, 89.0), 0, 16,
             "Extra angles for the amplification sweep (one thread each)");
  b.choice("input.kind", &P::input_kind, {"pulse", "ricker", "accelerogram"},
           "Incident time function: B-spline pulse, Ricker wavelet or recorded accelerogram");
  b.real("input.pulse_duration", &P::pulse_duration, "s", Range::closed(0.01, 10.0), "B-spline pulse length");
  b.real("input.ricker_peak_frequency", &P::ricker_peak_frequency, "Hz", Range::closed(0.05, 50.0),
         "Ricker peak frequency");
  b.real("input.amplitude", &P::input_amplitude, "m", Range::positive(10.0),
         "Peak incident displacement (pulse, Ricker)");
  b.dataPath("input.accelerogram_file", &P::accelerogram_file, "CSV or whitespace-separated file: time [s], acceleration [m/s^2]; or a PEER .AT2 record (in g, converted with g = 9.80665 m/s^2); builtin:synthetic_kanai_tajimi.csv for the shipped synthetic record");
  b.real("input.accelerogram_peak_acceleration", &P::accelerogram_peak_acceleration, "m/s^2", Range::positive(50.0),
         "Peak acceleration the record is scaled to");
  b.real("seabed.density", &P::seabed_density, "kg/m^3", Range::closed(500.0, 5000.0), "Seabed density");
  b.real("seabed.vs", &P::seabed_vs, "m/s", Range::closed(50.0, 6000.0), "Seabed S-wave speed");
  b.real("seabed.vp", &P::seabed_vp, "m/s", Range::closed(100.0, 12000.0), "Seabed P-wave speed");
  b.real("water.density", &P::water_density, "kg/m^3", Range::closed(500.0, 2000.0), "Seawater density");
  b.real("water.sound_speed", &P::water_sound_speed, "m/s", Range::closed(500.0, 3000.0), "Sound speed in water");
  b.real("water.depth", &P::water_depth, "m", Range::positive(5000.0), "Water depth at the lateral boundaries");
  b.real("geometry.flat_width", &P::flat_width, "m", Range::closed(10.0, 20000.0), "Reef-flat width L");
  b.real("geometry.lateral_water_width", &P::lateral_water_width, "m", Range::closed(10.0, 20000.0),
         "Water between reef toe and lateral boundary (box: half-width)");
  b.real("geometry.seabed_thickness", &P::seabed_thickness, "m", Range::closed(10.0, 20000.0),
         "Seabed depth modelled below the seabed surface");
  b.table("geometry.layers", &P::layers, layerBinder(), 1, 6, "Reef-rock layers from the top down");
  b.real("solver.cutoff_frequency", &P::cutoff_frequency, "Hz", Range::closed(0.2, 40.0),
         "f_cut: element size <= min speed / (10 f_cut)");
  b.real("solver.duration", &P::duration, "s", Range::closed(0.1, 200.0), "Simulated time");
  b.real("solver.courant_fraction", &P::courant_fraction, "-", Range::open(0.0, 1.0),
         "Time step as a fraction of the stable step");
  b.integer("output.snapshot_count", &P::snapshot_count, "-", Range::closed(0, 200), "Wave-field frames");
  b.integer("output.station_count", &P::station_count, "-", Range::closed(3, 401), "Stations along the reef flat");
  b.integer("modes.count", &P::mode_count, "-", Range::closed(0, 60),
            "Lowest natural modes of the reef and seabed, with the water coupled when it is present; 0 skips");
  b.choice("modes.base", &P::modal_base, {"fixed", "springs"},
           "Modal boundary: clamped bottom, or the artificial boundary's springs only");
  // Labels for people: study plots, legends and tables name the parameters by them.
  b.labels({
      {"geometry.layers", "reef layer"},
      {"incidence.angle_deg", "Incidence angle"},
      {"input.ricker_peak_frequency", "Ricker peak frequency"},
      {"input.amplitude", "Incident amplitude"},
      {"seabed.density", "Seabed density"},
      {"seabed.vs", "Seabed S-wave speed"},
      {"seabed.vp", "Seabed P-wave speed"},
      {"water.density", "Seawater density"},
      {"water.sound_speed", "Sound speed in water"},
      {"water.depth", "Water depth"},
      {"geometry.flat_width", "Reef-flat width L"},
      {"solver.cutoff_frequency", "Cutoff frequency f_cut"},
  });
  return b;
}

ElasticMaterial seabedMaterial(const SeismicParameters& p) { return {p.seabed_density, p.seabed_vp, p.seabed_vs}; }

WaterLayer waterLayer(const SeismicParameters& p) {
  return {p.water_density, p.water_sound_speed, p.include_water ? p.water_depth : 0.0};
}

WaveType waveType(const SeismicParameters& p) { return p.wave_type == "SV" ? WaveType::SV : WaveType::P; }

ModelExtent modelExtent(const SeismicParameters& p) {
  ModelExtent e;
  e.seabed_depth = p.seabed_thickness;
  if (p.model == "reef") {
    e.reef_half_base = 0.5 * p.flat_width;
    for (const auto& l : p.layers) {
      e.reef_height += l.thickness;
      e.reef_half_base += l.thickness / std::tan(l.slope_deg * std::numbers::pi / 180.0);
    }
    e.half_width = e.reef_half_base + p.lateral_water_width;
  } else {
    e.half_width = p.lateral_water_width;
  }
  e.top = std::max(p.include_water ? p.water_depth : 0.0, e.reef_height);
  return e;
}

double slowestSpeed(const SeismicParameters& p) {
  double v = p.seabed_vs;
  if (p.model == "reef")
    for (const auto& l : p.layers) v = std::min(v, l.vs);
  if (p.include_water) v = std::min(v, p.water_sound_speed);
  return v;
}

std::vector<FieldError> checkSeismicParameters(const SeismicParameters& p) {
  std::vector<FieldError> errors;
  const double root2 = std::sqrt(2.0);
  // Poisson ratio in [0, 0.5): vp ≥ √2·vs.
  if (p.seabed_vp < root2 * p.seabed_vs)
    errors.push_back({"seabed.vp", numberText(p.seabed_vp),
                      "must be at least sqrt(2)·seabed.vs = " + numberText(root2 * p.seabed_vs) + " m/s (Poisson ratio >= 0)"});
  for (std::size_t i = 0; i < p.layers.size(); ++i)
    if (p.layers[i].vp < root2 * p.layers[i].vs)
      errors.push_back({"geometry.layers[" + std::to_string(i) + "].vp", numberText(p.layers[i].vp),
                        "must be at least sqrt(2)·vs = " + numberText(root2 * p.layers[i].vs) + " m/s (Poisson ratio >= 0)"});
  if (p.input_kind == "accelerogram" && p.accelerogram_file.empty())
    errors.push_back({"input.accelerogram_file", "\"\"", "must name a CSV or PEER .AT2 file when input.kind is \"accelerogram\""});
  // Mesh size guard: Δ = v_min/(10 f_cut) over the model box.
  const ModelExtent box = modelExtent(p);
  const double delta = slowestSpeed(p) / (10.0 * p.cutoff_frequency);
  const double elements =
      std::ceil(2.0 * box.half_width / delta) * std::ceil((box.top + box.seabed_depth) / delta);
  if (elements > 6.0e5)
    errors.push_back({"solver.cutoff_frequency", numberText(p.cutoff_frequency),
                      "gives about " + numberText(elements) + " elements of " + numberText(delta) +
                          " m (limit 600000): lower the cut-off frequency or the model size"});
  return errors;
}

}  // namespace maris::seismic
