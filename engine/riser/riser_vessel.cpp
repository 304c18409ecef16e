// Vessel motion at the riser top (contract and conventions in riser/riser_vessel.hpp).
#include "riser/riser_vessel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/angles.hpp"
#include "core/ocean_kinematics_batch.hpp"
#include "core/text_format.hpp"
#include "core/ocean_waves.hpp"
#include "core/resources.hpp"

namespace maris::riser {
namespace {

using P = RiserParameters;
using std::numbers::pi;
constexpr const char* kDofNames[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
constexpr const char* kExpectedColumns =
    "columns heading [deg], omega [rad/s] (or period [s]), and <dof>_amplitude, <dof>_phase [deg] for surge, sway, "
    "heave (m/m), roll, pitch, yaw (deg/m)";

// a + w (b − a) for amplitudes; for phases along the shorter arc.
double lerp(double a, double b, double w) { return a + w * (b - a); }
double lerpPhase(double a, double b, double w) { return a + w * std::remainder(b - a, 2 * pi); }

RaoValue blend(const RaoValue& a, const RaoValue& b, double w) {
  RaoValue out;
  for (int d = 0; d < 6; ++d) {
    out.amplitude[d] = lerp(a.amplitude[d], b.amplitude[d], w);
    out.phase_lag[d] = lerpPhase(a.phase_lag[d], b.phase_lag[d], w);
  }
  return out;
}

// The RAO of heading row h at omega (end rows held outside the frequencies).
RaoValue atHeading(const RaoTable& t, std::size_t h, double omega, bool* outside) {
  const std::size_t nf = t.omega.size(), base = h * nf;
  auto row = [&](std::size_t f) {
    RaoValue v;
    for (int d = 0; d < 6; ++d) {
      v.amplitude[d] = t.amplitude[d][base + f];
      v.phase_lag[d] = t.phase_lag[d][base + f];
    }
    return v;
  };
  if (omega <= t.omega.front() || omega >= t.omega.back()) {
    if (outside && (omega < t.omega.front() || omega > t.omega.back())) *outside = true;
    return row(omega <= t.omega.front() ? 0 : nf - 1);
  }
  const std::size_t f = static_cast<std::size_t>(std::upper_bound(t.omega.begin(), t.omega.end(), omega) - t.omega.begin()) - 1;
  return blend(row(f), row(f + 1), (omega - t.omega[f]) / (t.omega[f + 1] - t.omega[f]));
}

Mat3 rotationX(double a) { return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix(); }
Mat3 rotationY(double a) { return Eigen::AngleAxisd(a, Vec3::UnitY()).toRotationMatrix(); }
Mat3 rotationZ(double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); }

}  // namespace

RaoTable raoTableFromText(std::string_view text, const TableSpec& spec, bool phase_lead, bool rotations_in_radians,
                          std::vector<FieldError>& errors) {
  TextTable t;
  try {
    t = parseTable(text, spec, true);
  } catch (const InputError& e) {
    errors.insert(errors.end(), e.errors().begin(), e.errors().end());
    return {};
  }
  const std::size_t first_error = errors.size();
  errors.insert(errors.end(), t.errors.begin(), t.errors.end());
  // Columns by name.
  const int heading = t.column("heading"), omega = t.column("omega"), period = t.column("period");
  std::string missing;
  auto need = [&](const std::string& name) {
    const int c = t.column(name);
    if (c < 0) missing += (missing.empty() ? "" : ", ") + name;
    return c;
  };
  need("heading");
  int amplitude[6], phase[6];
  for (int d = 0; d < 6; ++d) {
    amplitude[d] = need(std::string(kDofNames[d]) + "_amplitude");
    phase[d] = need(std::string(kDofNames[d]) + "_phase");
  }
  if (omega < 0 && period < 0) missing += (missing.empty() ? "" : ", ") + std::string("omega (or period)");
  if (!missing.empty()) {
    errors.push_back(tableError(spec, 0, "expected " + std::string(kExpectedColumns) + "; missing: " + missing));
    return {};
  }
  if (omega >= 0 && period >= 0) {
    errors.push_back(tableError(spec, 0, "has both omega and period columns: give one"));
    return {};
  }
  const int frequency = omega >= 0 ? omega : period;
  if (t.rows.empty()) {
    errors.push_back(tableError(spec, 0, "has no data rows; expected " + std::string(kExpectedColumns)));
    return {};
  }
  RaoTable out;
  const double rotation_scale = rotations_in_radians ? 1.0 : kRadiansPerDegree;
  const double phase_sign = phase_lead ? -1.0 : 1.0;
  std::vector<double> block;  // the current heading's frequencies [rad/s] in file order
  std::vector<int> block_lines;
  auto closeBlock = [&] {
    if (block.empty()) return;
    if (out.heading.size() == 1) {
      out.omega = block;
    } else if (block.size() != out.omega.size() ||
               !std::equal(block.begin(), block.end(), out.omega.begin(),
                           [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); })) {
      errors.push_back(tableError(spec, block_lines.front(),
                                  "heading " + numberText(out.heading.back()) + " has other frequencies than heading " +
                                      numberText(out.heading.front()) + " (every heading needs the same frequencies)",
                                  &t, frequency));
    }
    block.clear();
    block_lines.clear();
  };
  for (const auto& row : t.rows) {
    bool complete = row.cells[heading].has_value() && row.cells[frequency].has_value();
    for (int d = 0; d < 6; ++d) complete = complete && row.cells[amplitude[d]] && row.cells[phase[d]];
    if (!complete) continue;  // its empty or bad cells are already in errors
    const double h = *row.cells[heading], f = *row.cells[frequency];
    if (!(f > 0)) {
      errors.push_back(tableError(spec, row.line, "must be > 0, found " + numberText(f), &t, frequency));
      continue;
    }
    const double w = omega >= 0 ? f : 2 * pi / f;
    if (out.heading.empty() || h != out.heading.back()) {
      if (!out.heading.empty() && !(h > out.heading.back())) {
        errors.push_back(tableError(spec, row.line,
                                    "heading " + numberText(h) + " after heading " + numberText(out.heading.back()) +
                                        ": rows must come in blocks of one heading, in increasing heading",
                                    &t, heading));
        continue;
      }
      closeBlock();
      out.heading.push_back(h);
    }
    if (!block.empty()) {
      const double previous = omega >= 0 ? block.back() : 2 * pi / block.back();
      if (!(f > previous)) {
        errors.push_back(tableError(spec, row.line,
                                    "must be greater than the previous row's " + numberText(previous) + " at heading " +
                                        numberText(h) + " (frequencies of one heading strictly increasing)",
                                    &t, frequency));
        continue;
      }
    }
    block.push_back(w);
    block_lines.push_back(row.line);
    for (int d = 0; d < 6; ++d) {
      const double a = *row.cells[amplitude[d]];
      if (a < 0) errors.push_back(tableError(spec, row.line, "must be ≥ 0 (an amplitude), found " + numberText(a), &t, amplitude[d]));
      out.amplitude[d].push_back(d >= 3 ? a * rotation_scale : a);
      out.phase_lag[d].push_back(phase_sign * radiansFromDegrees(*row.cells[phase[d]]));
    }
  }
  closeBlock();
  if (!out.heading.empty() && out.heading.back() - out.heading.front() > 360.0)
    errors.push_back(tableError(spec, 0, "headings span " + numberText(out.heading.back() - out.heading.front()) +
                                             " deg from " + numberText(out.heading.front()) + ": at most 360", &t, heading));
  if (errors.size() > first_error) return {};
  // A period column lists frequencies in decreasing order: store every block by increasing omega.
  if (period >= 0) {
    const std::size_t nf = out.omega.size();
    std::reverse(out.omega.begin(), out.omega.end());
    for (int d = 0; d < 6; ++d)
      for (std::size_t h = 0; h < out.heading.size(); ++h) {
        std::reverse(out.amplitude[d].begin() + static_cast<std::ptrdiff_t>(h * nf),
                     out.amplitude[d].begin() + static_cast<std::ptrdiff_t>((h + 1) * nf));
        std::reverse(out.phase_lag[d].begin() + static_cast<std::ptrdiff_t>(h * nf),
                     out.phase_lag[d].begin() + static_cast<std::ptrdiff_t>((h + 1) * nf));
      }
  }
  return out;
}

