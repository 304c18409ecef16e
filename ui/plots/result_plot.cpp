#include "plots/result_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QSvgGenerator>
#include <qcustomplot.h>

#include "plots/display_units.hpp"
#include "plots/plot_axes.hpp"
#include "plots/reference_data.hpp"
#include "theme.hpp"

namespace maris::ui {

QString axisLabel(const std::string& text, const std::string& unit) {
  QString label = QString::fromStdString(text);
  if (const QString shown = unitText(unit); !shown.isEmpty()) label += QStringLiteral(" [%1]").arg(shown);
  return label;
}

QString axisLabel(const Column& column) { return axisLabel(displayLabel(column), displayUnit(column.unit).unit); }

QString fullGraphName(const QCPAbstractPlottable& graph) {
  const QVariant full = graph.property(kFullNameProperty);
  return full.isValid() ? full.toString() : graph.name();
}

QString wrapAtSpaces(const QString& text, int max_line) {
  QStringList lines;
  QString line;
  for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
    if (!line.isEmpty() && line.size() + 1 + word.size() > max_line) {
      lines << line;
      line.clear();
    }
    line += (line.isEmpty() ? QString() : QStringLiteral(" ")) + word;
  }
  if (!line.isEmpty()) lines << line;
  return lines.join(QLatin1Char('\n'));
}

namespace {

// A column's values in its display unit (plots/display_units.hpp).
QVector<double> shownValues(const Column& column) {
  const double factor = displayUnit(column.unit).factor;
  QVector<double> out(column.values.begin(), column.values.end());
  if (factor != 1.0)
    for (double& v : out) v *= factor;
  return out;
}

Qt::PenStyle runPenStyle(int run) {
  static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine,
                                        Qt::DashDotDotLine};
  return styles[run % 5];
}

// The y axis each column is drawn on: the left one, or a right one for columns much smaller than the largest
// (plots/plot_axes.hpp: the right axis, then further right axes outside it). Reference points go on their column's
// axis.
struct YAxes {
  std::vector<QCPAxis*> axes;                 // per tier: left, right, right 2, …
  std::map<std::string, std::size_t> tier_of;  // column name -> tier
  std::size_t tierOf(const std::string& name) const {
    const auto it = tier_of.find(name);
    return it == tier_of.end() ? 0 : it->second;
  }
  QCPAxis* of(const std::string& name) const { return axes[tierOf(name)]; }
  QString note(const std::string& name) const {
    const std::size_t tier = tierOf(name);
    if (tier == 0) return {};
    return tier == 1 ? QStringLiteral(" (right axis)") : QStringLiteral(" (right axis %1)").arg(tier);
  }
};


// Graphs of one source's y columns. With one y column the runs differ by colour, with several by
// line style (colour then names the column).
// Each column on its axis of `axes` (a legend entry of the right axis says so).
void addSourceGraphs(QCustomPlot& plot, QCPAxis* x_axis, const YAxes& axes, const PlotSource& source, int run,
                     bool several_sources, const Table& table, const Column& x, const PlotSpec& spec) {
  // Entries name their unit only where the axes do not say it for them: when the columns are on one axis in one
  // unit, the axis label carries it and the legend has room for the words that tell entries apart.
  std::set<std::string> units;
  bool one_axis = true;
  for (const auto& name : spec.y)
    if (const Column* y = table.find(name)) {
      units.insert(displayUnit(y->unit).unit);
      one_axis = one_axis && axes.tierOf(name) == 0;
    }
  const bool unit_on_axis = one_axis && units.size() == 1;
  int series = 0;
  for (const auto& name : spec.y) {
    const Column* y = table.find(name);
    if (!y) continue;
    QCPGraph* g = plot.addGraph(x_axis, axes.of(name));
    QString graph_name = (unit_on_axis ? QString::fromStdString(displayLabel(*y)) : axisLabel(*y)) + axes.note(name);
    if (several_sources) graph_name = source.label + ": " + graph_name;
    g->setName(graph_name);
    const int color_index = spec.y.size() == 1 ? run : series;
    QPen pen(seriesColor(color_index, plot.palette()), run == 0 ? 1.8 : 1.4);
    pen.setStyle(spec.y.size() == 1 ? Qt::SolidLine : runPenStyle(run));
    g->setPen(pen);
    g->setData(shownValues(x), shownValues(*y), true);
    ++series;
  }
}


