// work_precision_plot: turns a benchmark CSV (Maris layout: names row, units row, data rows; text
// columns allowed) into a log–log work–precision PNG. Only built with the GUI libraries (Qt 6,
// QCustomPlot); the benchmarks themselves need no Qt.
//   work_precision_plot IN.csv OUT.png --x cpu_time --y error_same_n --series variant,method
//       [--where case=case5 --where n=100 ...] [--title "..."] [--xlabel "CPU time [s]"] [--ylabel "error [-]"]
//       [--detail setting] [--note note]
// One series per distinct value of the --series columns (work_precision_series.hpp: points sorted by x),
// each with its own colour and marker shape; the legend sits right of the axes. Rows whose x or y is not a
// finite positive number (a failed run's "inf") are left out and listed in a note under the plot, with
// the --detail columns and the reason from the --note column (default "note", if the CSV has it).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <QApplication>

#include "plots/result_plot.hpp"
#include "theme.hpp"
#include "work_precision_series.hpp"
#include <qcustomplot.h>

namespace {

int usage() {
  std::fprintf(stderr, "usage: work_precision_plot IN.csv OUT.png --x COL --y COL --series COL[,COL...] "
                       "[--where COL=VALUE ...] [--title TEXT] [--xlabel TEXT] [--ylabel TEXT] [--detail COL,...] "
                       "[--note COL]\n");
  return 2;
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

// Twelve marker shapes: series k gets colour k mod 12 (maris::ui::seriesColor, the GUI's palette) and shape
// (k + k / 12) mod 12, so the first twelve differ in both and later ones (case 5 has 16: four variants × four
// methods) never repeat an earlier colour-and-shape pair.
int shapeIndex(int k) { return (k + k / 12) % 12; }

QCPScatterStyle::ScatterShape seriesShape(int k) {
  using S = QCPScatterStyle;
  static const S::ScatterShape shapes[] = {S::ssCircle,      S::ssSquare,     S::ssTriangle,   S::ssDiamond,
                                           S::ssCross,       S::ssTriangleInverted, S::ssPlus, S::ssStar,
                                           S::ssCrossCircle, S::ssPlusSquare, S::ssCrossSquare, S::ssPlusCircle};
  return shapes[shapeIndex(k)];
}

void setLogAxis(QCPAxis* axis, const QString& label, double low, double high) {
  axis->setScaleType(QCPAxis::stLogarithmic);
  axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  axis->setNumberFormat("eb");
  axis->setNumberPrecision(0);
  axis->setLabel(label);
  // Half a decade of room on each side so that markers at the ends are not cut.
  axis->setRange(low / std::sqrt(10.0), high * std::sqrt(10.0));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string input = argv[1], output = argv[2];
  std::string title = "Work-precision", x_label, y_label;
  maris::bench::SeriesSelection selection;
  selection.note_column = "note";
  for (int a = 3; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--x") selection.x = value;
    else if (key == "--y") selection.y = value;
    else if (key == "--title") title = value;
    else if (key == "--xlabel") x_label = value;
    else if (key == "--ylabel") y_label = value;
    else if (key == "--series") selection.series_columns = splitList(value);
    else if (key == "--detail") selection.detail_columns = splitList(value);
    else if (key == "--note") selection.note_column = value;
    else if (key == "--where" && value.find('=') != std::string::npos)
      selection.where.push_back({value.substr(0, value.find('=')), value.substr(value.find('=') + 1)});
    else return usage();
  }
  if (selection.x.empty() || selection.y.empty() || selection.series_columns.empty()) return usage();

  maris::bench::WorkPrecisionSet set;
  try {
    std::ifstream in(input);
    if (!in) throw std::runtime_error("cannot be read");
    std::stringstream text;
    text << in.rdbuf();
    set = maris::bench::groupWorkPrecision(maris::bench::parseTextCsv(text.str()), selection);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "work_precision_plot: %s: %s\n", input.c_str(), e.what());
    return 2;
  }
  if (set.series.empty()) {
    std::fprintf(stderr, "work_precision_plot: no plottable rows left after the filters in %s\n", input.c_str());
    return 2;
  }

  qputenv("QT_QPA_PLATFORM", qgetenv("QT_QPA_PLATFORM").isEmpty() ? "offscreen" : qgetenv("QT_QPA_PLATFORM"));
  QApplication app(argc, argv);
  QCustomPlot plot;
  plot.resize(1200, 800);
  double x_low = 1e300, x_high = 0, y_low = 1e300, y_high = 0;
  for (std::size_t k = 0; k < set.series.size(); ++k) {
    const auto& series = set.series[k];
    QCPGraph* graph = plot.addGraph();
    graph->setName(QString::fromStdString(series.label));
    const QColor color = maris::ui::seriesColor(static_cast<int>(k), QPalette(Qt::white));  // drawn on white
    graph->setPen(QPen(color, 1.6));
    // Shapes 7–12 are drawn hollow (their inner cross or plus would vanish under a fill).
    const int index = static_cast<int>(k);
    graph->setScatterStyle(QCPScatterStyle(seriesShape(index), color, shapeIndex(index) < 6 ? color : Qt::white, 8));
    for (const auto& [x, y] : series.points) {
      graph->addData(x, y);
      x_low = std::min(x_low, x), x_high = std::max(x_high, x), y_low = std::min(y_low, y), y_high = std::max(y_high, y);
    }
  }
  setLogAxis(plot.xAxis, QString::fromStdString(x_label.empty() ? selection.x + " [" + set.x_unit + "]" : x_label),
             x_low, x_high);
  setLogAxis(plot.yAxis, QString::fromStdString(y_label.empty() ? selection.y + " [" + set.y_unit + "]" : y_label),
             y_low, y_high);
  plot.xAxis2->setVisible(true);
  plot.yAxis2->setVisible(true);
  plot.xAxis2->setTicks(false);
  plot.yAxis2->setTicks(false);

  // Title above, the legend in a column right of the axes (it never covers points), the note below.
  plot.plotLayout()->insertRow(0);
  plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, QString::fromStdString(title), QFont("sans", 12, QFont::Bold)));
  plot.legend->setVisible(true);
  plot.axisRect()->insetLayout()->take(plot.legend);
  auto* side = new QCPLayoutGrid;  // legend on top, empty space below it
  plot.plotLayout()->addElement(1, 1, side);
  plot.plotLayout()->setColumnStretchFactor(1, 0.001);
  side->addElement(0, 0, plot.legend);
  side->addElement(1, 0, new QCPLayoutElement(&plot));
  side->setRowStretchFactor(0, 0.001);
  side->setMargins(QMargins(4, 0, 10, 0));
  plot.legend->setMargins(QMargins(6, 4, 6, 4));
  const std::string note = maris::bench::leftOutNote(set.left_out, 6);
  if (!note.empty()) {
    // Wrapped: QCPTextElement does not wrap, and an unbroken note would widen the column and squeeze the legend.
    auto* text = new QCPTextElement(&plot, maris::ui::wrapAtSpaces(QString::fromStdString(note), 150), QFont("sans", 8));
    text->setTextFlags(Qt::AlignLeft);
    plot.plotLayout()->addElement(2, 0, text);
    std::printf("%s\n", note.c_str());
  }
  if (!maris::ui::savePlotWidget(plot, QString::fromStdString(output), 1200, 800)) {
    std::fprintf(stderr, "work_precision_plot: could not write %s\n", output.c_str());
    return 3;
  }
  std::printf("written %s (%zu series, %zu left out)\n", output.c_str(), set.series.size(), set.left_out.size());
  return 0;
}
