#include "plots/study_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <qcustomplot.h>

#include "plots/display_units.hpp"
#include "plots/result_plot.hpp"
#include "plots/viridis.hpp"
#include "theme.hpp"

namespace maris::ui {

namespace {

std::vector<double> distinctValues(const std::vector<double>& values) {
  std::vector<double> out = values;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// `values` in the display unit of `unit` (View ▸ Units; SI where nothing was chosen, as in maris-cli).
std::vector<double> shownValues(std::vector<double> values, const std::string& unit) {
  const double factor = displayUnit(unit).factor;
  if (factor != 1.0)
    for (double& v : values) v *= factor;
  return values;
}

// The result's axis label: its label for people (or its name made readable) and its display unit.
QString resultAxisLabel(const StudyPlotData& data) {
  return studyAxisLabel(data.result_label.empty() ? readableName(data.result_name) : data.result_label,
                        data.result_unit);
}

int indexOf(const std::vector<double>& sorted, double v) {
  return static_cast<int>(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
}

// `v` with at least `digits` significant digits, and all of its integer digits below 1e6 (20000, not 2e+04).
QString studyNumber(double v, int digits) {
  const double magnitude = std::abs(v);
  if (magnitude >= 1.0 && magnitude < 1e6)
    digits = std::max(digits, static_cast<int>(std::floor(std::log10(magnitude))) + 1);
  return QString::number(v, 'g', digits);
}

// Significant digits that tell `values` apart: 4, or more where two distinct values would read the same.
int distinguishingDigits(const std::vector<double>& values) {
  const std::vector<double> distinct = distinctValues(values);
  for (int digits = 4; digits < 17; ++digits) {
    QStringList texts;
    for (double v : distinct) texts << studyNumber(v, digits);
    texts.removeDuplicates();
    if (texts.size() == static_cast<qsizetype>(distinct.size())) return digits;
  }
  return 17;
}

// "Length L [m] = 120, Method = 2" for the parameters other than `x` of case `c`, each with its `digits`
// (studyValueDigits).
QString groupLabel(const StudyPlotData& data, int x, std::size_t c, const std::vector<int>& digits) {
  QStringList parts;
  for (int p = 0; p < static_cast<int>(data.parameters.size()); ++p)
    if (p != x) parts << studyParameterValue(data.parameters[p], data.parameters[p].values[c], digits[p]);
  return parts.join(QStringLiteral(", "));
}

// An empty plot with one axis rectangle in row 0 (the title, if any, goes above it afterwards).
QCPAxisRect* freshAxisRect(QCustomPlot& plot) {
  plot.clearGraphs();
  plot.clearPlottables();
  plot.clearItems();
  plot.plotLayout()->clear();
  auto* rect = new QCPAxisRect(&plot);
  plot.plotLayout()->addElement(0, 0, rect);
  return rect;
}

void addTitle(QCustomPlot& plot, const std::string& title) {
  if (title.empty()) return;
  plot.plotLayout()->insertRow(0);
  plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, QString::fromStdString(title)));
}

// Tick labels at the cells' indices reading the cells' values (a grid need not be evenly spaced).
void cellTicks(QCPAxis* axis, const std::vector<double>& values) {
  QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
  const int step = std::max<int>(1, static_cast<int>(values.size()) / 10);
  const int digits = distinguishingDigits(values);
  for (int i = 0; i < static_cast<int>(values.size()); i += step)
    ticker->addTick(i, studyNumber(values[i], digits));
  axis->setTicker(ticker);
  axis->setRange(-0.5, values.size() - 0.5);
}

bool fillLines(QCustomPlot& plot, const StudyPlotData& data, int x, DrawnStudyPlot& drawn) {
  const StudyParameterData& px = data.parameters[x];
  const std::vector<double> shown_x = shownValues(px.values, px.unit);
  const std::vector<double> shown_result = shownValues(data.result, data.result_unit);
  // Cases grouped by the values of every other parameter, in order of those values.
  std::map<std::vector<double>, std::vector<int>> groups;
  for (std::size_t c = 0; c < data.caseCount(); ++c) {
    if (!std::isfinite(data.result[c]) || !std::isfinite(px.values[c])) continue;
    std::vector<double> key;
    for (int p = 0; p < static_cast<int>(data.parameters.size()); ++p)
      if (p != x) key.push_back(data.parameters[p].values[c]);
    groups[key].push_back(static_cast<int>(c));
  }
  if (groups.empty()) return false;
  QCPAxisRect* rect = freshAxisRect(plot);
  QCPAxis* x_axis = rect->axis(QCPAxis::atBottom);
  QCPAxis* y_axis = rect->axis(QCPAxis::atLeft);
  x_axis->setLabel(studyAxisLabel(px));
  y_axis->setLabel(resultAxisLabel(data));
  // A sample (table, Latin hypercube) shares no combination between cases: its points stand alone.
  const bool scatter = std::all_of(groups.begin(), groups.end(), [](const auto& g) { return g.second.size() == 1; });
  if (scatter) {
    std::vector<int> all;
    for (const auto& [key, cases] : groups) all.push_back(cases.front());
    groups = {{{}, all}};
  }
  std::vector<int> digits;
  for (const auto& p : data.parameters) digits.push_back(studyValueDigits(p));
  int series = 0;
  for (auto& [key, cases] : groups) {
    std::stable_sort(cases.begin(), cases.end(), [&](int a, int b) { return px.values[a] < px.values[b]; });
    QVector<double> keys, values;
    for (int c : cases) {
      keys << shown_x[c];
      values << shown_result[c];
    }
    QCPGraph* g = plot.addGraph(x_axis, y_axis);
    const QColor color = seriesColor(series, plot.palette());
    g->setName(scatter || groups.size() == 1 ? resultAxisLabel(data)
                                            : groupLabel(data, x, cases.front(), digits));
    g->setPen(QPen(color, 1.6));
    g->setLineStyle(scatter ? QCPGraph::lsNone : QCPGraph::lsLine);
    g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, color, color, 6));
    g->setData(keys, values, true);
    drawn.graph_cases.push_back(cases);
    drawn.points += static_cast<int>(cases.size());
    ++series;
  }
  if (px.log) setLogScale(x_axis);
  plot.rescaleAxes();
  // Room around the outermost points, so their markers are whole and clickable.
  x_axis->scaleRange(1.06, x_axis->range().center());
  y_axis->scaleRange(1.1, y_axis->range().center());
  if (plot.graphCount() > 1) addPlotLegend(plot, *rect);
  addTitle(plot, data.title);
  applyPlotColors(plot);
  return true;
}