// The y label of an axis with several columns: `title` (the plot's title; when empty, the columns' own
// labels) and the columns' unit(s).
QString severalColumnsLabel(const Table& table, const std::vector<std::string>& columns, const std::string& title) {
  QStringList units, labels;
  for (const auto& name : columns) {
    const Column* y = table.find(name);
    const QString unit = y ? unitText(displayUnit(y->unit).unit) : QString();
    if (!unit.isEmpty() && !units.contains(unit)) units << unit;
    if (y) labels << QString::fromStdString(displayLabel(*y));
  }
  QString label = title.empty() ? labels.join(QStringLiteral(", ")) : QString::fromStdString(title);
  // A title's closing aside ("Pitch RAO (curve: frequency domain, markers: time domain)") stays above the plot: on
  // the axis it made the label longer than the axis, clipped at both ends.
  if (!title.empty() && label.endsWith(QLatin1Char(')'))) {
    const qsizetype open = label.lastIndexOf(QStringLiteral(" ("));
    if (open > 0) label.truncate(open);
  }
  // "Bending frequencies against pretension ratio i_T": the y axis shows what comes before "against" (the x axis
  // names the rest), so the label fits beside the axis.
  if (!title.empty())
    for (const QString& word : {QStringLiteral(" against "), QStringLiteral(" vs ")})
      if (const qsizetype at = label.indexOf(word); at > 0) label.truncate(at);
  if (!units.isEmpty()) label += QStringLiteral("%1[%2]").arg(label.isEmpty() ? "" : " ", units.join(", "));
  return label;
}

// The label of a y axis that shows `columns`: the column's own label and unit when it is one.
QString yAxisLabel(const Table& table, const std::vector<std::string>& columns, const std::string& title) {
  if (columns.size() == 1)
    if (const Column* y = table.find(columns.front())) return axisLabel(*y);
  return severalColumnsLabel(table, columns, title);
}

// A plot point in fractions of the axes (0 … 1 inside them; log axes in log space); NaN where a log axis cannot
// show it.
double axisFraction(const QCPAxis* axis, double v) {
  const QCPRange r = axis->range();
  if (axis->scaleType() == QCPAxis::stLogarithmic) {
    if (v <= 0 || r.lower <= 0) return std::numeric_limits<double>::quiet_NaN();
    return std::log(v / r.lower) / std::log(r.upper / r.lower);
  }
  return r.size() > 0 ? (v - r.lower) / r.size() : 0.5;
}

// Whether the segment a–b (axis fractions) passes through the box [x0, x1] × [y0, y1] (Liang–Barsky clipping).
bool segmentCrossesBox(double ax, double ay, double bx, double by, double x0, double x1, double y0, double y1) {
  double t0 = 0.0, t1 = 1.0;
  const double dx = bx - ax, dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - x0, x1 - ax, ay - y0, y1 - ay};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

// The axis rect's size in pixels: its laid-out size once the plot was drawn at its present size, else the plot's
// size less room for the tick labels, axis labels and title (a plot not yet shown is taken as 600 × 400).
QSizeF axisRectPixels(const QCustomPlot& plot, const QCPAxisRect& rect) {
  if (rect.width() > 50 && rect.height() > 50 && plot.viewport().size() == plot.size())
    return QSizeF(rect.width(), rect.height());
  const double w = plot.width() > 100 ? plot.width() : 600, h = plot.height() > 100 ? plot.height() : 400;
  return QSizeF(std::max(50.0, w - 90.0), std::max(50.0, h - 80.0));
}

// The legend of a plot (fillPlot makes one, inside the axes or in a row under them), or null.
QCPLegend* findPlotLegend(const QCustomPlot& plot) {
  for (QCPLayoutElement* e : plot.plotLayout()->elements(true))
    if (auto* legend = qobject_cast<QCPLegend*>(e)) return legend;
  return nullptr;
}

}  // namespace

