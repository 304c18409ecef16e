#include "fiv/fiv_results.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "fiv/fiv_theory.hpp"

namespace maris::fiv {

namespace {

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string hstarText(double h_star) { return std::isfinite(h_star) ? fixed(h_star, 2) : "∞"; }

// Per-branch columns of one sweep direction.
void addDirectionColumns(Table& t, const FivModel& model, const std::vector<double>& speeds,
                         const SweepBranch& branch, const std::vector<LimitCycle>& cycles, const std::string& dir) {
  const std::string label = submergenceLabel(branch.submergence_ratio);
  std::vector<double> a_star, spread, response, f_star, power, power_fluid, eta, residual, clear;
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    const LimitCycle& c = cycles[i];
    a_star.push_back(c.amplitude / model.side);
    spread.push_back(c.amplitude_spread / model.side);
    response.push_back(static_cast<double>(static_cast<int>(c.response)));
    f_star.push_back(c.frequency / model.f_n);
    power.push_back(c.power_damper);
    power_fluid.push_back(c.power_fluid);
    const double fluid = sweptFluidPower(model.density, speeds[i], model.length, model.side, c.amplitude);
    eta.push_back(betzEfficiency(c.power_damper, fluid));
    residual.push_back(c.residual);
    clear.push_back(branch.clearanceExceeded(c) ? 1.0 : 0.0);
  }
  // Labels: the quantity's symbol, the sweep direction and the submergence ratio ("A*/D, up, h* = 1.11").
  const std::string of = ", " + dir + ", h* = " + hstarText(branch.submergence_ratio);
  t.add("A_star_" + dir + "_" + label, "-", a_star, "A*/D" + of);
  t.add("f_star_" + dir + "_" + label, "-", f_star, "f*" + of);
  t.add("P_" + dir + "_" + label, "W", power, "P = c⟨ẏ²⟩" + of);
  t.add("PF_" + dir + "_" + label, "W", power_fluid, "⟨F ẏ⟩" + of);
  t.add("eta_" + dir + "_" + label, "-", eta, "η" + of);
  t.add("residual_" + dir + "_" + label, "-", residual, "Residual" + of);
  t.add("A_spread_" + dir + "_" + label, "-", spread, "Cycle-to-cycle std of A*/D" + of);
  t.add("response_" + dir + "_" + label, "-", response,
        "Response (0 rest, 1 periodic, 2 quasi-periodic, 3 drifting)" + of);
  t.add("clearance_exceeded_" + dir + "_" + label, "-", clear, "Clearance exceeded (1 = yes)" + of);
}

void addBranchScalars(Results& r, const FivModel& model, const std::vector<double>& speeds, const SweepBranch& b) {
  const std::string label = submergenceLabel(b.submergence_ratio);
  const std::string hs = "h* = " + hstarText(b.submergence_ratio);
  if (std::isfinite(b.linear_onset_speed))
    r.addScalar("linear_onset_speed_" + label, b.linear_onset_speed, "m/s",
                "Quasi-steady galloping onset 2c/(ρDLκ_g A1), " + hs, "Linear onset U, " + hs);
  if (b.onset_speed >= 0.0)
    r.addScalar("galloping_onset_speed_" + label, b.onset_speed, "m/s",
                "Lowest up-sweep speed from which A/D stays above the onset threshold, " + hs, "Galloping onset U, " + hs);
  std::size_t i_p = 0, i_eta = 0;
  std::vector<double> eta(speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const LimitCycle& c = b.up[i];
    eta[i] = betzEfficiency(c.power_damper,
                            sweptFluidPower(model.density, speeds[i], model.length, model.side, c.amplitude));
    if (c.power_damper > b.up[i_p].power_damper) i_p = i;
    if (eta[i] > eta[i_eta]) i_eta = i;
  }
  r.addScalar("max_power_" + label, b.up[i_p].power_damper, "W", "Largest ⟨cẏ²⟩ of the up-sweep, " + hs, "max P, " + hs);
  r.addScalar("amplitude_ratio_at_max_speed_" + label, b.up.back().amplitude / model.side, "-",
              "A/D at the highest speed (up-sweep), " + hs, "A/D at the highest U, " + hs);
  r.addScalar("max_efficiency_" + label, eta[i_eta], "-", "Largest η = P/(½ρU³L(D+2A)·16/27), " + hs, "max η, " + hs);
  r.addScalar("speed_of_max_efficiency_" + label, speeds[i_eta], "m/s", "Speed of the largest η, " + hs, "U at max η, " + hs);
  // The cylinder would pierce the free surface: the model does not hold there.
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (!b.clearanceExceeded(b.up[i])) continue;
    r.warnings.push_back(hs + ": the upward excursion exceeds the clearance h − D/2 = " + fixed(b.clearance, 3) +
                         " m from U = " + fixed(speeds[i], 2) + " m/s (" + fixed(b.up[i].y_max, 3) +
                         " m): the cylinder would break the surface; results there are outside the model");
    break;
  }
}

PlotSpec curvePlot(std::string name, std::string title, std::string x, std::vector<std::string> y,
                   std::string reference_table = {}, std::vector<std::string> reference_y = {}) {
  PlotSpec p = makePlot(std::move(name), std::move(title), "sweep", std::move(x), std::move(y));
  p.reference_table = std::move(reference_table);
  p.reference_y = std::move(reference_y);
  return p;
}

}  // namespace