bool fillHeatMap(QCustomPlot& plot, const StudyPlotData& data, int x, DrawnStudyPlot& drawn) {
  if (data.parameters.size() != 2) return false;
  const int y = 1 - x;
  if (!isFullGrid(data, x, y)) return false;
  drawn.cell_x = distinctValues(data.parameters[x].values);
  drawn.cell_y = distinctValues(data.parameters[y].values);
  const int nx = static_cast<int>(drawn.cell_x.size()), ny = static_cast<int>(drawn.cell_y.size());
  const std::vector<double> shown_result = shownValues(data.result, data.result_unit);
  drawn.cell_case.assign(static_cast<std::size_t>(nx) * ny, -1);
  QCPAxisRect* rect = freshAxisRect(plot);
  QCPAxis* x_axis = rect->axis(QCPAxis::atBottom);
  QCPAxis* y_axis = rect->axis(QCPAxis::atLeft);
  auto* map = new QCPColorMap(x_axis, y_axis);
  map->data()->setSize(nx, ny);
  map->data()->setRange(QCPRange(0, nx - 1), QCPRange(0, ny - 1));
  for (std::size_t c = 0; c < data.caseCount(); ++c) {
    const int i = indexOf(drawn.cell_x, data.parameters[x].values[c]);
    const int j = indexOf(drawn.cell_y, data.parameters[y].values[c]);
    const double v = shown_result[c];
    drawn.cell_case[static_cast<std::size_t>(j) * nx + i] = static_cast<int>(c);
    if (std::isfinite(v)) {
      map->data()->setCell(i, j, v);
      ++drawn.points;
    } else {
      map->data()->setAlpha(i, j, 0);  // a failed case leaves its cell empty
    }
  }
  if (drawn.points == 0) return false;
  x_axis->setLabel(studyAxisLabel(data.parameters[x]));
  y_axis->setLabel(studyAxisLabel(data.parameters[y]));
  auto* scale = new QCPColorScale(&plot);
  plot.plotLayout()->addElement(0, 1, scale);
  scale->setType(QCPAxis::atRight);
  scale->axis()->setLabel(resultAxisLabel(data));
  map->setColorScale(scale);
  // Viridis: uniform in lightness, readable in grey print, and no end colour vanishes into a light or
  // dark background.
  QCPColorGradient viridis;
  viridis.clearColorStops();
  for (std::size_t i = 0; i < kViridis.size(); ++i)
    viridis.setColorStopAt(static_cast<double>(i) / (kViridis.size() - 1),
                           QColor(kViridis[i][0], kViridis[i][1], kViridis[i][2]));
  map->setGradient(viridis);
  map->setInterpolate(false);
  map->rescaleDataRange(true);
  auto* margins = new QCPMarginGroup(&plot);
  rect->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
  scale->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
  cellTicks(x_axis, shownValues(drawn.cell_x, data.parameters[x].unit));
  cellTicks(y_axis, shownValues(drawn.cell_y, data.parameters[y].unit));
  addTitle(plot, data.title);
  applyPlotColors(plot);
  const DrawingColors colors = drawingColors(plot.palette());
  for (QCPAxis* axis : {scale->axis()}) {
    axis->setBasePen(QPen(colors.foreground, 1));
    axis->setTickPen(QPen(colors.foreground, 1));
    axis->setSubTickPen(QPen(colors.foreground, 1));
    axis->setTickLabelColor(colors.foreground);
    axis->setLabelColor(colors.foreground);
  }
  for (QCPAxis* axis : {x_axis, y_axis}) axis->grid()->setVisible(false);
  return true;
}

}  // namespace

