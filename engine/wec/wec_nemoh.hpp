// Import of Nemoh frequency-domain output (postProcessor "Tecplot" files, Nemoh v2 and v3; Capytaine writes the
// same files with capytaine.io.legacy.write_dataset_as_tecplot_files):
//   RadiationCoefficients.tec  one zone per radiating DoF, title "Motion of body <b> in DoF <i>", rows
//                              w  A(1) B(1)  A(2) B(2) ... over all 6·N_bodies force DoFs; A [kg], B [N·s/m]
//   ExcitationForce.tec        one zone per heading, title "Diffraction force - beta = <deg> deg" (Nemoh's name
//                              for the total excitation), rows  w  |F(1)| angle(F(1))  |F(2)| angle(F(2)) ...,
//                              |F| [N/m], angle [rad]
// Coefficients are dimensional; the frequency column is ω [rad/s] unless the VARIABLES line names "(Hz)" or a
// period "(s)". Nemoh and Capytaine use the e^{−iωt} time factor: amplitudes are conjugated on import into the
// scene's e^{+iωt} convention (wec_hydro.hpp). DoFs 1 (surge) and 3 (heave) of every body and heading 0 are read;
// with N bodies a row holds 6N (A, B) pairs, body-major, and the result is a CoupledHydro (one float per body).
//
// Nemoh does not write A∞, so it is recovered from the finite-frequency table by Ogilvie's relation
// (wec_radiation.hpp), averaged over the table band; the spread of the estimate is returned as its error.
#pragma once

#include <filesystem>
#include <memory>

#include "wec/wec_coupled.hpp"
#include "wec/wec_hydro.hpp"

namespace maris::wec {

struct NemohImport {
  std::shared_ptr<TabulatedHydro> hydro;   // one body in the files
  std::shared_ptr<CoupledHydro> coupled;   // several bodies: surge/heave of all, with the interaction
  double a_inf_spread_surge = 0.0;  // [kg] max − min of the Ogilvie estimates over the band
  double a_inf_spread_heave = 0.0;  // [kg]
};

// Reads <directory>/RadiationCoefficients.tec and <directory>/ExcitationForce.tec.
// Throws InputError (path "hydro.nemoh_directory") naming the file and line of any problem.
NemohImport readNemoh(const std::filesystem::path& directory);

}  // namespace maris::wec
