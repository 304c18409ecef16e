// Tether scene speed: (1) catenary forward solve time and round-trip error across the taut-to-slack range,
// (2) 60 s closed loop with the 150-link cable against real time, (3) the cable's deviation from the catenary
// and its time-discretisation error against the cable time step. Writes CSVs into the folder given as argv[1]
// (default: bench-results/tether).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "catalog.hpp"
#include "core/scenario.hpp"
#include "tether/tether_parameters.hpp"
#include "tether/tether_simulation.hpp"
#include "bench_clock.hpp"

using namespace maris;
using namespace maris::tether;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }


TetherParameters builtinParameters(const std::string& id) {
  return tetherBinder().read(findBuiltin(id)->scenario.parameters);
}

std::string catenarySolveTimes() {
  std::string csv = "r_minus_1,time_per_solve,iterations,roundtrip_rel_error_sag\n-,ns,-,-\n";
  std::printf("catenary forward solve (L = 1.5 m, level span; CPU time)\n%10s %12s %6s %14s\n", "r-1", "ns/solve", "iter",
              "round-trip err");
  const double L = 1.5;
  for (double e = -12; e <= 10; e += 2) {
    const double span = L / (1.0 + std::pow(10.0, e));
    const int reps = 200000;
    double sink = 0.0;
    const double cpu0 = maris::bench::processCpuSeconds();
    for (int i = 0; i < reps; ++i) sink += catenaryFromSpan(span * (1.0 + 1e-12 * (i & 7)), 0.0, L).sag;
    const double ns = 1e9 * (maris::bench::processCpuSeconds() - cpu0) / reps;
    const Catenary c = catenaryFromSpan(span, 0.0, L);
    const Catenary back = catenaryFromShape(c.sag, 0.0, L);
    const Catenary again = catenaryFromSpan(back.span, 0.0, L);
    const double err = std::abs(again.sag - c.sag) / c.sag;
    std::printf("%10.0e %12.1f %6d %14.2e%s\n", std::pow(10.0, e), ns, c.iterations, err, sink > 0 ? "" : " ");
    char row[160];
    std::snprintf(row, sizeof row, "%.3e,%.2f,%d,%.3e\n", std::pow(10.0, e), ns, c.iterations, err);
    csv += row;
  }
  return csv;
}

std::string closedLoopSpeed() {
  std::string csv = "scenario,cable,simulated,wall,cpu,real_time_factor_cpu\n-,-,s,s,s,-\n";
  std::printf("\n60 s closed loop (30 Hz, exact features)\n%-28s %6s %10s %10s %12s\n", "scenario", "cable", "wall [s]",
              "cpu [s]", "x realtime");
  for (const char* id : {"tether_sim3_moving_leader", "tether_default"})
    for (bool cable : {true, false}) {
      TetherParameters p = builtinParameters(id);
      p.duration = 60.0;
      p.cable_enabled = cable;
      RunContext context;
      const auto start = Clock::now();
      const double cpu0 = maris::bench::processCpuSeconds();
      simulateTether(p, context);
      const double wall = secondsSince(start), cpu = maris::bench::processCpuSeconds() - cpu0;
      std::printf("%-28s %6s %10.3f %10.3f %12.1f\n", id, cable ? "150" : "off", wall, cpu, 60.0 / cpu);
      char row[200];
      std::snprintf(row, sizeof row, "%s,%d,60,%.4f,%.4f,%.1f\n", id, cable ? 150 : 0, wall, cpu, 60.0 / cpu);
      csv += row;
    }
  return csv;
}

std::string cableTimeStep() {
  // Moving-leader run (20 s): max cable-catenary distance, and the largest node distance to the finest-step run
  // over 100 frames (the time-discretisation error of the cable).
  std::string csv = "substeps,time_step,max_deviation_from_catenary,max_difference_to_finest,cpu\n-,s,m,m,s\n";
  std::printf("\ncable time step (tether_sim3_moving_leader, 20 s, 150 links)\n%9s %10s %14s %14s %8s\n", "substeps",
              "dt [s]", "max dev [m]", "vs finest [m]", "cpu [s]");
  TetherParameters p = builtinParameters("tether_sim3_moving_leader");
  p.duration = 20.0;
  p.animation_frames = 100;
  const int finest = 320;
  std::vector<Snapshot> reference;
  for (int substeps : {finest, 12, 20, 40, 80, 160}) {
    p.cable_substeps = substeps;
    RunContext context;
    const double cpu0 = maris::bench::processCpuSeconds();
    double max_dev = 0.0, diff = 0.0;
    std::string status;
    try {
      const SimulationOutput out = simulateTether(p, context);
      for (const auto& t : out.ticks) max_dev = std::max(max_dev, t.cable_deviation);
      if (substeps == finest) reference = out.frames;
      for (std::size_t f = 0; f < out.frames.size(); ++f)
        for (std::size_t i = 0; i < out.frames[f].cable.size(); ++i)
          diff = std::max(diff, (out.frames[f].cable[i] - reference[f].cable[i]).norm());
    } catch (const SolverError& e) {
      status = std::string(" unstable: ") + e.what();
    }
    const double wall = maris::bench::processCpuSeconds() - cpu0;
    const double dt = 1.0 / (p.control_rate * substeps);
    std::printf("%9d %10.2e %14.3e %14.3e %8.3f%s\n", substeps, dt, max_dev, diff, wall, status.c_str());
    char row[200];
    std::snprintf(row, sizeof row, "%d,%.4e,%.4e,%.4e,%.4f\n", substeps, dt, status.empty() ? max_dev : NAN,
                  status.empty() ? diff : NAN, wall);
    csv += row;
  }
  return csv;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "bench-results/tether";
  std::filesystem::create_directories(dir);
  writeFileAtomic(dir / "catenary_solve.csv", catenarySolveTimes());
  writeFileAtomic(dir / "closed_loop_speed.csv", closedLoopSpeed());
  writeFileAtomic(dir / "cable_time_step.csv", cableTimeStep());
  std::printf("\nCSV files written to %s\n", dir.string().c_str());
  return 0;
}
