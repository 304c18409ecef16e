#include "plots/plot_axes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <qcustomplot.h>

#include "plots/display_units.hpp"

namespace maris::ui {

double displayMagnitude(const Column& column) {
  double largest = 0.0;
  for (double v : column.values)
    if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  return largest * std::abs(displayUnit(column.unit).factor);
}

AxisSplit splitByMagnitude(const Table& table, const std::vector<std::string>& y, double ratio) {
  double largest = 0.0;
  for (const auto& name : y)
    if (const Column* c = table.find(name)) largest = std::max(largest, displayMagnitude(*c));
  AxisSplit split;
  for (const auto& name : y) {
    const Column* c = table.find(name);
    const double size = c ? displayMagnitude(*c) : 0.0;
    (size > 0.0 && size * ratio < largest ? split.right : split.left).push_back(name);
  }
  return split;
}

std::vector<std::vector<std::string>> magnitudeTiers(const Table& table, const std::vector<std::string>& y,
                                                     double ratio) {
  std::vector<std::pair<double, std::size_t>> sized;  // (size, position in y), largest first
  for (std::size_t i = 0; i < y.size(); ++i) {
    const Column* c = table.find(y[i]);
    sized.emplace_back(c ? displayMagnitude(*c) : 0.0, i);
  }
  std::stable_sort(sized.begin(), sized.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::size_t> tier_of(y.size(), 0);
  double tier_largest = 0.0;  // the size of the current tier's largest column
  std::size_t tier = 0;
  for (const auto& [size, i] : sized) {
    if (size <= 0.0) continue;  // all zero: with the first tier
    if (tier_largest == 0.0) {
      tier_largest = size;
    } else if (size * ratio < tier_largest && tier + 1 < kMaxValueAxes) {
      ++tier;
      tier_largest = size;
    }
    tier_of[i] = tier;
  }
  std::vector<std::vector<std::string>> tiers(tier + 1);
  for (std::size_t i = 0; i < y.size(); ++i) tiers[tier_of[i]].push_back(y[i]);
  return tiers;
}

namespace {

// Widens `axis` so that [lo, hi] lies at least `margin` of its range inside both ends.
void holdInside(QCPAxis* axis, double lo, double hi, double margin) {
  const bool log = axis->scaleType() == QCPAxis::stLogarithmic;
  auto to = [log](double v) { return log ? std::log10(v) : v; };
  auto from = [log](double v) { return log ? std::pow(10.0, v) : v; };
  QCPRange range = axis->range();
  if (log && (lo <= 0.0 || range.lower <= 0.0)) return;
  double lower = to(range.lower), upper = to(range.upper);
  const double size = upper - lower;
  if (!(size > 0.0)) return;
  const double pad = margin * size;
  lower = std::min(lower, to(lo) - pad);
  upper = std::max(upper, to(hi) + pad);
  axis->setRange(from(lower), from(upper));
}

}  // namespace

void fitAxesToData(QCustomPlot& plot, double margin) {
  plot.rescaleAxes();
  // Each axis's smallest and largest marker coordinate (the markers' own extent, not the curves').
  std::map<QCPAxis*, QCPRange> marked;
  for (int i = 0; i < plot.graphCount(); ++i) {
    QCPGraph* g = plot.graph(i);
    if (g->lineStyle() != QCPGraph::lsNone || g->scatterStyle().isNone() || g->dataCount() == 0) continue;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) {
      for (auto [axis, v] : {std::pair{g->keyAxis(), it->key}, std::pair{g->valueAxis(), it->value}}) {
        if (!std::isfinite(v)) continue;
        auto [entry, added] = marked.try_emplace(axis, QCPRange(v, v));
        if (!added) entry->second.expand(v);
      }
    }
  }
  for (const auto& [axis, extent] : marked) holdInside(axis, extent.lower, extent.upper, margin);
}

}  // namespace maris::ui
