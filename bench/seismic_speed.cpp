// Seismic scene work–precision benchmark, written as CSV (default seismic_speed.csv, or argv[1]; a second
// argument "reef" runs part 3 only, "synthesis" part 0 only):
//   0. free-field Fourier synthesis (FFT through core/spectrum.hpp): solid histories at 50 depths of a 5 s
//      record at dt = 1 ms, below (FFT length 16384) and beyond (65536) the critical angle, plus 200 bare
//      forward FFTs of each length;
//   1. free-field transfer functions at 1e5 (frequency, angle) points: time and worst energy residual;
//   2. the paper's verification box (600 m water over 600 m seabed, 0.2 s P pulse at 45°, 5 s) on
//      meshes from f_cut = 5 to 20 Hz: wall time against the peak error vs the analytic free field;
//   3. the placeholder reef (Ricker 1 Hz P at 30°, with water, 5 s) on Δ = 50, 25, 16.7 m against
//      Δ = 12.5 m: CPU time against the error of the largest R_a,x and R_a,y on the flat, next to the
//      scene's own coarse-companion estimate.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "catalog.hpp"
#include "core/run_context.hpp"
#include "core/scenario.hpp"
#include "core/spectrum.hpp"
#include "seismic/free_field.hpp"
#include "seismic/free_field_synthesis.hpp"
#include "seismic/seismic_solve.hpp"
#include "bench_clock.hpp"

using namespace maris;
using namespace maris::seismic;

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}