void addSweepResults(Results& results, const FivModel& model, const SweepResult& sweep, bool has_reference) {
  Table t;
  t.name = "sweep";
  t.title = "Limit cycles over current speed per submergence ratio (up- and down-sweep)";
  std::vector<double> u_star, re;
  for (double u : sweep.speeds) {
    u_star.push_back(u / (model.f_n * model.side));
    re.push_back(u * model.side / model.viscosity);
  }
  t.add("U", "m/s", sweep.speeds, "Current speed U");
  t.add("U_star", "-", u_star, "U*");
  t.add("Re", "-", re, "Re");
  std::vector<std::string> a_up, a_both, f_up, p_up, eta_up;
  for (const SweepBranch& b : sweep.branches) {
    const std::string label = submergenceLabel(b.submergence_ratio);
    addDirectionColumns(t, model, sweep.speeds, b, b.up, "up");
    if (!b.down.empty()) addDirectionColumns(t, model, sweep.speeds, b, b.down, "down");
    if (std::isfinite(b.submergence_ratio)) {
      std::vector<double> froude;
      for (double u : sweep.speeds) froude.push_back(u / std::sqrt(model.gravity * b.submergence_ratio * model.side));
      t.add("Fr_" + label, "-", froude, "Fr, h* = " + hstarText(b.submergence_ratio));
    }
    a_up.push_back("A_star_up_" + label);
    a_both.push_back("A_star_up_" + label);
    if (!b.down.empty()) a_both.push_back("A_star_down_" + label);
    f_up.push_back("f_star_up_" + label);
    p_up.push_back("P_up_" + label);
    eta_up.push_back("eta_up_" + label);
    addBranchScalars(results, model, sweep.speeds, b);
  }
  results.tables.push_back(std::move(t));
  const std::string ra = has_reference ? "paper_amplitude" : "", rf = has_reference ? "paper_frequency" : "",
                    rp = has_reference ? "paper_power" : "";
  auto refs = [&](const char* col) { return has_reference ? std::vector<std::string>{col} : std::vector<std::string>{}; };
  results.plots.push_back(curvePlot("amplitude_ratio", "Amplitude ratio A/D vs reduced velocity (up-sweep)", "U_star",
                                    a_up, ra, refs("A_star")));
  if (a_both.size() > a_up.size())
    results.plots.push_back(curvePlot("amplitude_hysteresis", "A/D up- and down-sweep (hysteresis)", "U_star", a_both));
  results.plots.push_back(curvePlot("frequency_ratio", "Frequency ratio f/f_n vs reduced velocity (up-sweep)",
                                    "U_star", f_up, rf, refs("f_star")));
  results.plots.push_back(curvePlot("power", "Converted power ⟨cẏ²⟩ vs current speed (up-sweep)", "U", p_up, rp,
                                    refs("P")));
  results.plots.push_back(curvePlot("efficiency", "Efficiency against Betz-limited fluid power (up-sweep)", "U",
                                    eta_up, rp, refs("eta_implied")));
}

void addReferenceTables(Results& results, const FivModel& model, const std::vector<ReferencePoint>& points) {
  Table ta, tf, tp;
  ta.name = "paper_amplitude";
  ta.title = "Reference amplitudes";
  tf.name = "paper_frequency";
  tf.title = "Reference response frequencies";
  tp.name = "paper_power";
  tp.title = "Reference converted power (and the efficiency it implies with this model's L and ρ)";
  std::vector<double> au, aus, ah, aa, fu, fus, fh, ff, pu, pus, ph, pp, pe;
  const double to_u_star = 1.0 / (model.f_n * model.side);
  for (const ReferencePoint& p : points) {
    const double h = std::isfinite(p.submergence_ratio) ? p.submergence_ratio : 0.0;
    if (p.amplitude) {
      au.push_back(p.speed), aus.push_back(p.speed * to_u_star), ah.push_back(h), aa.push_back(*p.amplitude / model.side);
    }
    if (p.frequency) {
      fu.push_back(p.speed), fus.push_back(p.speed * to_u_star), fh.push_back(h), ff.push_back(*p.frequency / model.f_n);
    }
    if (p.power) {
      pu.push_back(p.speed), pus.push_back(p.speed * to_u_star), ph.push_back(h), pp.push_back(*p.power);
      const double a = p.amplitude.value_or(0.0);
      pe.push_back(betzEfficiency(*p.power, sweptFluidPower(model.density, p.speed, model.length, model.side, a)));
    }
  }
  const char* h_note = "-";
  auto add_conditions = [&](Table& t, std::vector<double>& u, std::vector<double>& us, std::vector<double>& h) {
    t.add("U", "m/s", std::move(u), "Current speed U");
    t.add("U_star", "-", std::move(us), "U*");
    t.add("h_star_or_0_for_deep", h_note, std::move(h), "h* (0: deep)");
  };
  add_conditions(ta, au, aus, ah), add_conditions(tf, fu, fus, fh), add_conditions(tp, pu, pus, ph);
  ta.add("A_star", "-", aa, "A*/D measured"), tf.add("f_star", "-", ff, "f* measured"), tp.add("P", "W", pp, "P measured");
  tp.add("eta_implied", "-", pe, "η implied");
  results.tables.push_back(std::move(ta));
  results.tables.push_back(std::move(tf));
  results.tables.push_back(std::move(tp));
}

}  // namespace maris::fiv
