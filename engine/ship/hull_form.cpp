#include "ship/hull_form.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Geometry>

#include "core/monotone_cubic.hpp"

namespace maris::ship {

namespace {

// Composite Simpson weights for n (odd) equally spaced nodes with spacing h.
Eigen::VectorXd simpsonWeights(int n, double h) {
  assert(n >= 3 && n % 2 == 1);
  Eigen::VectorXd w(n);
  for (int i = 0; i < n; ++i) w[i] = (i == 0 || i == n - 1) ? 1.0 : (i % 2 ? 4.0 : 2.0);
  return w * (h / 3.0);
}

double triangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace

HullGrid HullGrid::coarsened() const {
  assert(nx() % 2 == 1 && nz() % 2 == 1);
  HullGrid c;
  c.x_aft = x_aft;
  c.dx = 2.0 * dx;
  c.dz = 2.0 * dz;
  c.convergence_order = convergence_order;
  c.half_breadth.resize((nx() + 1) / 2, (nz() + 1) / 2);
  for (int i = 0; i < c.nx(); ++i)
    for (int j = 0; j < c.nz(); ++j) c.half_breadth(i, j) = half_breadth(2 * i, 2 * j);
  return c;
}

HullGrid HullGrid::reversed() const {
  HullGrid r = *this;
  r.half_breadth = half_breadth.colwise().reverse();
  return r;
}

HullForm makeParametricHull(double length, double beam, double draft, double waterline_exponent,
                            double section_exponent) {
  HullForm h;
  h.kind = HullForm::Kind::Parametric;
  h.name = (waterline_exponent == 2.0 && section_exponent == 2.0) ? "Wigley" : "parametric";
  h.length_pp = length;
  h.beam = beam;
  h.draft = draft;
  h.waterline_exponent = waterline_exponent;
  h.section_exponent = section_exponent;
  return h;
}

HullForm makeOffsetsHull(std::string name, OffsetsTable table, double length_pp, double scale) {
  HullForm h;
  h.kind = HullForm::Kind::Offsets;
  h.name = std::move(name);
  h.length_pp = length_pp * scale;
  h.offsets = scale == 1.0 ? std::move(table) : scaledOffsets(table, scale);
  return h;
}

HullGrid sampleHull(const HullForm& hull, int nx, int nz) {
  assert(nx >= 3 && nz >= 3 && nx % 2 == 1 && nz % 2 == 1);
  HullGrid g;
  g.half_breadth.resize(nx, nz);
  g.convergence_order = hull.kind == HullForm::Kind::Parametric ? 2.0 : 1.0;
  if (hull.kind == HullForm::Kind::Parametric) {
    const double L = hull.length_pp;
    g.x_aft = 0.0;
    g.dx = L / (nx - 1);
    g.dz = hull.draft / (nz - 1);
    for (int i = 0; i < nx; ++i) {
      const double xi = std::abs(2.0 * g.x(i) / L - 1.0);
      const double fx = std::max(0.0, 1.0 - std::pow(xi, hull.waterline_exponent));
      for (int j = 0; j < nz; ++j) {
        const double fz = std::max(0.0, 1.0 - std::pow(std::abs(g.z(j)) / hull.draft, hull.section_exponent));
        g.half_breadth(i, j) = 0.5 * hull.beam * fx * fz;
      }
    }
    return g;
  }
  // Offsets: monotone cubic in z along every station, then in x along every sampled waterline.
  const auto& st = hull.offsets.stations;
  const double depth = -hull.offsets.deepest();
  g.x_aft = st.front().x;
  g.dx = (st.back().x - st.front().x) / (nx - 1);
  g.dz = depth / (nz - 1);
  Eigen::MatrixXd by_station(st.size(), nz);
  for (std::size_t s = 0; s < st.size(); ++s) {
    const MonotoneCubic section(st[s].z, st[s].half_breadth);
    for (int j = 0; j < nz; ++j) by_station(s, j) = section.valueOr(j == nz - 1 ? -depth : g.z(j), 0.0);
  }
  std::vector<double> xs(st.size());
  for (std::size_t s = 0; s < st.size(); ++s) xs[s] = st[s].x;
  for (int j = 0; j < nz; ++j) {
    std::vector<double> ys(by_station.rows());
    for (Eigen::Index s = 0; s < by_station.rows(); ++s) ys[s] = by_station(s, j);
    const MonotoneCubic waterline(xs, ys);
    for (int i = 0; i < nx; ++i)
      g.half_breadth(i, j) = std::max(0.0, waterline.valueOr(i == nx - 1 ? xs.back() : g.x(i), 0.0));
  }
  return g;
}

// The moulded draft: the deepest keel point of the stations in the middle half of Lpp (so that a sonar dome
// or a bulb below the baseline does not count). A station whose bottom row still has breadth reaches the
// grid's depth; otherwise its keel lies between its last wet row and the next one, found by extending the
// last two wet half-breadths linearly to zero (exact for a V keel such as the Wigley hull's, error < dz for
// a flat bottom lying between two rows).
double designDraft(const HullGrid& g, double length_pp) {
  double draft = 0.0;
  bool any = false;
  for (int i = 0; i < g.nx(); ++i) {
    if (g.x(i) < 0.25 * length_pp || g.x(i) > 0.75 * length_pp) continue;
    int last_wet = -1;
    for (int j = 0; j < g.nz(); ++j)
      if (g.half_breadth(i, j) > 0.0) last_wet = j;
    if (last_wet < 0) continue;
    any = true;
    double keel = g.depth();
    if (last_wet < g.nz() - 1) {
      const double y = g.half_breadth(i, last_wet);
      const double drop = last_wet > 0 ? g.half_breadth(i, last_wet - 1) - y : 0.0;
      const double extension = drop > y ? g.dz * y / drop : g.dz;  // linear extension, at most one row
      keel = -g.z(last_wet) + extension;
    }
    draft = std::max(draft, keel);
  }
  return any ? draft : g.depth();  // a hull without a middle body (or a tiny grid): the deepest point
}

HullParticulars computeParticulars(const HullGrid& g, double length_pp) {
  HullParticulars p;
  const int nx = g.nx(), nz = g.nz();
  const Eigen::VectorXd wx = simpsonWeights(nx, g.dx), wz = simpsonWeights(nz, g.dz);
  const Eigen::MatrixXd& Y = g.half_breadth;
  p.length_pp = length_pp;
  p.max_depth = g.depth();
  p.draft = designDraft(g, length_pp);

  // Sections: area and vertical moment; then volume, LCB and KB.
  const Eigen::VectorXd section_area = 2.0 * Y * wz;
  Eigen::VectorXd zs(nz);
  for (int j = 0; j < nz; ++j) zs[j] = g.z(j);
  const Eigen::VectorXd section_moment = 2.0 * Y * wz.cwiseProduct(zs);
  p.volume = wx.dot(section_area);
  Eigen::VectorXd xs(nx);
  for (int i = 0; i < nx; ++i) xs[i] = g.x(i);
  p.lcb_from_ap = p.volume > 0 ? wx.cwiseProduct(xs).dot(section_area) / p.volume : 0.0;
  p.lcb_percent = 100.0 * (p.lcb_from_ap - 0.5 * length_pp) / length_pp;
  // KB above the keel of the midship part (the baseline), so that KB = T − depth of the centroid.
  p.kb = p.volume > 0 ? wx.dot(section_moment) / p.volume + p.draft : 0.0;
  p.max_section_area = section_area.maxCoeff();

  // Waterplane: area, breadth and the extent of Y(x, 0) > 0.
  const Eigen::VectorXd wl = Y.col(0);
  p.waterplane_area = 2.0 * wx.dot(wl);
  p.beam_wl = 2.0 * wl.maxCoeff();
  int first = -1, last = -1;
  for (int i = 0; i < nx; ++i)
    if (wl[i] > 0.0) {
      if (first < 0) first = i;
      last = i;
    }
  if (first >= 0) p.length_wl = g.x(std::min(last + 1, nx - 1)) - g.x(std::max(first - 1, 0));

  p.block_coefficient = p.volume / (length_pp * p.beam_wl * p.draft);
  p.prismatic_coefficient = p.volume / (p.max_section_area * length_pp);
  p.midship_coefficient = p.max_section_area / (p.beam_wl * p.draft);
  p.waterplane_coefficient = p.waterplane_area / (length_pp * p.beam_wl);

  // Wetted surface: the grid surface (x, Y, z) as triangles, skipping those lying in the centre plane, plus
  // the flat of bottom under the deepest waterline; times two sides. Transom faces are dry (not counted).
  double side = 0.0;
  auto P = [&](int i, int j) { return Eigen::Vector3d(g.x(i), Y(i, j), g.z(j)); };
  for (int i = 0; i + 1 < nx; ++i)
    for (int j = 0; j + 1 < nz; ++j) {
      const bool y00 = Y(i, j) > 0, y10 = Y(i + 1, j) > 0, y01 = Y(i, j + 1) > 0, y11 = Y(i + 1, j + 1) > 0;
      if (y00 || y10 || y11) side += triangleArea(P(i, j), P(i + 1, j), P(i + 1, j + 1));
      if (y00 || y11 || y01) side += triangleArea(P(i, j), P(i + 1, j + 1), P(i, j + 1));
    }
  for (int i = 0; i + 1 < nx; ++i) side += 0.5 * g.dx * (Y(i, nz - 1) + Y(i + 1, nz - 1));
  p.wetted_surface = 2.0 * side;

  // Transom (aft end section) and bulb (section at the FP when the body extends forward of it).
  p.transom_area = section_area[0];
  const double x_end = g.x(nx - 1);
  if (x_end > length_pp + 1e-9 * length_pp && length_pp >= g.x_aft) {
    const double s = (length_pp - g.x_aft) / g.dx;
    const int i = std::min(static_cast<int>(s), nx - 2);
    const double t = s - i;
    p.bulb_area = (1 - t) * section_area[i] + t * section_area[i + 1];
    const double moment = (1 - t) * section_moment[i] + t * section_moment[i + 1];
    if (p.bulb_area > 0) p.bulb_centre_height = moment / p.bulb_area + p.draft;
  }
  return p;
}

ForeShoulder foreShoulder(const HullGrid& g, double shoulder_distance) {
  const Eigen::VectorXd wl = g.half_breadth.col(0);
  const double ymax = wl.maxCoeff();
  int bow = -1;
  for (int i = g.nx() - 1; i >= 0 && bow < 0; --i)
    if (wl[i] > 0.0) bow = std::min(i + 1, g.nx() - 1);
  ForeShoulder fs;
  if (bow < 0) return fs;
  for (int i = bow; i > 0; --i) {
    if (shoulder_distance > 0) {
      // A given shoulder: the last step is cut where it reaches the distance (the waterline is linear on it).
      const double step = std::min(g.dx, shoulder_distance - fs.distance);
      fs.arc_length += std::hypot(step, (wl[i] - wl[i - 1]) * step / g.dx);
      fs.distance += step;
      if (fs.distance >= shoulder_distance * (1.0 - 1e-12)) break;
      continue;
    }
    // Walk aft from the bow until the waterline reaches its maximum (within 1e-6: a parallel middle body
    // interpolated from equal offsets is flat to round-off).
    fs.arc_length += std::hypot(g.dx, wl[i] - wl[i - 1]);
    fs.distance += g.dx;
    if (wl[i - 1] >= ymax * (1.0 - 1e-6)) break;
  }
  return fs;
}

}  // namespace maris::ship