double peakError(const std::vector<double>& fe, const std::vector<double>& ff) {
  double a = 0.0, b = 0.0;
  for (double x : fe) a = std::max(a, std::abs(x));
  for (double x : ff) b = std::max(b, std::abs(x));
  return std::abs(a - b) / b;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "seismic_speed.csv";
  std::ostringstream csv;
  // Error columns: box rows B u_x, B u_y, A u_y peak errors; reef rows max R_a,x, max R_a,y errors and the
  // companion estimate.
  csv << "case,parameter,points_or_cells,steps,wall_time_s,cpu_time_s,error_1,error_2,error_3\n";

  const bool reef_only = argc > 2 && std::string(argv[2]) == "reef";
  const bool synthesis_only = argc > 2 && std::string(argv[2]) == "synthesis";
  // 0. Free-field synthesis: the FFT-bound part of every run's boundary driving.
  if (!reef_only) {
    const ElasticMaterial seabed{2700.0, 4500.0, 1800.0};
    const WaterLayer water{1025.0, 1450.0, 600.0};
    const double dt = 1e-3;
    std::vector<double> pulse(5001, 0.0);  // Ricker 5 Hz centred at 0.3 s
    for (std::size_t k = 0; k < pulse.size(); ++k) {
      const double a = std::numbers::pi * 5.0 * (static_cast<double>(k) * dt - 0.3);
      pulse[k] = (1.0 - 2.0 * a * a) * std::exp(-a * a);
    }
    for (const double angle : {30.0, 70.0}) {
      const FreeField ff(seabed, water, WaveType::P, angle * std::numbers::pi / 180.0);
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = maris::bench::processCpuSeconds();
      const FreeFieldSynthesis synthesis(ff, pulse, 0.0, dt);
      double checksum = 0.0;
      for (int d = 0; d < 50; ++d) checksum += synthesis.solid(-12.0 * d).uy[2500];
      const double t = seconds(t0), c = maris::bench::processCpuSeconds() - c0;
      std::printf("synthesis P %.0f deg: 50 depths x 5001 samples in %.4f s wall, %.4f s CPU (checksum %.9e)\n", angle, t,
                  c, checksum);
      csv << "free_field_synthesis,P " << angle << " deg 50 depths,5001,0," << t << "," << c << ",,,\n";
    }
    for (const std::size_t n : {std::size_t{16384}, std::size_t{65536}}) {
      std::vector<Complex> x(n);
      for (std::size_t k = 0; k < n; ++k) x[k] = Complex(std::sin(0.001 * static_cast<double>(k * k % 7919)), 0.0);
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = maris::bench::processCpuSeconds();
      double checksum = 0.0;
      for (int r = 0; r < 200; ++r) checksum += std::abs(fft(x)[static_cast<std::size_t>(r)]);
      const double t = seconds(t0), c = maris::bench::processCpuSeconds() - c0;
      std::printf("fft: 200 forward transforms of length %zu in %.4f s wall, %.4f s CPU (%.1f us CPU each, checksum "
                  "%.9e)\n", n, t, c, 1e6 * c / 200.0, checksum);
      csv << "fft,length " << n << ",200,0," << t << "," << c << ",,,\n";
    }
    std::fflush(stdout);
  }
  if (synthesis_only) {
    writeFileAtomic(out, csv.str());
    std::printf("written %s\n", out.c_str());
    return 0;
  }
  // 1. Transfer functions: 100 angles × 1000 frequencies, P with water, at the seabed.
  if (!reef_only) {
    const ElasticMaterial seabed{2700.0, 4500.0, 1800.0};
    const WaterLayer water{1025.0, 1450.0, 600.0};
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = maris::bench::processCpuSeconds();
    double worst = 0.0, checksum = 0.0;
    for (int a = 0; a < 100; ++a) {
      const FreeField ff(seabed, water, WaveType::P, a * 0.75 * std::numbers::pi / 180.0);
      for (int k = 1; k <= 1000; ++k) {
        const Complex w(2.0 * std::numbers::pi * 0.02 * k, 0.0);
        const auto amp = ff.solve(w);
        checksum += std::abs(ff.solidAt(amp, w, 0.0, 0.0).uy);
        worst = std::max(worst, std::abs(ff.energyResidual(amp)));
      }
    }
    const double t = seconds(t0), c = maris::bench::processCpuSeconds() - c0;
    std::printf("free field: 1e5 transfer functions in %.4f s wall, %.4f s CPU, worst energy residual %.2e (checksum %.6f)\n",
                t, c, worst, checksum);
    csv << "free_field_transfer,P 0-74.25 deg x 0.02-20 Hz,100000,0," << t << "," << c << "," << worst << ",,\n";
  }

  // 2. Verification box on successively finer meshes (single thread).
  const auto* builtin = findBuiltin("seismic_verification_box");
  if (!builtin) {
    std::fprintf(stderr, "built-in scenario seismic_verification_box missing\n");
    return 1;
  }
  SeismicParameters p = seismicBinder().read(builtin->scenario.parameters);
  p.duration = 5.0;
  for (double f_cut : {5.0, 10.0, 15.0, 20.0}) {
    if (reef_only) break;
    p.cutoff_frequency = f_cut;
    RunContext ctx;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = maris::bench::processCpuSeconds();
    const FeCase c = runFeCase(p, p.angle_deg, true, false, ctx);
    const double t = seconds(t0), cpu = maris::bench::processCpuSeconds() - c0;
    const double eb_x = peakError(c.seabed_fe_ux, c.seabed_ff_ux), eb_y = peakError(c.seabed_fe_uy, c.seabed_ff_uy);
    const double ea_y = peakError(c.probe_fe_uy, c.probe_ff_uy);
    std::printf("verification box f_cut %4.1f Hz: %6d cells, %5ld steps, %7.2f s wall, %6.2f s CPU; peak errors B ux %.4f "
                "uy %.4f A uy %.4f\n",
                f_cut, c.cell_count, c.steps, t, cpu, eb_x, eb_y, ea_y);
    std::fflush(stdout);
    csv << "verification_box,f_cut " << f_cut << " Hz," << c.cell_count << "," << c.steps << "," << t << "," << cpu << "," << eb_x
        << "," << eb_y << "," << ea_y << "\n";
  }
  // 3. Reef work–precision against the finest mesh (all meshes put the layer interfaces on grid lines).
  SeismicParameters reef;
  reef.ricker_peak_frequency = 1.0;
  reef.duration = 5.0;
  reef.station_count = 21;
  auto largest = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
  std::vector<double> cutoffs{1.6, 3.2, 4.8, 6.4};
  std::vector<PeakRatios> ratios;
  std::vector<FeCase> cases;
  std::vector<double> cpu_times;
  for (double f_cut : cutoffs) {
    reef.cutoff_frequency = f_cut;
    RunContext ctx;
    const double c0 = maris::bench::processCpuSeconds();
    cases.push_back(runFeCase(reef, 30.0, true, false, ctx));
    cpu_times.push_back(maris::bench::processCpuSeconds() - c0);
    ratios.push_back(amplificationRatios(cases.back()));
  }
  const PeakRatios& best = ratios.back();
  for (std::size_t k = 0; k + 1 < cutoffs.size(); ++k) {
    const double ex = std::abs(largest(ratios[k].ax) / largest(best.ax) - 1.0);
    const double ey = std::abs(largest(ratios[k].ay) / largest(best.ay) - 1.0);
    // The scene's estimate for this mesh: change against its coarse companion.
    RunContext ctx;
    reef.cutoff_frequency = cutoffs[k];
    const PeakRatios coarse = amplificationRatios(runFeCase(reef, 30.0, true, false, ctx, true));
    const double est = std::max(std::abs(largest(coarse.ax) / largest(ratios[k].ax) - 1.0),
                                std::abs(largest(coarse.ay) / largest(ratios[k].ay) - 1.0));
    std::printf("reef Δ %5.1f m: %6d cells, %5ld steps, %6.2f s CPU; error vs Δ %.1f m: max R_ax %.4f, max R_ay %.4f; "
                "companion estimate %.4f\n",
                cases[k].element_size, cases[k].cell_count, cases[k].steps, cpu_times[k], cases.back().element_size, ex,
                ey, est);
    std::fflush(stdout);
    csv << "reef_work_precision,delta " << cases[k].element_size << " m," << cases[k].cell_count << "," << cases[k].steps
        << ",," << cpu_times[k] << "," << ex << "," << ey << "," << est << "\n";
  }
  writeFileAtomic(out, csv.str());
  std::printf("written %s\n", out.c_str());
  return 0;
}
