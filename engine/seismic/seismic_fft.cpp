#include "seismic/seismic_fft.hpp"

#include <cassert>
#include <cmath>
#include <numbers>
#include <utility>

namespace maris::seismic {

std::size_t nextPowerOfTwo(std::size_t n) {
  std::size_t p = 1;
  while (p < n) p <<= 1;
  return p;
}

void fftInPlace(std::vector<std::complex<double>>& data, int sign) {
  const std::size_t n = data.size();
  assert(n > 0 && (n & (n - 1)) == 0);
  // Bit-reversal permutation.
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(data[i], data[j]);
  }
  // Butterflies; twiddles from a direct cos/sin per stage entry keep the round-off at O(eps log N).
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double angle = sign * 2.0 * std::numbers::pi / static_cast<double>(len);
    const std::size_t half = len / 2;
    std::vector<std::complex<double>> twiddle(half);
    for (std::size_t k = 0; k < half; ++k) twiddle[k] = std::polar(1.0, angle * static_cast<double>(k));
    for (std::size_t start = 0; start < n; start += len) {
      for (std::size_t k = 0; k < half; ++k) {
        const std::complex<double> a = data[start + k];
        const std::complex<double> b = data[start + k + half] * twiddle[k];
        data[start + k] = a + b;
        data[start + k + half] = a - b;
      }
    }
  }
}

}  // namespace maris::seismic
