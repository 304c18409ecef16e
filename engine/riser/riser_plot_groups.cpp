#include "riser/riser_plot_groups.hpp"

namespace maris::riser {

// The names are those of riser_results.cpp, riser_envelope.cpp, riser_fatigue.cpp, riser_seabed.cpp,
// riser_frequency_sweep.cpp and riser_stress_convergence.cpp; test_riser_plot_groups runs the built-in scenarios
// and checks that every plot falls in one group and every name still names a plot.
std::vector<PlotGroupSpec> riserPlotGroups() {
  return {
      {"Over time at the probes", {"probe*_displacement", "probe_stress"}},
      {"Over time at the ends: top reaction, energy, waves, touchdown",
       {"top_force", "energy", "wave_elevation", "touchdown"}},
      {"Along the riser: envelopes, profiles, fatigue", {"envelope_*", "profile*", "fatigue_life"}},
      {"Frequencies and convergence", {"frequency_*", "bending_stress_*"}},
  };
}

}  // namespace maris::riser
