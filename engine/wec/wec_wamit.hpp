// Import of WAMIT frequency-domain output (WAMIT User Manual v7, ch. 4 "Numeric output files"):
//   <stem>.1  added mass and damping:  PER  I  J  Ā(I,J)  B̄(I,J)     Ā = A/(ρL³), B̄ = B/(ρωL³)  (i, j ≤ 3)
//             PER = 0 (or −1 ignored) rows hold the infinite-frequency (zero-frequency) Ā without B̄;
//   <stem>.3  diffraction excitation:  PER  β  I  |X̄|  phase[deg]  Re X̄  Im X̄,  X̄ = X/(ρ g A L²),
//             time factor e^{+iωt} (the scene's convention, no conversion needed).
// PER is the wave period [s] (IPERIN = 1, WAMIT's default). Modes 1 (surge) and 3 (heave) at heading
// β = 0 are read; other modes and headings are ignored.
#pragma once

#include <filesystem>
#include <memory>

#include "wec/wec_hydro.hpp"

namespace maris::wec {

// Reads <stem>.1 and <stem>.3 and dimensionalises with ρ, g and ULEN = length_scale.
// Throws InputError (path "hydro.wamit_stem") naming the file and line of any problem.
std::shared_ptr<TabulatedHydro> readWamit(const std::filesystem::path& stem, double density, double gravity,
                                          double length_scale);

// Converts excitation amplitudes given in the e^{−iωt} convention (Capytaine, NEMOH) in place.
void convertFromEMinusIwt(std::vector<TabulatedHydro::Row>& rows);

}  // namespace maris::wec