QString studyAxisLabel(const std::string& label, const std::string& unit) {
  return axisLabel(label, displayUnit(unit).unit);
}

QString studyAxisLabel(const StudyParameterData& parameter) {
  return studyAxisLabel(parameter.label.empty() ? parameter.name : parameter.label, parameter.unit);
}

int studyValueDigits(const StudyParameterData& parameter) {
  return distinguishingDigits(shownValues(parameter.values, parameter.unit));
}

QString studyParameterValue(const StudyParameterData& parameter, double value, int digits) {
  return QStringLiteral("%1 = %2").arg(studyAxisLabel(parameter),
                                       studyNumber(value * displayUnit(parameter.unit).factor, digits));
}

QString studyValueLabel(const StudyParameterData& parameter, std::size_t c) {
  return studyParameterValue(parameter, c < parameter.values.size() ? parameter.values[c] : std::nan(""),
                             studyValueDigits(parameter));
}

bool isFullGrid(const StudyPlotData& data, int a, int b) {
  const int n = static_cast<int>(data.parameters.size());
  if (a < 0 || b < 0 || a >= n || b >= n || a == b || data.caseCount() == 0) return false;
  for (int p = 0; p < n; ++p)
    if (p != a && p != b && distinctValues(data.parameters[p].values).size() > 1) return false;
  const auto va = distinctValues(data.parameters[a].values);
  const auto vb = distinctValues(data.parameters[b].values);
  if (va.size() * vb.size() != data.caseCount()) return false;
  std::vector<char> seen(va.size() * vb.size(), 0);
  for (std::size_t c = 0; c < data.caseCount(); ++c) {
    char& cell = seen[indexOf(vb, data.parameters[b].values[c]) * va.size() + indexOf(va, data.parameters[a].values[c])];
    if (cell) return false;
    cell = 1;
  }
  return true;
}

