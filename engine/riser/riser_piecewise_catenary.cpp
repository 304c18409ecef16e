// Piecewise cable catenary start (contract in riser/riser_piecewise_catenary.hpp).
#include "riser/riser_piecewise_catenary.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace maris::riser {
namespace {

struct Piece {
  double start, end, weight;  // [m], [m], [N/m] submerged
};

// Horizontal reach and drop (downward) of one piece of constant weight w and length l, V0 at its upper end.
Eigen::Vector2d pieceStep(double h, double v0, double w, double l) {
  const double v1 = v0 - w * l, t0 = std::hypot(h, v0), t1 = std::hypot(h, v1);
  // Nearly weightless (or neutral) piece: the closed form cancels; it is straight along the tangent at its top.
  if (std::abs(w) * l <= 1e-9 * t0) return {l * h / t0, l * v0 / t0};
  return {h / w * (std::asinh(v0 / h) - std::asinh(v1 / h)), (t0 - t1) / w};
}

// ∫ w z ds over that piece (z downward drop, z0 at its upper end): w z0 l + T0 l − ∫T ds, with
// ∫T ds = [V √(H² + V²) + H² asinh(V/H)] from V1 to V0 over 2w (pieces merge over hundreds of metres, where the
// trapezoid of the end drops would pick the wrong root); the trapezoid, exact there, for a straight piece.
double pieceEnergy(double h, double v0, double w, double l, double z0, double dz) {
  const double v1 = v0 - w * l, t0 = std::hypot(h, v0);
  if (std::abs(w) * l <= 1e-9 * t0) return w * l * (z0 + 0.5 * dz);
  const auto f = [&](double v) { return v * std::hypot(h, v) + h * h * std::asinh(v / h); };
  return w * z0 * l + t0 * l - (f(v0) - f(v1)) / (2 * w);
}

class CableLine {
 public:
  CableLine(const std::vector<Segment>& segments) {
    // Neighbours of the same weight form one piece (the same catenary): a few pieces at any n, so the scans below
    // cost the same at n = 1000 as at n = 20.
    for (const Segment& s : segments) {
      const double w = s.weight_per_length - s.buoyancy_per_length;
      if (!pieces_.empty() && pieces_.back().weight == w)
        pieces_.back().end = s.arc_start + s.length;
      else
        pieces_.push_back({s.arc_start, s.arc_start + s.length, w});
      scale_ += std::abs(w) * s.length;
    }
    scale_ = std::max(scale_, 1e-12);
  }

  double scale() const { return scale_; }  // [N] Σ |w| l

  // Submerged weight from the top to s.
  double weightTo(double s) const {
    double w = 0.0;
    for (const Piece& p : pieces_) w += p.weight * std::max(0.0, std::min(s, p.end) - p.start);
    return w;
  }

  // End point (reach, drop) of the line suspended from 0 to `end`; with `samples`, also the points at those
  // arc lengths (beyond `end`: straight on, level with the end, the grounded part) and the potential energy
  // −Σ w l z̄ of all of it in `energy`.
  Eigen::Vector2d shape(double h, double v_top, double end, const std::vector<double>* samples = nullptr,
                        std::vector<Eigen::Vector2d>* points = nullptr, double* energy = nullptr) const {
    Eigen::Vector2d at = Eigen::Vector2d::Zero();
    double v = v_top, e = 0.0;
    std::size_t k = 0;
    for (const Piece& p : pieces_) {
      const double stop = std::min(p.end, end);
      if (stop <= p.start) break;
      while (samples && k < samples->size() && (*samples)[k] <= stop) {
        points->push_back(at + pieceStep(h, v, p.weight, (*samples)[k] - p.start));
        ++k;
      }
      const Eigen::Vector2d step = pieceStep(h, v, p.weight, stop - p.start);
      if (energy) e += pieceEnergy(h, v, p.weight, stop - p.start, at.y(), step.y());
      at += step;
      v -= p.weight * (stop - p.start);
    }
    if (samples) {
      for (const Piece& p : pieces_)
        if (p.end > end) e += p.weight * (p.end - std::max(p.start, end)) * at.y();
      for (; k < samples->size(); ++k) points->push_back(at + Eigen::Vector2d((*samples)[k] - end, 0.0));
    }
    if (energy) *energy = -e;  // drops are downward: height is −drop
    return at;
  }

