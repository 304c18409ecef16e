// Stateless catenary functions for a tether hanging between two attachment points in a vertical plane.
//
// Conventions (used by the whole tether scene):
//   - the tether plane is vertical; x is horizontal from the follower attachment P2 towards the leader
//     attachment P1, z is up. Heights are positive up.
//   - S  [m]  horizontal span between P2 and P1 (S >= 0);
//     dH [m]  rise dH = z(P1) - z(P2) (the paper's ΔH₂);
//     H  [m]  sag: height of P2 above the lowest point of the catenary (the paper's H₂);
//     L  [m]  tether length (inextensible);
//     C  [1/m] catenary constant: z = (cosh(C (x - x0)) - 1)/C above the vertex at x0.
//   - Source: Laranjeira, Dune & Hugel, Ocean Eng. 200 (2020) 107018, eqs. (1)-(7) and App. A.4; eq. 2's '+' root
//     (the sign is lost in the available text) is the one with L² − ΔH² = (2 sinh(CS/2)/C)², as tested.
//
// No function returns NaN: every input is classified into a named regime (CatenaryRegime). Geometry fields are
// filled whenever a catenary exists (Regular, NearlyTaut, VertexOutsideSpan) and for the VerticalHang limit.
#pragma once

#include <string>

namespace maris::tether {

enum class CatenaryRegime {
  Regular,            // a catenary with its lowest point between the attachment points
  NearlyTaut,         // as Regular, but the shape is ill-conditioned in the span (see condition_number)
  VertexOutsideSpan,  // the extended catenary's vertex lies beyond an attachment point: the paper's (H, dH) model
                      // with H >= 0 and H + dH >= 0 does not describe the tether (geometry still valid)
  VerticalHang,       // S -> 0: both halves hang vertically, C -> infinity, horizontal tension -> 0
  Overstretched,      // chord sqrt(S^2 + dH^2) >= L (or H = dH = 0): an inextensible tether cannot span it
  Degenerate,         // shape input with 2H + dH >= L (ends and vertex on one vertical) or H, dH out of domain
};

const char* toString(CatenaryRegime regime);

// A solved catenary in the tether plane. Written by catenaryFromShape / catenaryFromSpan.
struct Catenary {
  CatenaryRegime regime = CatenaryRegime::Degenerate;
  std::string message;          // why the regime applies, with the numbers (empty for Regular)
  double length = 0.0;          // [m] L
  double span = 0.0;            // [m] S, horizontal distance P2 -> P1
  double rise = 0.0;            // [m] dH = z(P1) - z(P2)
  double constant = 0.0;        // [1/m] C (+infinity only in VerticalHang)
  double inverse_constant = 0;  // [m] 1/C = horizontal tension / wet weight per length (0 in VerticalHang)
  double vertex_offset = 0.0;   // [m] x0: horizontal distance from P2 to the vertex (outside [0, S] if
                                //     VertexOutsideSpan)
  double sag = 0.0;             // [m] H = height of P2 above the vertex
  double condition_number = 1;  // [-] estimate of |d ln H / d ln S| (~ S/(q - S), q = sqrt(L^2 - dH^2))
  int iterations = 0;           // Newton (+ bisection) iterations of the span solve (0 for the shape route)
  bool has_geometry = false;    // true when the fields above describe a hanging tether (points, tensions)

  bool fitsPaperModel() const { return regime == CatenaryRegime::Regular || regime == CatenaryRegime::NearlyTaut; }
  double leaderSag() const { return sag + rise; }                 // [m] H1 = H + dH
  double leaderVertexDistance() const { return span - vertex_offset; }  // [m] D + ΔD of the paper
};

// Catenary constant C(H, dH, L) of eq. (2) with the '+' root, evaluated without cancellation
// (L^2 - x^2 as (L - x)(L + x)). Returns +infinity when 2H + dH >= L, 0 when H = dH = 0.
// Precondition: H >= 0, H + dH >= 0, |dH| < L.
double catenaryConstant(double sag, double rise, double length);

// Partial derivatives of C with respect to H and dH (App. A.4 of the paper) [1/m^2]. Precondition: H > 0,
// H + dH > 0, 2H + dH < L.
struct CatenaryConstantGradient {
  double d_sag = 0.0;   // ∂C/∂H
  double d_rise = 0.0;  // ∂C/∂dH
};
CatenaryConstantGradient catenaryConstantGradient(double sag, double rise, double length);

// The catenary of given sag H, rise dH and length L: C from eq. (2), horizontal distances from the vertex
// D = asinh(sqrt(CH(CH + 2)))/C (cancellation-free form of eq. 7), span S = D2 + D1.
// Regimes: Degenerate if L <= 0, H < 0, H + dH < 0 or 2H + dH >= L; Overstretched if H = dH = 0.
Catenary catenaryFromShape(double sag, double rise, double length);

// The catenary through two attachment points given by the horizontal span S >= 0, rise dH and length L
// (the forward problem). Solves sinh(xi) = r xi, r = sqrt(L^2 - dH^2)/S, xi = C S/2, by Newton on the
// convex form ln(sinh xi / xi) = ln r (<= 8 iterations for r - 1 in [1e-14, 1e12]) with a bracketing
// bisection fallback; then x0 = S/2 - atanh(dH/L)/C and H = 2 sinh^2(C x0/2)/C.
// Regimes: Overstretched (chord >= L), VerticalHang (S <= 1e-14 L: limit H = (L - dH)/2, 1/C = 0),
// VertexOutsideSpan (|dH| > L tanh xi), NearlyTaut (condition_number > 1e6), else Regular.
Catenary catenaryFromSpan(double span, double rise, double length);

// A point of the tether at arc length sigma from P2 (0 <= sigma <= L), in the tether plane relative to P2.
struct PlanePoint {
  double x = 0.0;  // [m] horizontal, towards P1
  double z = 0.0;  // [m] up
};
PlanePoint catenaryPointAtArcLength(const Catenary& c, double arc_length);

// Tension [N] at arc length sigma from P2 for wet weight w [N/m]: T = (w/C) cosh(C (x - x0)) (standard catenary
// statics). VerticalHang limit: T = w |sigma - H| (the weight of the tether between the point and the bottom).
double catenaryTension(const Catenary& c, double wet_weight_per_length, double arc_length);

// Slope angles of the tether to the horizontal at the ends [rad], atan(dz/dx) = atan(sinh(C (x - x0))) with x
// increasing from P2 to P1. VerticalHang: -pi/2 at P2 and +pi/2 at P1.
struct EndAngles {
  double at_follower = 0.0;  // [rad] atan(dz/dx) at P2 (negative when the tether leaves P2 downwards)
  double at_leader = 0.0;    // [rad] atan(dz/dx) at P1 (positive when the tether arrives at P1 upwards)
};
EndAngles catenaryEndAngles(const Catenary& c);

}  // namespace maris::tether
