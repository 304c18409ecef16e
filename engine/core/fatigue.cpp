// Rainflow counting, S–N curves and Miner damage (contract in core/fatigue.hpp).
#include "core/fatigue.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace maris::fatigue {
namespace {

// DNVGL-RP-C203, Edition April 2016. Table 2-1 (in air): log a_1 for N ≤ 10^7 and log a_2 (m_2 = 5) beyond;
// Table 2-2 (seawater with cathodic protection): log a_1 for N ≤ 10^6, the same log a_2 beyond. Thickness
// exponents k and the fatigue limits at 10^7 cycles as the tables list them (the limit is a check of the
// other columns: 10^((log a_2 − 7)/5)). The table of curves in seawater for free corrosion: one slope m = 3 for every
// curve, log a and its own thickness exponent (the last two columns).
struct DnvRow {
  const char* name;
  double m1, log_a1_air, log_a1_seawater_cp, log_a2, k, fatigue_limit_mpa;
  double log_a_free_corrosion, k_free_corrosion;
};
constexpr DnvRow kDnvRows[] = {
    {"B1", 4.0, 15.117, 14.917, 17.146, 0.00, 106.97, 12.436, 0.00},
    {"B2", 4.0, 14.885, 14.685, 16.856, 0.00, 93.59, 12.262, 0.00},
    {"C", 3.0, 12.592, 12.192, 16.320, 0.05, 73.10, 12.115, 0.15},
    {"C1", 3.0, 12.449, 12.049, 16.081, 0.10, 65.50, 11.972, 0.15},
    {"C2", 3.0, 12.301, 11.901, 15.835, 0.15, 58.48, 11.824, 0.15},
    {"D", 3.0, 12.164, 11.764, 15.606, 0.20, 52.63, 11.687, 0.20},
    {"E", 3.0, 12.010, 11.610, 15.350, 0.20, 46.78, 11.533, 0.20},
    {"F", 3.0, 11.855, 11.455, 15.091, 0.25, 41.52, 11.378, 0.25},
    {"F1", 3.0, 11.699, 11.299, 14.832, 0.25, 36.84, 11.222, 0.25},
    {"F3", 3.0, 11.546, 11.146, 14.576, 0.25, 32.75, 11.068, 0.25},
    {"G", 3.0, 11.398, 10.998, 14.330, 0.25, 29.24, 10.921, 0.25},
    {"W1", 3.0, 11.261, 10.861, 14.101, 0.25, 26.32, 10.784, 0.25},
    {"W2", 3.0, 11.107, 10.707, 13.845, 0.25, 23.39, 10.630, 0.25},
    {"W3", 3.0, 10.970, 10.570, 13.617, 0.25, 21.05, 10.493, 0.25},
};
const DnvRow& dnvRow(const std::string& name) {
  for (const auto& row : kDnvRows)
    if (name == row.name) return row;
  std::string names;
  for (const auto& row : kDnvRows) names += std::string(names.empty() ? "" : ", ") + row.name;
  throw std::invalid_argument("unknown DNVGL-RP-C203 S-N curve '" + name + "' (one of " + names + ")");
}

}  // namespace

std::vector<double> turningPoints(const std::vector<double>& signal) {
  std::vector<double> points;
  for (double x : signal) {
    if (!std::isfinite(x)) throw std::invalid_argument("rainflow: the signal has a non-finite sample");
    if (!points.empty() && x == points.back()) continue;  // plateau
    // Drop the previous point when it lies between its neighbours (the signal goes on in one direction).
    if (points.size() >= 2 && (points.back() - points[points.size() - 2]) * (x - points.back()) > 0.0) points.pop_back();
    points.push_back(x);
  }
  return points;
}

std::vector<Cycle> rainflow(const std::vector<double>& signal) {
  std::vector<Cycle> cycles;
  std::vector<double> stack;  // points not yet discarded; stack.front() is the starting point S
  auto count = [&](double a, double b, double n) { cycles.push_back({std::abs(a - b), 0.5 * (a + b), n}); };
  for (double point : turningPoints(signal)) {
    stack.push_back(point);
    while (stack.size() >= 3) {
      const std::size_t last = stack.size() - 1;
      const double x = std::abs(stack[last] - stack[last - 1]), y = std::abs(stack[last - 1] - stack[last - 2]);
      if (x < y) break;
      if (stack.size() == 3) {  // Y contains S: half a cycle, S moves to Y's second point
        count(stack[0], stack[1], 0.5);
        stack.erase(stack.begin());
      } else {
        count(stack[last - 2], stack[last - 1], 1.0);
        stack.erase(stack.begin() + static_cast<std::ptrdiff_t>(last - 2), stack.begin() + static_cast<std::ptrdiff_t>(last));
      }
    }
  }
  for (std::size_t i = 0; i + 1 < stack.size(); ++i) count(stack[i], stack[i + 1], 0.5);
  return cycles;
}

double SnCurve::transitionRange() const {
  if (m2 == 0.0) return 0.0;
  return std::pow(10.0, (log_a1 - std::log10(transition_cycles)) / m1);
}

SnCurve dnvCurve(const std::string& name, SnEnvironment environment) {
  const DnvRow& row = dnvRow(name);
  SnCurve c;
  c.reference_thickness = 25.0;
  if (environment == SnEnvironment::SeawaterFreeCorrosion) {
    c.name = std::string("DNVGL-RP-C203 ") + row.name + " in seawater for free corrosion";
    c.m1 = 3.0;
    c.log_a1 = row.log_a_free_corrosion;
    c.m2 = 0.0;  // one slope at every N
    c.thickness_exponent = row.k_free_corrosion;
    return c;
  }
  const bool air = environment == SnEnvironment::Air;
  c.name = std::string("DNVGL-RP-C203 ") + row.name + (air ? " in air" : " in seawater with cathodic protection");
  c.m1 = row.m1;
  c.log_a1 = air ? row.log_a1_air : row.log_a1_seawater_cp;
  c.m2 = 5.0;
  c.log_a2 = row.log_a2;
  c.transition_cycles = air ? 1e7 : 1e6;
  c.thickness_exponent = row.k;
  return c;
}

std::vector<std::string> dnvCurveNames() {
  std::vector<std::string> names;
  for (const auto& row : kDnvRows) names.emplace_back(row.name);
  return names;
}

double dnvFatigueLimit(const std::string& name) { return dnvRow(name).fatigue_limit_mpa; }

double cyclesToFailure(const SnCurve& curve, double stress_range_mpa, double thickness_mm) {
  if (!(stress_range_mpa >= 0.0)) throw std::invalid_argument("S-N curve: stress range must be ≥ 0");
  if (stress_range_mpa == 0.0) return std::numeric_limits<double>::infinity();
  double factor = 1.0;
  if (thickness_mm > 0.0 && curve.thickness_exponent != 0.0)
    factor = std::pow(std::max(thickness_mm, curve.reference_thickness) / curve.reference_thickness,
                      curve.thickness_exponent);
  const double log_s = std::log10(stress_range_mpa * factor);
  const double log_n1 = curve.log_a1 - curve.m1 * log_s;
  if (curve.m2 == 0.0 || log_n1 <= std::log10(curve.transition_cycles)) return std::pow(10.0, log_n1);
  return std::pow(10.0, curve.log_a2 - curve.m2 * log_s);
}

double minerDamage(const std::vector<Cycle>& cycles_pa, const SnCurve& curve, double thickness_mm) {
  double damage = 0.0;
  for (const auto& c : cycles_pa) damage += c.count / cyclesToFailure(curve, 1e-6 * c.range, thickness_mm);
  return damage;
}

}  // namespace maris::fatigue