RaoValue interpolateRao(const RaoTable& t, double heading_deg, double omega, bool* outside, bool* clamped) {
  const std::size_t nh = t.heading.size();
  const double first = t.heading.front(), last = t.heading.back();
  if (nh == 1) {
    if (clamped && std::abs(std::remainder(heading_deg - first, 360.0)) > 1e-9) *clamped = true;
    return atHeading(t, 0, omega, outside);
  }
  // The heading moved into [first, first + 360).
  double h = first + std::fmod(heading_deg - first, 360.0);
  if (h < first) h += 360.0;
  if (h <= last) {
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(t.heading.begin(), t.heading.end(), h) - t.heading.begin()), nh - 1);
    const std::size_t a = k - 1;
    const double w = (h - t.heading[a]) / (t.heading[k] - t.heading[a]);
    return blend(atHeading(t, a, omega, outside), atHeading(t, k, omega, outside), w);
  }
  double widest = 0.0;
  for (std::size_t k = 1; k < nh; ++k) widest = std::max(widest, t.heading[k] - t.heading[k - 1]);
  const double gap = first + 360.0 - last;
  if (gap <= widest * (1 + 1e-12))  // the table goes round: wrap from the last heading to the first
    return blend(atHeading(t, nh - 1, omega, outside), atHeading(t, 0, omega, outside), (h - last) / gap);
  if (clamped) *clamped = true;
  return atHeading(t, h - last <= first + 360.0 - h ? nh - 1 : 0, omega, outside);
}

