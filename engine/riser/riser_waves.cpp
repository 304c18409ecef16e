// Waves on the riser (contract in riser/riser_waves.hpp).
#include "riser/riser_waves.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/ocean_kinematics_batch.hpp"
#include "riser/riser_loads.hpp"
#include "riser/riser_model.hpp"
#include "core/text_format.hpp"

namespace maris::riser {
namespace {

using P = RiserParameters;
using std::numbers::pi;
constexpr double kDegree = pi / 180.0;
// The batch's truncation ε (core/ocean_kinematics_batch.hpp): components whose exponential decay makes them
// negligible at a Gauss point are left out of its depth sums; the wave velocity and acceleration change by at most
// 1e-7 of the sea's Σ a ω and Σ a ω² (the largest values the sums can take, at the surface), far below the
// integrator's step error of 1e-3 of the motion. In the speed case (200 components, 100 m deep) it takes the
// batch from 0.183 to 0.150 ms per evaluation at the 303 Gauss points (bench_riser_long_sea kinematics).
constexpr double kWaveTruncation = 1e-7;

SchemaBinder<WaveSpectrumRow> spectrumRowBinder() {
  SchemaBinder<WaveSpectrumRow> b;
  b.real("omega", &WaveSpectrumRow::omega, "rad/s", Range::nonNegative(100.0), "Angular frequency ω");
  b.real("density", &WaveSpectrumRow::density, "m^2*s/rad", Range::nonNegative(1e6), "One-sided spectral density S(ω)");
  return b;
}

ocean::WaveSpectrum spectrumOf(const RiserParameters& p) {
  if (p.wave_type == "jonswap")
    return ocean::jonswap(p.wave_significant_height, p.wave_peak_period, p.wave_peak_enhancement);
  if (p.wave_type == "pierson_moskowitz") return ocean::piersonMoskowitz(p.wave_significant_height, p.wave_peak_period);
  std::vector<double> omega, density;
  for (const auto& r : p.wave_spectrum_table) {
    omega.push_back(r.omega);
    density.push_back(r.density);
  }
  return ocean::spectrumTable(std::move(omega), std::move(density));
}

}  // namespace

void bindWaveParameters(SchemaBinder<RiserParameters>& b) {
  b.choice("waves.type", &P::wave_type, {"none", "airy", "jonswap", "pierson_moskowitz", "spectrum_table"},
           "Waves: none, a regular Airy wave, an irregular sea from a JONSWAP, Pierson–Moskowitz or tabulated "
           "spectrum (linear kinematics over depth water_level − seabed_level)");
  b.real("waves.height", &P::wave_height, "m", Range::positive(100.0), "Airy wave height H (crest to trough)");
  b.real("waves.period", &P::wave_period, "s", Range::positive(100.0), "Airy wave period T");
  b.real("waves.phase_deg", &P::wave_phase_deg, "deg", Range::closed(-360, 360),
         "Airy wave phase (crest at x = y = 0, t = 0 for 0)");
  b.real("waves.significant_height", &P::wave_significant_height, "m", Range::positive(50.0),
         "Significant wave height Hs = 4√m0 (jonswap, pierson_moskowitz)");
  b.real("waves.peak_period", &P::wave_peak_period, "s", Range::positive(100.0), "Spectral peak period Tp");
  b.real("waves.peak_enhancement", &P::wave_peak_enhancement, "-", Range::closed(1.0, 20.0),
         "JONSWAP peak enhancement γ (σ = 0.07 below the peak, 0.09 above)");
  b.table("waves.spectrum_table", &P::wave_spectrum_table, spectrumRowBinder(), 0, 10000,
          "User spectrum S(ω) (spectrum_table): rows of increasing ω, linear in between, zero outside");
  b.integer("waves.component_count", &P::wave_component_count, "-", Range::closed(1, 5000),
            "Components of an irregular sea");
  b.choice("waves.discretisation", &P::wave_discretisation, {"random_frequency", "equal_energy"},
           "Irregular sea frequencies: random within equal-width bins, or at the centroids of equal-energy bins "
           "(neither repeats with a common period)");
  b.integer("waves.seed", &P::wave_seed, "-", Range::closed(0, 2147483647),
            "Seed of the phases (mt19937_64; the same seed gives the bitwise same sea)");
  b.real("waves.direction_deg", &P::wave_direction_deg, "deg", Range::closed(-360, 360),
         "Direction the waves travel towards, from +x towards +y");
  b.choice("waves.stretching", &P::wave_stretching, {"wheeler", "vertical"},
           "Kinematics up to the instantaneous surface: Wheeler stretching or vertical extrapolation of the z = 0 "
           "values");
  b.real("waves.ramp_time", &P::wave_ramp_time, "s", Range::positive(1e5),
         "Smooth start of the waves, r = τ³(10 − 15τ + 6τ²) (statics is solved in calm water)");
  b.real("waves.elevation_x", &P::wave_elevation_x, "m", Range::any(), "x of the recorded wave elevation");
  b.real("waves.elevation_y", &P::wave_elevation_y, "m", Range::any(), "y of the recorded wave elevation");
}

void checkWaveParameters(const RiserParameters& p, std::vector<FieldError>& e) {
  if (p.wave_type == "none") return;
  if (!(p.water_level > p.seabed_level))
    e.push_back({"environment.seabed_level", numberText(p.seabed_level),
                 "waves need the sea bed below environment.water_level = " + numberText(p.water_level) + " (the depth)"});
  if (p.wave_type != "spectrum_table") return;
  if (p.wave_spectrum_table.size() < 2)
    e.push_back({"waves.spectrum_table", std::to_string(p.wave_spectrum_table.size()) + " rows",
                 "waves.type = spectrum_table needs at least 2 rows"});
  bool any = false;
  for (std::size_t k = 0; k < p.wave_spectrum_table.size(); ++k) {
    any = any || p.wave_spectrum_table[k].density > 0.0;
    if (k > 0 && !(p.wave_spectrum_table[k].omega > p.wave_spectrum_table[k - 1].omega))
      e.push_back({"waves.spectrum_table[" + std::to_string(k) + "].omega", numberText(p.wave_spectrum_table[k].omega),
                   "must be greater than the previous row's omega " + numberText(p.wave_spectrum_table[k - 1].omega)});
  }
  if (p.wave_spectrum_table.size() >= 2 && !any)
    e.push_back({"waves.spectrum_table", "all densities 0", "the spectrum has no energy"});
}

double RiserSea::ramp(double t) const {
  if (t >= ramp_time) return 1.0;
  if (t <= 0.0) return 0.0;
  const double tau = t / ramp_time;
  return tau * tau * tau * (10.0 - 15.0 * tau + 6.0 * tau * tau);
}

double RiserSea::rampRate(double t) const {
  if (t <= 0.0 || t >= ramp_time) return 0.0;
  const double tau = t / ramp_time;
  return 30.0 * tau * tau * (1.0 - tau) * (1.0 - tau) / ramp_time;
}

double RiserSea::rampAcceleration(double t) const {
  if (t <= 0.0 || t >= ramp_time) return 0.0;
  const double tau = t / ramp_time;
  return 60.0 * tau * (1.0 - tau) * (1.0 - 2.0 * tau) / (ramp_time * ramp_time);
}

double RiserSea::elevation(double x, double y, double t) const { return ramp(t) * field.elevation(x, y, t); }

ocean::FluidKinematics RiserSea::at(const Eigen::Vector3d& point, double t) const {
  const double r = ramp(t);
  if (r == 0.0) {  // calm water: wet below the still-water level, nothing moving
    ocean::FluidKinematics calm;
    calm.wet = point.z() <= water_level;
    return calm;
  }
  return field.kinematics(Eigen::Vector3d(point.x(), point.y(), point.z() - water_level), t, r, rampRate(t));
}

std::shared_ptr<const RiserSea> buildRiserSea(const RiserParameters& p) {
  if (p.wave_type == "none") return nullptr;
  auto sea = std::make_shared<RiserSea>();
  const double depth = p.water_level - p.seabed_level, direction = p.wave_direction_deg * kDegree;
  const auto stretching = p.wave_stretching == "vertical" ? ocean::Stretching::Vertical : ocean::Stretching::Wheeler;
  if (p.wave_type == "airy") {
    sea->field = ocean::airyWave(p.wave_height, p.wave_period, direction, p.wave_phase_deg * kDegree, depth, p.gravity,
                                 stretching);
  } else {
    const auto method = p.wave_discretisation == "equal_energy" ? ocean::Discretisation::EqualEnergy
                                                                : ocean::Discretisation::RandomFrequency;
    sea->field = ocean::irregularSea(spectrumOf(p), p.wave_component_count, method,
                                     static_cast<std::uint64_t>(p.wave_seed), direction, depth, p.gravity, stretching);
  }
  sea->water_level = p.water_level;
  sea->ramp_time = p.wave_ramp_time;
  sea->elevation_x = p.wave_elevation_x;
  sea->elevation_y = p.wave_elevation_y;
  sea->batch = std::make_shared<const ocean::WaveKinematicsBatch>(sea->field, direction, p.gravity, kWaveTruncation);
  return sea;
}

namespace {

// Per thread: the Gauss points, their kinematics and the batch's scratch (the time phases of the last time, valid
// for the batch `owner` only; the weak reference keeps the batch's memory block, so a later batch never gets its
// address while the scratch refers to it).
struct WaveLoadScratch {
  std::weak_ptr<const ocean::WaveKinematicsBatch> owner;
  std::vector<Eigen::Vector3d> points;
  std::vector<ocean::FluidKinematics> fluid;
  ocean::WaveKinematicsBatch::Scratch batch;
};

// The kinematics at the Gauss points of pose at its time: those held for the step (pose.step_waves, once its first
// evaluation has filled them), else evaluated (into the held ones, or into scratch.fluid without them; calm water
// before the ramp starts; point by point for a sea without a batch).
const std::vector<ocean::FluidKinematics>& waveKinematicsAtGaussPoints(const RiserModel& m, const RiserPose& pose,
                                                                       WaveLoadScratch& scratch) {
  const RiserSea& sea = *m.sea;
  const double t = pose.time, r = sea.ramp(t);
  const ocean::WaveKinematicsBatch* batch = sea.batch.get();
  StepWaveKinematics* held = r == 0.0 || batch == nullptr ? nullptr : pose.step_waves;
  if (held && held->filled) return held->fluid;
  const std::size_t count = 3 * static_cast<std::size_t>(m.n + 1);
  std::vector<ocean::FluidKinematics>& fluid = held ? held->fluid : scratch.fluid;
  scratch.points.resize(count);
  fluid.resize(count);
  for (int i = 0; i <= m.n; ++i) {
    const Vec3 tangent = pose.rotation[i].col(0);
    for (int q = 0; q < 3; ++q)
      scratch.points[3 * i + q] = pose.position[i] + kGaussX[q] * m.segments[i].length * tangent;
  }
  if (r == 0.0 || batch == nullptr) {
    for (std::size_t k = 0; k < count; ++k) fluid[k] = sea.at(scratch.points[k], t);
    return fluid;
  }
  if (scratch.owner.owner_before(sea.batch) || sea.batch.owner_before(scratch.owner))  // another sea's scratch
    scratch.batch = {}, scratch.owner = sea.batch;
  const Eigen::Vector3d level(0.0, 0.0, sea.water_level);
  for (auto& p : scratch.points) p -= level;  // the field's z = 0 is the still-water level
  batch->evaluate(scratch.points.data(), count, t, r, sea.rampRate(t), scratch.batch, fluid.data());
  if (held) held->filled = true;
  return fluid;
}

}  // namespace

void addMorisonInWaves(const RiserModel& m, const RiserPose& pose, double factor, SegmentLoads& loads) {
  thread_local WaveLoadScratch scratch;
  const std::vector<ocean::FluidKinematics>& kinematics = waveKinematicsAtGaussPoints(m, pose, scratch);
  for (int i = 0; i <= m.n; ++i) {
    const Segment& seg = m.segments[i];
    const Mat3& r = pose.rotation[i];
    const Vec3 t = r.col(0);
    for (int q = 0; q < 3; ++q) {
      const double xi = kGaussX[q] * seg.length, w = kGaussW[q] * seg.length;
      const Vec3 p = pose.position[i] + xi * t;
      const ocean::FluidKinematics& fluid = kinematics[3 * static_cast<std::size_t>(i) + q];
      if (!fluid.wet) continue;
      const Vec3 v = pose.velocity[i] + pose.omega[i].cross(xi * t);
      const Vec3 local = r.transpose() * (v - m.currentAt(p.z()) - fluid.velocity);
      // √(y² + z²), not std::hypot (a library call, 3 % of a run in a sea): relative velocities are far from
      // overflow and underflow, and the two differ by an ulp.
      const double vn = std::sqrt(local.y() * local.y() + local.z() * local.z());
      const Vec3 drag_local(-seg.tangential_drag * std::abs(local.x()) * local.x(), -seg.normal_drag * vn * local.y(),
                            -seg.normal_drag * vn * local.z());
      const Vec3 normal_acceleration = fluid.acceleration - fluid.acceleration.dot(t) * t;
      const Vec3 f = factor * w * (r * drag_local + seg.fluid_inertia_per_length * normal_acceleration);
      loads.force[i] += f;
      loads.moment[i] += (xi * t).cross(f);
      loads.power_drag += f.dot(v);
    }
  }
}

}  // namespace maris::riser