std::array<int, 4> legendCornerCover(const QCustomPlot& plot, const QCPAxisRect& rect, QSizeF legend_px) {
  const QSizeF rect_px = axisRectPixels(plot, rect);
  // The inset layout keeps the legend 12 px from the axes (QCPLayoutInset's margins): that strip is covered too.
  const double box_w = std::min(1.0, (legend_px.width() + 12.0) / rect_px.width());
  const double box_h = std::min(1.0, (legend_px.height() + 12.0) / rect_px.height());
  std::array<int, 4> hidden{0, 0, 0, 0};
  const struct {
    double x0, x1, y0, y1;
  } boxes[4] = {{1.0 - box_w, 1.0, 1.0 - box_h, 1.0},
                {0.0, box_w, 1.0 - box_h, 1.0},
                {1.0 - box_w, 1.0, 0.0, box_h},
                {0.0, box_w, 0.0, box_h}};
  for (int g = 0; g < plot.graphCount(); ++g) {
    const QCPGraph* graph = plot.graph(g);
    const auto data = graph->data();
    const int n = data->size();
    const int stride = std::max(1, n / 2000);  // a sample is enough to see which corners the data pass through
    const bool lines = graph->lineStyle() != QCPGraph::lsNone;
    double px = 0, py = 0;
    bool have_previous = false;
    for (int i = 0; i < n; i += stride) {
      const double fx = axisFraction(graph->keyAxis(), data->at(i)->key);
      const double fy = axisFraction(graph->valueAxis(), data->at(i)->value);
      if (!std::isfinite(fx) || !std::isfinite(fy)) {
        have_previous = false;
        continue;
      }
      for (int c = 0; c < 4; ++c) {
        const auto& b = boxes[c];
        const bool inside = fx >= b.x0 && fx <= b.x1 && fy >= b.y0 && fy <= b.y1;
        hidden[c] += inside || (lines && have_previous && segmentCrossesBox(px, py, fx, fy, b.x0, b.x1, b.y0, b.y1));
      }
      px = fx;
      py = fy;
      have_previous = true;
    }
  }
  return hidden;
}

void placePlotLegend(QCustomPlot& plot) {
  QCPLegend* legend = findPlotLegend(plot);
  QCPAxisRect* rect = plot.axisRect();
  if (!legend || !rect) return;
  // Taken out of wherever it is, then put where it hides least.
  if (legend->layout()) legend->layout()->take(legend);
  plot.plotLayout()->simplify();
  std::vector<QCPAbstractPlottable*> entries;
  for (int i = 0; i < legend->itemCount(); ++i)
    if (auto* item = qobject_cast<QCPPlottableLegendItem*>(legend->item(i))) entries.push_back(item->plottable());
  const QFontMetrics metrics(legend->font());
  const int plot_width = plot.width() > 100 ? plot.width() : 600;
  auto entry_width = [&](const QString& name) { return metrics.horizontalAdvance(name) + legend->iconSize().width() + 24; };
  int widest = 0;
  for (QCPAbstractPlottable* p : entries) widest = std::max(widest, entry_width(fullGraphName(*p)));
  // Entries too wide or too many for a corner go under the axes; wider than the plot, they are shortened with "…" in
  // the middle, keeping the end that tells entries apart (", float 2", the unit). The whole name stays as the
  // graph's "full_name": the hover read-out and the entry's tooltip show it.
  bool below = widest > 0.45 * plot_width || entries.size() > 8;
  const int room = plot_width - legend->iconSize().width() - 40;
  for (QCPAbstractPlottable* p : entries) {
    const QString full = fullGraphName(*p);
    p->setProperty(kFullNameProperty, full);
    p->setName(metrics.elidedText(full, Qt::ElideMiddle, room));
  }
  Qt::Alignment corner = Qt::AlignTop | Qt::AlignRight;
  if (!below) {
    legend->setWrap(0);
    legend->setFillOrder(QCPLayoutGrid::foRowsFirst, true);
    const QSize size = legend->minimumOuterSizeHint();
    const std::array<int, 4> hidden = legendCornerCover(plot, *rect, QSizeF(size.width(), size.height()));
    const Qt::Alignment corners[] = {Qt::AlignTop | Qt::AlignRight, Qt::AlignTop | Qt::AlignLeft,
                                     Qt::AlignBottom | Qt::AlignRight, Qt::AlignBottom | Qt::AlignLeft};
    const auto best = std::min_element(hidden.begin(), hidden.end());
    corner = corners[best - hidden.begin()];
    // Every corner crosses a curve (an oscillation fills the axes): under the axes it hides nothing.
    below = *best > 0;
  }
  if (below) {
    // Entries side by side in as many columns as the plot's width holds: a short block under the axes.
    int shown_widest = 0;
    for (QCPAbstractPlottable* p : entries) shown_widest = std::max(shown_widest, entry_width(p->name()));
    const int count = static_cast<int>(entries.size());
    int columns = std::max(1, (plot_width - 20) / std::max(1, shown_widest));
    // More than three rows would take the axes' height: more columns (each at least 160 px), entries shortened
    // to their column.
    constexpr int kMaxRows = 3, kMinColumnPx = 160;
    if ((count + columns - 1) / columns > kMaxRows) {
      const int wanted = std::min((count + kMaxRows - 1) / kMaxRows, std::max(1, (plot_width - 20) / kMinColumnPx));
      if (wanted > columns) {
        columns = wanted;
        const int column_room = (plot_width - 20) / columns - legend->iconSize().width() - 24;
        for (QCPAbstractPlottable* p : entries)
          p->setName(metrics.elidedText(fullGraphName(*p), Qt::ElideMiddle, column_room));
      }
    }
    legend->setWrap(std::min(static_cast<int>(entries.size()), columns));
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    const int row = plot.plotLayout()->rowCount();
    plot.plotLayout()->addElement(row, 0, legend);
    plot.plotLayout()->setRowStretchFactor(row, 0.001);
    legend->setMargins(QMargins(6, 2, 6, 2));
  } else {
    legend->setMargins(QMargins(7, 5, 7, 4));  // QCPLegend's own
    rect->insetLayout()->addElement(legend, corner);
  }
}

