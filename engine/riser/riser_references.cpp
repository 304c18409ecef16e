#include "riser/riser_references.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace maris::riser {
namespace {

using std::numbers::pi;

// ∫_0^L cos(a s) cos(b s) ds and ∫_0^L s cos(a s) cos(b s) ds for a = jπ/L, b = kπ/L (j, k ≥ 1):
// cos·cos = ½[cos((a−b)s) + cos((a+b)s)], ∫_0^L s cos(c s) ds = ((−1)^m − 1)/c² for c = mπ/L ≠ 0, L²/2 for c = 0.
double firstMomentOfCosine(int m, double length) {
  if (m == 0) return length * length / 2;
  const double c = m * pi / length;
  return ((m % 2 == 0 ? 1.0 : -1.0) - 1.0) / (c * c);
}

}  // namespace

double tensionedBeamFrequency(int k, double length, double tension, double mass_per_length, double ei) {
  const double a = k * pi / length;
  return a * std::sqrt(tension / mass_per_length + a * a * ei / mass_per_length);
}

std::vector<double> conveyingPipeFrequencies(const ConveyingPipe& pipe, int modes, int count) {
  const double length = pipe.length;
  const double flux = pipe.fluid_mass_per_length * pipe.flow_speed * pipe.flow_speed;  // M u² [N]
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(modes, modes), g = Eigen::MatrixXd::Zero(modes, modes);
  for (int j = 1; j <= modes; ++j) {
    const double a = j * pi / length;
    for (int c = 1; c <= modes; ++c) {
      const double b = c * pi / length;
      // ∫ (T0 − Mu² − w s) a b cos(a s) cos(b s) ds
      const double plain = j == c ? length / 2 : 0.0;
      const double moment = (firstMomentOfCosine(j - c, length) + firstMomentOfCosine(j + c, length)) / 2;
      k(j - 1, c - 1) = a * b * ((pipe.top_tension - flux) * plain - pipe.weight_per_length * moment);
      if ((j + c) % 2 == 1) g(j - 1, c - 1) = 2 * pipe.fluid_mass_per_length * pipe.flow_speed * 2.0 * j * c / (j * j - c * c);
    }
    k(j - 1, j - 1) += length / 2 * pipe.ei * std::pow(a, 4);
  }
  const double mass = pipe.mass_per_length * length / 2;
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(2 * modes, 2 * modes);
  s.topRightCorner(modes, modes).setIdentity();
  s.bottomLeftCorner(modes, modes) = -k / mass;
  s.bottomRightCorner(modes, modes) = -g / mass;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(s, false);
  std::vector<double> w;
  for (Eigen::Index c = 0; c < 2 * modes; ++c) {
    const std::complex<double> lambda = eig.eigenvalues()[c];
    if (lambda.imag() > 0 && std::abs(lambda.real()) <= 1e-7 * std::abs(lambda)) w.push_back(lambda.imag());
  }
  std::sort(w.begin(), w.end());
  if (static_cast<int>(w.size()) > count) w.resize(count);
  return w;
}

}  // namespace maris::riser
