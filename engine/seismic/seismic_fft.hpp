// Radix-2 complex FFT used by the free-field synthesis. Temporary: engine/core/spectrum.hpp (numerics
// helper) was not on main when this scene was written; replace this when core offers a complex FFT.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace maris::seismic {

// In place, unscaled: X[k] = Σ_n x[n]·exp(sign·2πi·k·n/N), sign = −1 or +1. N must be a power of two.
void fftInPlace(std::vector<std::complex<double>>& data, int sign);

// Smallest power of two ≥ n (n ≥ 1).
std::size_t nextPowerOfTwo(std::size_t n);

}  // namespace maris::seismic