void VesselMotion::degreesOfFreedom(double t, Vec6& x, Vec6& v, Vec6& a) const {
  // The unramped motion d = Σ a R cos(ψ + ε) = P cos ψ − Q sin ψ (P = a R cos ε, Q = a R sin ε per dof and
  // component) and its derivatives (dψ/dt = −ω), in blocks of components whose cos ψ and sin ψ (core/
  // ocean_kinematics_batch: reduced to [−π, π], kernels in SIMD lanes) and their ω, ω² multiples fit on the stack;
  // each sum is a 6 × block matrix–vector product.
  constexpr std::size_t kBlock = 64;
  Vec6 d = Vec6::Zero(), dd = Vec6::Zero(), ddd = Vec6::Zero();
  double c[kBlock], s[kBlock], wc[kBlock], ws[kBlock], wwc[kBlock], wws[kBlock];
  for (std::size_t start = 0; start < omega_.size(); start += kBlock) {
    const std::size_t count = std::min(kBlock, omega_.size() - start);
    const double* w = omega_.data() + start;
    ocean::harmonicPhases(count, reference_phase_.data() + start, w, t, c, s);
    for (std::size_t j = 0; j < count; ++j) {
      wc[j] = w[j] * c[j], ws[j] = w[j] * s[j];
      wwc[j] = w[j] * wc[j], wws[j] = w[j] * ws[j];
    }
    const auto first = static_cast<Eigen::Index>(start), size = static_cast<Eigen::Index>(count);
    const auto in_phase = cos_part_.middleCols(first, size), quadrature = sin_part_.middleCols(first, size);
    using Block = Eigen::Map<const Eigen::VectorXd>;
    d.noalias() += in_phase * Block(c, size) - quadrature * Block(s, size);
    dd.noalias() += in_phase * Block(ws, size) + quadrature * Block(wc, size);
    ddd.noalias() += quadrature * Block(wws, size) - in_phase * Block(wwc, size);
  }
  const RiserSea& sea = *sea_;
  const double r = sea.ramp(t), rd = sea.rampRate(t), rdd = sea.rampAcceleration(t);
  x = r * d;
  v = rd * d + r * dd;
  a = rdd * d + 2 * rd * dd + r * ddd;
}