void setLogScale(QCPAxis* axis) {
  axis->setScaleType(QCPAxis::stLogarithmic);
  axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
}

// A legend inside the axes at a corner where it hides no curve, or under them (placePlotLegend).
void addPlotLegend(QCustomPlot& plot, QCPAxisRect& rect) {
  auto* legend = new QCPLegend;
  // Parked in the axes' inset until placed (an element needs a layout for its plot and font).
  rect.insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignRight);
  legend->setLayer(QLatin1String("legend"));
  for (int i = 0; i < plot.graphCount(); ++i) plot.graph(i)->addToLegend(legend);
  const DrawingColors colors = drawingColors(plot.palette());
  legend->setBrush(colors.legend_background);
  legend->setBorderPen(QPen(colors.foreground, 0.8));
  legend->setTextColor(colors.foreground);
  placePlotLegend(plot);
}

bool fillPlot(QCustomPlot& plot, const Results& results, const PlotSpec& spec) {
  return fillPlot(plot, std::vector<PlotSource>{{QString(), &results}}, spec);
}

bool fillPlot(QCustomPlot& plot, const std::vector<PlotSource>& sources, const PlotSpec& spec,
              const std::vector<Table>& references) {
  plot.clearGraphs();
  plot.clearPlottables();
  plot.clearItems();
  if (sources.empty() || !sources.front().results) return false;
  const Results& primary = *sources.front().results;
  const Table* table = primary.findTable(spec.table);
  if (!table) return false;
  const Column* x = table->find(spec.x);
  if (!x) return false;
  for (const auto& name : spec.y)
    if (!table->find(name)) return false;
  plot.plotLayout()->clear();
  auto* rect = new QCPAxisRect(&plot);
  plot.plotLayout()->addElement(0, 0, rect);
  if (!spec.title.empty()) {
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, QString::fromStdString(spec.title)));
  }
  QCPAxis* x_axis = rect->axis(QCPAxis::atBottom);
  QCPAxis* y_axis = rect->axis(QCPAxis::atLeft);
  x_axis->setLabel(axisLabel(*x));
  // On a log axis every size is readable; on a linear one a much smaller quantity gets a right axis (and a still
  // much smaller one another right axis outside it).
  const auto tiers = spec.log_y ? std::vector<std::vector<std::string>>{spec.y} : magnitudeTiers(*table, spec.y);
  YAxes axes;
  for (std::size_t tier = 0; tier < tiers.size(); ++tier) {
    QCPAxis* axis = tier == 0   ? y_axis
                    : tier == 1 ? rect->axis(QCPAxis::atRight)
                                : rect->addAxis(QCPAxis::atRight);
    axes.axes.push_back(axis);
    for (const auto& name : tiers[tier]) axes.tier_of[name] = tier;
    axis->setLabel(tiers.size() == 1 ? yAxisLabel(*table, spec.y, spec.title) : yAxisLabel(*table, tiers[tier], {}));
    if (tier == 0) continue;
    axis->setVisible(true);
    axis->setTickLabels(true);
    axis->grid()->setVisible(false);  // the left axis's grid only: two sets of lines would not read
  }

  const bool several = sources.size() > 1;
  for (int run = 0; run < static_cast<int>(sources.size()); ++run) {
    const Results* results = sources[run].results;
    const Table* t = results ? results->findTable(spec.table) : nullptr;
    const Column* tx = t ? t->find(spec.x) : nullptr;
    if (tx) addSourceGraphs(plot, x_axis, axes, sources[run], run, several, *t, *tx, spec);
  }
  int markers = 0;
  // The scene's own points go by their column's declared label ("C_T measured" says what they are); the user's
  // reference files also by the file's title, which tells them apart from the scene's.
  auto add_markers = [&](const Table& ref, const Column* rx, const Column* ry, QCPScatterStyle::ScatterShape shape,
                         bool scene_points) {
    QCPGraph* g = plot.addGraph(x_axis, axes.of(ry->name));
    const QString source = scene_points && !ry->label.empty()
                               ? QString()
                               : QString::fromStdString(ref.title.empty() ? ref.name : ref.title) + QStringLiteral(": ");
    g->setName(source + QString::fromStdString(displayLabel(*ry)) + axes.note(ry->name));
    g->setLineStyle(QCPGraph::lsNone);
    g->setScatterStyle(QCPScatterStyle(shape, QPen(drawingColors(plot.palette()).foreground, 1.2),
                                       QBrush(seriesColor(3 + markers++, plot.palette())), 7));
    g->setData(shownValues(*rx), shownValues(*ry));
  };
  if (const Table* ref = primary.findTable(spec.reference_table)) {
    const Column* rx = ref->find(spec.x);
    for (const auto& name : spec.reference_y)
      if (const Column* ry = ref->find(name); rx && ry) add_markers(*ref, rx, ry, QCPScatterStyle::ssCircle, true);
  }
  for (const Table& ref : references) {
    const ReferenceColumns match = matchReferenceColumns(ref, spec);
    for (const Column* ry : match.y) add_markers(ref, match.x, ry, QCPScatterStyle::ssDiamond, false);
  }
  if (spec.log_x) setLogScale(x_axis);
  if (spec.log_y) setLogScale(y_axis);
  fitAxesToData(plot);
  if (plot.graphCount() > 1) addPlotLegend(plot, *rect);
  applyPlotColors(plot);
  return true;
}

