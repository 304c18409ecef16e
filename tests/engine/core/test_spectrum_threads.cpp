// FFTW plans are made on first use of a length; making one is not thread-safe in FFTW, so core/spectrum.cpp
// guards it. Eight threads transforming lengths no one has planned yet must each get the serial answer.
#include <complex>
#include <thread>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/spectrum.hpp"

namespace maris {
namespace {

using Complex = std::complex<double>;

std::vector<Complex> signal(std::size_t n, int seed) {
  std::vector<Complex> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = Complex(std::sin(0.37 * (j + seed)), std::cos(0.11 * j * seed));
  return x;
}

TEST(SpectrumThreads, ConcurrentFirstUseOfNewLengthsMatchesSerialResults) {
  // Lengths 3001 … 3008 and their real transforms are used nowhere else in this test binary, so every thread
  // creates plans while the others do. Tolerance 0: the same plan on the same data gives the same bits.
  constexpr int kThreads = 8;
  std::vector<std::vector<Complex>> parallel(kThreads), parallel_real(kThreads);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&, i] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        parallel[i] = fft(signal(3001 + i, i));
        const std::vector<Complex> x = signal(5001 + i, i);
        Eigen::VectorXd real(static_cast<Eigen::Index>(x.size()));
        for (std::size_t j = 0; j < x.size(); ++j) real[static_cast<Eigen::Index>(j)] = x[j].real();
        parallel_real[i] = realFft(real);
      }
    });
  for (auto& t : threads) t.join();
  for (int i = 0; i < kThreads; ++i) {
    EXPECT_EQ(parallel[i], fft(signal(3001 + i, i))) << "length " << 3001 + i;
    const std::vector<Complex> x = signal(5001 + i, i);
    Eigen::VectorXd real(static_cast<Eigen::Index>(x.size()));
    for (std::size_t j = 0; j < x.size(); ++j) real[static_cast<Eigen::Index>(j)] = x[j].real();
    EXPECT_EQ(parallel_real[i], realFft(real)) << "real length " << 5001 + i;
  }
}

}  // namespace
}  // namespace maris