TopKinematics VesselMotion::at(double t) const {
  Vec6 x, v, a;
  degreesOfFreedom(t, x, v, a);
  // R = R_z(yaw) R_y(pitch) R_x(roll); each factor's rates: Ṙ_k = θ̇_k R_k K_k, R̈_k = θ̈_k R_k K_k + θ̇_k² R_k K_k².
  const Mat3 rx = rotationX(x[3]), ry = rotationY(x[4]), rz = rotationZ(x[5]);
  const Mat3 kx = skew(Vec3::UnitX()), ky = skew(Vec3::UnitY()), kz = skew(Vec3::UnitZ());
  const Mat3 rx1 = v[3] * rx * kx, ry1 = v[4] * ry * ky, rz1 = v[5] * rz * kz;
  const Mat3 rx2 = a[3] * rx * kx + v[3] * v[3] * rx * kx * kx, ry2 = a[4] * ry * ky + v[4] * v[4] * ry * ky * ky,
             rz2 = a[5] * rz * kz + v[5] * v[5] * rz * kz * kz;
  const Mat3 rotation = rz * ry * rx;
  const Mat3 rate = rz1 * ry * rx + rz * ry1 * rx + rz * ry * rx1;
  const Mat3 second = rz2 * ry * rx + rz * ry2 * rx + rz * ry * rx2 + 2 * (rz1 * ry1 * rx + rz1 * ry * rx1 + rz * ry1 * rx1);
  TopKinematics k;
  k.position = heading_ * (x.head<3>() + rotation * hang_off_ - hang_off_);
  k.velocity = heading_ * (v.head<3>() + rate * hang_off_);
  k.acceleration = heading_ * (a.head<3>() + second * hang_off_);
  if (vertical_free_) k.position.z() = k.velocity.z() = k.acceleration.z() = 0.0;
  return k;
}

std::shared_ptr<const VesselMotion> buildVesselMotion(const RiserParameters& p, std::shared_ptr<const RiserSea> sea,
                                                      const Vec3& top_mean, bool vertical_free) {
  TableSpec spec{"parameters.vessel.rao_file", p.vessel_rao_file, kExpectedColumns};
  const std::string text = readDataText(p.vessel_rao_file, "riser", spec.field);
  refuseForeignFormat(text, spec);
  std::vector<FieldError> errors;
  const RaoTable table =
      raoTableFromText(text, spec, p.vessel_rao_phase == "lead", p.vessel_rao_rotation_unit == "rad", errors);
  if (!errors.empty()) throw InputError(std::move(errors));
  auto m = std::make_shared<VesselMotion>();
  const double heading = radiansFromDegrees(p.vessel_heading_deg);
  m->heading_ = rotationZ(heading);
  m->hang_off_ = Vec3(p.vessel_hang_off_x, p.vessel_hang_off_y, p.vessel_hang_off_z);
  m->reference = top_mean - m->heading_ * m->hang_off_;
  m->vertical_free_ = vertical_free;
  const ocean::WaveField& field = sea->field;
  const double direction = radiansFromDegrees(p.wave_direction_deg);
  const double relative_deg = p.wave_direction_deg - p.vessel_heading_deg;
  const auto n = static_cast<Eigen::Index>(field.size());
  m->cos_part_.setZero(6, n);
  m->sin_part_.setZero(6, n);
  bool outside = false, clamped = false;
  double variance = 0.0, variance_outside = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const ocean::WaveComponent& c = field.components()[static_cast<std::size_t>(i)];
    const double k = ocean::waveNumber(c.omega, field.depth(), p.gravity);  // as the field's own k
    const double kx = k * std::cos(direction), ky = k * std::sin(direction);
    m->omega_.push_back(c.omega);
    // ψ = k·x_ref + φ − ω t, as WaveField::elevation: the part without t once, not at every call
    m->reference_phase_.push_back(kx * m->reference.x() + ky * m->reference.y() + c.phase);
    bool this_outside = false;
    const RaoValue rao = interpolateRao(table, relative_deg, c.omega, &this_outside, &clamped);
    variance += 0.5 * c.amplitude * c.amplitude;
    if (this_outside) variance_outside += 0.5 * c.amplitude * c.amplitude;
    outside = outside || this_outside;
    for (int d = 0; d < 6; ++d) {
      m->cos_part_(d, i) = c.amplitude * rao.amplitude[d] * std::cos(rao.phase_lag[d]);
      m->sin_part_(d, i) = c.amplitude * rao.amplitude[d] * std::sin(rao.phase_lag[d]);
    }
  }
  m->mean_period = field.meanPeriod();
  if (outside)
    m->warnings.push_back("vessel.rao_file: wave components outside the RAO frequencies [" + numberText(table.omega.front()) +
                          ", " + numberText(table.omega.back()) + "] rad/s (" + numberText(100.0 * variance_outside / variance) +
                          " % of the wave variance) take the nearest row's RAO");
  if (clamped)
    m->warnings.push_back("vessel.rao_file: the relative wave direction " + numberText(relative_deg) +
                          " deg (waves.direction_deg − vessel.heading_deg) is outside the RAO headings [" +
                          numberText(table.heading.front()) + ", " + numberText(table.heading.back()) +
                          "] deg: the nearest heading's RAOs are used");
  m->sea_ = std::move(sea);
  return m;
}