void applyPlotColors(QCustomPlot& plot) {
  const DrawingColors c = drawingColors(plot.palette());
  plot.setBackground(c.background);
  for (int e = 0; e < plot.plotLayout()->elementCount(); ++e)
    if (auto* title = qobject_cast<QCPTextElement*>(plot.plotLayout()->elementAt(e))) title->setTextColor(c.foreground);
  for (QCPAxisRect* rect : plot.axisRects()) {
    rect->setBackground(c.background);
    for (QCPAxis* axis : rect->axes()) {
      axis->setBasePen(QPen(c.foreground, 1));
      axis->setTickPen(QPen(c.foreground, 1));
      axis->setSubTickPen(QPen(c.foreground, 1));
      axis->setTickLabelColor(c.foreground);
      axis->setLabelColor(c.foreground);
      axis->grid()->setPen(QPen(c.grid, 1, Qt::DotLine));
      axis->grid()->setZeroLinePen(QPen(c.grid, 1));
    }
  }
}

bool plotCarriesData(const Results& results, const PlotSpec& spec) {
  const Table* table = results.findTable(spec.table);
  if (!table) return false;
  auto largest = [](const Column& c) {
    double m = 0.0;
    for (double v : c.values)
      if (std::isfinite(v)) m = std::max(m, std::abs(v));
    return m;
  };
  for (const auto& name : spec.y) {
    const Column* y = table->find(name);
    if (!y) continue;
    // Round-off is not data: a straight riser's lateral offsets of 1e-14 m beside its 100 m of depth. A value counts
    // above 1e-12 of the largest magnitude among the table's columns in the same unit (itself when it is alone).
    double scale = 0.0;
    for (const Column& c : table->columns)
      if (c.unit == y->unit) scale = std::max(scale, largest(c));
    if (largest(*y) > 1e-12 * scale) return true;
  }
  return false;
}

int primaryPointCount(const QCustomPlot& plot, const PlotSpec& spec) {
  int points = 0;
  const int graphs = std::min<int>(plot.graphCount(), static_cast<int>(spec.y.size()));
  for (int i = 0; i < graphs; ++i) points += plot.graph(i)->dataCount();
  return points;
}