bool fillStudyPlot(QCustomPlot& plot, const StudyPlotData& data, int x, StudyPlotKind kind, DrawnStudyPlot* drawn) {
  DrawnStudyPlot local;
  DrawnStudyPlot& out = drawn ? *drawn : local;
  out = DrawnStudyPlot{};
  out.kind = kind;
  const bool shaped = x >= 0 && x < static_cast<int>(data.parameters.size()) &&
                      std::all_of(data.parameters.begin(), data.parameters.end(),
                                  [&](const auto& p) { return p.values.size() == data.caseCount(); });
  const bool ok = shaped && (kind == StudyPlotKind::Lines ? fillLines(plot, data, x, out) : fillHeatMap(plot, data, x, out));
  if (!ok) {
    out = DrawnStudyPlot{};
    plot.clearPlottables();
  }
  return ok;
}

bool saveStudyPlotImage(const StudyPlotData& data, int x, StudyPlotKind kind, const QString& file, int width_px,
                        int height_px) {
  QCustomPlot plot;
  plot.resize(width_px, height_px);
  if (!fillStudyPlot(plot, data, x, kind)) return false;
  return savePlotWidget(plot, file, width_px, height_px);
}

int studyCaseAt(QCustomPlot& plot, const DrawnStudyPlot& drawn, QPointF pixel, double radius_px) {
  if (drawn.kind == StudyPlotKind::HeatMap) {
    if (drawn.cell_case.empty() || plot.plottableCount() == 0) return -1;
    QCPAbstractPlottable* map = plot.plottable(0);
    const int i = static_cast<int>(std::lround(map->keyAxis()->pixelToCoord(pixel.x())));
    const int j = static_cast<int>(std::lround(map->valueAxis()->pixelToCoord(pixel.y())));
    const int nx = static_cast<int>(drawn.cell_x.size()), ny = static_cast<int>(drawn.cell_y.size());
    if (i < 0 || j < 0 || i >= nx || j >= ny) return -1;
    return drawn.cell_case[static_cast<std::size_t>(j) * nx + i];
  }
  int best = -1;
  double best_distance = radius_px;
  for (int g = 0; g < plot.graphCount() && g < static_cast<int>(drawn.graph_cases.size()); ++g) {
    QCPGraph* graph = plot.graph(g);
    int k = 0;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it, ++k) {
      const QPointF at(graph->keyAxis()->coordToPixel(it->key), graph->valueAxis()->coordToPixel(it->value));
      const double d = std::hypot(at.x() - pixel.x(), at.y() - pixel.y());
      if (d <= best_distance && k < static_cast<int>(drawn.graph_cases[g].size())) {
        best_distance = d;
        best = drawn.graph_cases[g][k];
      }
    }
  }
  return best;
}

QPointF studyCasePixel(QCustomPlot& plot, const DrawnStudyPlot& drawn, int index) {
  if (drawn.kind == StudyPlotKind::HeatMap) {
    const auto it = std::find(drawn.cell_case.begin(), drawn.cell_case.end(), index);
    if (it == drawn.cell_case.end() || plot.plottableCount() == 0) return {-1, -1};
    const auto cell = static_cast<int>(it - drawn.cell_case.begin());
    const int nx = static_cast<int>(drawn.cell_x.size());
    QCPAbstractPlottable* map = plot.plottable(0);
    return {map->keyAxis()->coordToPixel(cell % nx), map->valueAxis()->coordToPixel(cell / nx)};
  }
  for (int g = 0; g < plot.graphCount() && g < static_cast<int>(drawn.graph_cases.size()); ++g) {
    const auto& cases = drawn.graph_cases[g];
    const auto it = std::find(cases.begin(), cases.end(), index);
    if (it == cases.end()) continue;
    const auto point = plot.graph(g)->data()->at(static_cast<int>(it - cases.begin()));
    return {plot.graph(g)->keyAxis()->coordToPixel(point->key), plot.graph(g)->valueAxis()->coordToPixel(point->value)};
  }
  return {-1, -1};
}

}  // namespace maris::ui