void bindVesselParameters(SchemaBinder<RiserParameters>& b) {
  b.dataPath("vessel.rao_file", &P::vessel_rao_file,
         "Displacement RAOs of the vessel (top.motion = vessel): CSV \"builtin:NAME\" or a path, columns heading "
         "[deg], omega [rad/s] (or period [s]), <dof>_amplitude and <dof>_phase [deg] for surge, sway, heave [m/m], "
         "roll, pitch, yaw [deg/m] (docs/riser.md, Vessel motion)");
  b.choice("vessel.rao_phase", &P::vessel_rao_phase, {"lag", "lead"},
           "Sign of the RAO phases: lag (OrcaFlex's default: x = a R cos(ωt − ε) for η = a cos(ωt) at the RAO "
           "origin) or lead (x = a R cos(ωt + ε))");
  b.choice("vessel.rao_rotation_unit", &P::vessel_rao_rotation_unit, {"deg", "rad"},
           "Unit of the roll, pitch and yaw amplitudes per metre of wave amplitude (deg/m or rad/m)");
  b.real("vessel.heading_deg", &P::vessel_heading_deg, "deg", Range::closed(-360, 360),
         "Vessel heading: its x axis (bow) from global +x towards +y; the RAO direction is waves.direction_deg minus "
         "this");
  b.real("vessel.hang_off_x", &P::vessel_hang_off_x, "m", Range::closed(-1e4, 1e4),
         "Hang-off point (the riser top) from the RAO origin along the vessel x axis (forward)");
  b.real("vessel.hang_off_y", &P::vessel_hang_off_y, "m", Range::closed(-1e4, 1e4),
         "Hang-off point from the RAO origin along the vessel y axis (to port)");
  b.real("vessel.hang_off_z", &P::vessel_hang_off_z, "m", Range::closed(-1e4, 1e4),
         "Hang-off point from the RAO origin along the vessel z axis (up)");
  b.real("vessel.offset_x", &P::vessel_offset_x, "m", Range::closed(-1e4, 1e4),
         "Static vessel offset along global x: moves the top's mean position from top.x (any top motion)");
  b.real("vessel.offset_y", &P::vessel_offset_y, "m", Range::closed(-1e4, 1e4), "Static vessel offset along global y");
  b.real("vessel.offset_z", &P::vessel_offset_z, "m", Range::closed(-1e4, 1e4),
         "Static vessel offset along global z (ignored for the tensioner, whose top height the geometry sets)");
}

void checkVesselParameters(const RiserParameters& p, std::vector<FieldError>& e) {
  if (p.top_motion != "vessel") return;
  if (p.wave_type == "none")
    e.push_back({"top.motion", "\"vessel\"", "the vessel moves in the waves: needs waves.type other than none"});
  if (p.vessel_rao_file.empty()) {
    e.push_back({"vessel.rao_file", "\"\"", "must name a CSV of displacement RAOs when top.motion = vessel"});
    return;
  }
  if (auto problem = dataPathProblem(p.vessel_rao_file, "riser")) {
    e.push_back({"vessel.rao_file", Json(p.vessel_rao_file).dump(), *problem});
    return;
  }
  TableSpec spec{"vessel.rao_file", p.vessel_rao_file, kExpectedColumns};
  try {
    const std::string text = readDataText(p.vessel_rao_file, "riser", spec.field);
    refuseForeignFormat(text, spec);
    raoTableFromText(text, spec, p.vessel_rao_phase == "lead", p.vessel_rao_rotation_unit == "rad", e);
  } catch (const InputError& x) {
    e.insert(e.end(), x.errors().begin(), x.errors().end());
  }
}

void upgradeVesselParameters(Json& parameters, std::vector<std::string>& notes) {
  if (parameters.contains("vessel")) return;
  parameters["vessel"] = riserBinder().write(RiserParameters{})["vessel"];
  notes.push_back("vessel added, unused (new in the riser schema: top.motion = vessel; save the scenario to keep it)");
}

}  // namespace maris::riser