PlotWords plotWords(QCustomPlot& plot) {
  PlotWords texts;
  QList<QCPLegend*> legends;
  const auto axisLabels = [&](QCPAxisRect* rect) {
    QList<QCPAxis*> axes = rect->axes(QCPAxis::atBottom) + rect->axes(QCPAxis::atLeft);
    for (QCPAxis* axis : rect->axes(QCPAxis::atRight) + rect->axes(QCPAxis::atTop))
      if (axis->visible()) axes << axis;
    for (QCPAxis* axis : axes)
      if (!axis->label().isEmpty()) texts.axes << axis->label();
    for (int i = 0; i < rect->insetLayout()->elementCount(); ++i)
      if (auto* legend = qobject_cast<QCPLegend*>(rect->insetLayout()->elementAt(i))) legends << legend;
  };
  for (QCPLayoutElement* element : plot.plotLayout()->elements(true)) {
    if (auto* title = qobject_cast<QCPTextElement*>(element)) {
      if (!texts.title.isEmpty()) texts.title += QLatin1Char(' ');
      texts.title += title->text();
    } else if (auto* scale = qobject_cast<QCPColorScale*>(element)) {
      if (!scale->axis()->label().isEmpty()) texts.axes << scale->axis()->label();
    } else if (auto* rect = qobject_cast<QCPAxisRect*>(element)) {
      axisLabels(rect);
    } else if (auto* legend = qobject_cast<QCPLegend*>(element)) {
      legends << legend;
    }
  }
  for (QCPLegend* legend : legends) {
    if (!legend->visible()) continue;
    for (int i = 0; i < legend->itemCount(); ++i)
      if (auto* item = qobject_cast<QCPPlottableLegendItem*>(legend->item(i)))
        texts.legend << fullGraphName(*item->plottable());
  }
  texts.legend.removeDuplicates();
  return texts;
}

bool savePlotWidget(QCustomPlot& plot, const QString& file, int width_px, int height_px) {
  const QFileInfo info(file);
  const QString suffix = info.suffix().toLower();
  // Written beside the target under a temporary name, then renamed: never a torn file.
  const QString partial = info.dir().filePath(QStringLiteral(".%1.partial.%2").arg(info.completeBaseName(), suffix));
  bool ok = false;
  if (suffix == QLatin1String("png")) {
    // As QCustomPlot::savePng draws it (96 dpi), with the plot's words as text chunks.
    QImage image = plot.toPixmap(width_px, height_px).toImage();
    image.setDotsPerMeterX(static_cast<int>(96 / 0.0254));
    image.setDotsPerMeterY(static_cast<int>(96 / 0.0254));
    const PlotWords texts = plotWords(plot);
    image.setText(QStringLiteral("Software"), QStringLiteral("Maris"));
    if (!texts.title.isEmpty()) image.setText(QStringLiteral("Title"), texts.title);
    if (!texts.axes.isEmpty()) image.setText(QStringLiteral("Axes"), texts.axes.join(QLatin1Char('\n')));
    if (!texts.legend.isEmpty()) image.setText(QStringLiteral("Legend"), texts.legend.join(QLatin1Char('\n')));
    ok = image.save(partial, "PNG");
  } else if (suffix == QLatin1String("pdf")) {
    ok = plot.savePdf(partial, width_px, height_px);
  } else if (suffix == QLatin1String("svg")) {
    QSvgGenerator generator;
    generator.setFileName(partial);
    generator.setSize(QSize(width_px, height_px));
    generator.setViewBox(QRect(0, 0, width_px, height_px));
    generator.setTitle(QStringLiteral("Maris plot"));
    QCPPainter painter;
    if (painter.begin(&generator)) {
      plot.toPainter(&painter, width_px, height_px);
      ok = painter.end();
    }
  } else {
    return false;
  }
  std::error_code ec;
  if (ok) std::filesystem::rename(partial.toStdString(), file.toStdString(), ec);
  if (!ok || ec) std::filesystem::remove(partial.toStdString(), ec);
  return ok && !ec;
}

bool savePlotImage(const Results& results, const PlotSpec& spec, const QString& file, int width_px, int height_px) {
  QCustomPlot plot;
  plot.resize(width_px, height_px);
  if (!fillPlot(plot, results, spec)) return false;
  return savePlotWidget(plot, file, width_px, height_px);
}

}  // namespace maris::ui