  // H giving the reach `reach` of the line suspended to `end` (the reach grows with H); NaN if out of range.
  double horizontalTensionFor(double v_top, double end, double reach) const {
    double lo = 1e-12 * scale_, hi = 1e12 * scale_;
    if (!(shape(lo, v_top, end).x() < reach && shape(hi, v_top, end).x() > reach))
      return std::numeric_limits<double>::quiet_NaN();
    for (int it = 0; it < 64; ++it) {
      const double mid = std::sqrt(lo * hi);
      (shape(mid, v_top, end).x() < reach ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
  }

 private:
  std::vector<Piece> pieces_;
  double scale_ = 0.0;
};

// Roots of g over [a, b]: a scan of `count` intervals, bisection in each that changes sign (NaN: undefined).
std::vector<double> rootsOf(const std::function<double(double)>& g, double a, double b, int count) {
  std::vector<double> roots;
  double x0 = a, g0 = g(a);
  for (int k = 1; k <= count; ++k) {
    const double x1 = a + (b - a) * k / count, g1 = g(x1);
    if (std::isfinite(g0) && std::isfinite(g1) && (g0 < 0) != (g1 < 0)) {
      double lo = x0, hi = x1, glo = g0;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi), gm = g(mid);
        if (!std::isfinite(gm)) break;
        if ((gm < 0) == (glo < 0)) {
          lo = mid;
          glo = gm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(0.5 * (lo + hi));
    }
    x0 = x1;
    g0 = g1;
  }
  return roots;
}

}  // namespace

bool submergedWeightVaries(const std::vector<Segment>& segments) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Segment& s : segments) {
    lo = std::min(lo, s.weight_per_length - s.buoyancy_per_length);
    hi = std::max(hi, s.weight_per_length - s.buoyancy_per_length);
  }
  return hi - lo > 1e-9 * std::max(std::abs(lo), std::abs(hi));
}

std::optional<PiecewiseCatenary> piecewiseCatenary(const std::vector<Segment>& segments, const RiserSeabed* bed,
                                                   const Eigen::Vector3d& top, const Eigen::Vector3d& anchor,
                                                   double length, const std::vector<double>& arc_lengths) {
  Eigen::Vector3d across = anchor - top;
  across.z() = 0;
  const double span = across.norm(), drop = top.z() - anchor.z();
  if (segments.empty() || span <= 1e-9 * length || (anchor - top).norm() >= length) return std::nullopt;
  const Eigen::Vector3d e = across / span;
  const CableLine line(segments);
  constexpr int kScan = 400;
  const double tolerance = 1e-6 * length;  // the line may touch the bed's level, not pass below it

  struct Candidate {
    double h, v_top, end;
  };
  std::vector<Candidate> candidates;
  // Grounded: touchdown s_td in (L − span, L], V_top = W(s_td) > 0, the rest straight on the bed to the anchor.
  const bool grounded = bed && drop > 0 && std::abs(bed->penetration(anchor, 0.0)) <= 0.05 * drop;
  if (grounded) {
    const auto mismatch = [&](double s) {
      const double v_top = line.weightTo(s);
      if (!(v_top > 0)) return std::numeric_limits<double>::quiet_NaN();
      const double h = line.horizontalTensionFor(v_top, s, span - (length - s));
      return std::isfinite(h) ? line.shape(h, v_top, s).y() - drop : h;
    };
    for (double s : rootsOf(mismatch, length - span, length, kScan)) {
      const double v_top = line.weightTo(s);
      candidates.push_back({line.horizontalTensionFor(v_top, s, span - (length - s)), v_top, s});
    }
  }
  // Fully suspended: V_top = scale · sinh t.
  const auto vertical = [&](double t) { return line.scale() * std::sinh(t); };
  const auto suspended = [&](double t) {
    const double h = line.horizontalTensionFor(vertical(t), length, span);
    return std::isfinite(h) ? line.shape(h, vertical(t), length).y() - drop : h;
  };
  for (double t : rootsOf(suspended, -10.0, 10.0, kScan))
    candidates.push_back({line.horizontalTensionFor(vertical(t), length, span), vertical(t), length});

  std::optional<PiecewiseCatenary> best;
  double least = std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) {
    if (!std::isfinite(c.h)) continue;
    std::vector<Eigen::Vector2d> plane;
    double energy = 0.0;
    line.shape(c.h, c.v_top, c.end, &arc_lengths, &plane, &energy);
    const bool buried = bed && std::any_of(plane.begin(), plane.end(), [&](const Eigen::Vector2d& p) {
                          return grounded && p.y() > drop + tolerance;
                        });
    if (buried || plane.size() != arc_lengths.size() || !(energy < least)) continue;
    least = energy;
    PiecewiseCatenary out{c.h, c.v_top, c.end, {}};
    for (const Eigen::Vector2d& p : plane) out.points.push_back(top + p.x() * e - p.y() * Eigen::Vector3d::UnitZ());
    best = std::move(out);
  }
  return best;
}

}  // namespace maris::riser
