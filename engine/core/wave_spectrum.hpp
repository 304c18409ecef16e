// One-directional sea-state spectra S(ω) [m²·s/rad] (one-sided, ω in rad/s): Pierson–Moskowitz and
// JONSWAP in terms of (Hs, Tp), or a user table, and their spectral moments m_n = ∫ ω^n S(ω) dω.
//
// Pierson–Moskowitz (DNV-RP-C205, 2010, eq. 3.5.5.1):
//   S_PM(ω) = (5/16) Hs² ω_p⁴ ω⁻⁵ exp(−(5/4)(ω_p/ω)⁴),  ω_p = 2π/Tp;  m0 = Hs²/16 exactly.
// JONSWAP (Hasselmann et al. 1973; DNV-RP-C205 eq. 3.5.5.4) with σ = 0.07 (ω ≤ ω_p), 0.09 (ω > ω_p):
//   S_J(ω) = A_γ S_PM(ω) γ^{exp(−(ω − ω_p)²/(2σ²ω_p²))}.
// A_γ is computed here by quadrature so that m0 = Hs²/16 holds to ~1e-12 (DNV's closed approximation
// A_γ ≈ 1 − 0.287 ln γ is within 0.25 % of it for 1 ≤ γ ≤ 5, 1.8 % at γ = 7; tested).
#pragma once

#include <string>
#include <vector>

namespace maris::ocean {

enum class SpectrumKind { PiersonMoskowitz, Jonswap, Table };

struct WaveSpectrum {
  SpectrumKind kind = SpectrumKind::PiersonMoskowitz;
  double significant_height = 0.0;  // [m] Hs (analytic kinds)
  double peak_period = 0.0;         // [s] Tp (analytic kinds)
  double peak_enhancement = 1.0;    // [-] JONSWAP γ
  double normalisation = 1.0;       // [-] A_γ (1 for Pierson–Moskowitz)
  std::vector<double> table_omega;  // [rad/s] strictly increasing (Table)
  std::vector<double> table_density;  // [m²·s/rad] ≥ 0, linear between points, zero outside (Table)

  double density(double omega) const;  // [m²·s/rad]
  // Frequency band that the discretisation covers [rad/s]: [0.5, 6]·ω_p for the analytic kinds (outside it
  // lies 1e-3·m0 or less: the PM tail above 6ω_p holds 1 − exp(−1.25/6⁴) = 9.6e-4), the table's range otherwise.
  double bandLow() const;
  double bandHigh() const;
  std::string name() const;
};

// Throw std::invalid_argument naming the quantity when Hs ≤ 0, Tp ≤ 0, γ < 1, or a table is not increasing,
// has fewer than 2 points, or a negative density.
WaveSpectrum piersonMoskowitz(double significant_height, double peak_period);
WaveSpectrum jonswap(double significant_height, double peak_period, double peak_enhancement);
WaveSpectrum spectrumTable(std::vector<double> omega, std::vector<double> density);

// m_n = ∫_0^∞ ω^n S(ω) dω for n = 0 … 4 (n = 4 is infinite for PM/JONSWAP; not allowed for them).
// Analytic kinds: Gauss–Legendre in u = ω_p/ω over u ∈ (0, 4] where the integrand is smooth (relative error
// ~1e-13); table: exact for the piecewise-linear density.
double spectralMoment(const WaveSpectrum& spectrum, int order);
// ∫ S(ω) dω over [a, b] (same quadratures).
double bandVariance(const WaveSpectrum& spectrum, double a, double b);

}  // namespace maris::ocean
