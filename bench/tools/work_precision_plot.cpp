// work_precision_plot: turns a benchmark CSV (Maris layout: names row, units row, data rows; text
// columns allowed) into a log–log PNG with the plot code the GUI and maris-cli use (ui/plots), one
// curve per series. Only built with the GUI libraries (Qt 6); the benchmarks themselves need no Qt.
//   work_precision_plot IN.csv OUT.png --x cpu_time --y error_same_n --series variant,method
//                       [--where case=case5 --where n=100 ...] [--title "..."]
// Rows whose x or y is not a finite positive number (unstable runs: "inf") are skipped; each series'
// points are sorted by x and joined.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <QApplication>

#include "plots/result_plot.hpp"
#include <qcustomplot.h>

namespace {

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}

int usage() {
  std::fprintf(stderr, "usage: work_precision_plot IN.csv OUT.png --x COL --y COL --series COL[,COL...] "
                       "[--where COL=VALUE ...] [--title TEXT]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string input = argv[1], output = argv[2];
  std::string x_name, y_name, title = "Work-precision";
  std::vector<std::string> series_columns;
  std::vector<std::pair<std::string, std::string>> filters;
  for (int a = 3; a + 1 < argc; a += 2) {
    const std::string key = argv[a], value = argv[a + 1];
    if (key == "--x") x_name = value;
    else if (key == "--y") y_name = value;
    else if (key == "--title") title = value;
    else if (key == "--series") series_columns = splitCsv(value);
    else if (key == "--where" && value.find('=') != std::string::npos)
      filters.push_back({value.substr(0, value.find('=')), value.substr(value.find('=') + 1)});
    else return usage();
  }
  if (x_name.empty() || y_name.empty() || series_columns.empty()) return usage();
  std::ifstream in(input);
  std::string line;
  std::vector<std::string> names, units;
  if (!std::getline(in, line) || (names = splitCsv(line)).empty() || !std::getline(in, line)) {
    std::fprintf(stderr, "work_precision_plot: %s is not a Maris CSV (names row, units row)\n", input.c_str());
    return 2;
  }
  units = splitCsv(line);
  auto index = [&](const std::string& name) {
    for (std::size_t c = 0; c < names.size(); ++c)
      if (names[c] == name) return static_cast<int>(c);
    std::fprintf(stderr, "work_precision_plot: no column '%s' in %s\n", name.c_str(), input.c_str());
    std::exit(2);
  };
  const int xc = index(x_name), yc = index(y_name);
  std::map<std::string, std::vector<std::pair<double, double>>> series;
  while (std::getline(in, line)) {
    const std::vector<std::string> row = splitCsv(line);
    if (row.size() != names.size()) continue;
    bool keep = true;
    for (const auto& [column, value] : filters) keep = keep && row[index(column)] == value;
    const double x = std::atof(row[xc].c_str()), y = std::atof(row[yc].c_str());
    if (!keep || !(std::isfinite(x) && std::isfinite(y) && x > 0 && y > 0)) continue;
    std::string label;
    for (const auto& column : series_columns) label += (label.empty() ? "" : " ") + row[index(column)];
    series[label].push_back({x, y});
  }
  if (series.empty()) {
    std::fprintf(stderr, "work_precision_plot: no rows left after the filters\n");
    return 2;
  }
  // One Results per series (the plot code overlays several runs' tables with the same PlotSpec).
  std::vector<maris::Results> runs;
  std::vector<QString> labels;
  for (auto& [label, points] : series) {
    std::sort(points.begin(), points.end());
    maris::Table t;
    t.name = "points";
    auto& cx = t.add(x_name, units.size() > std::size_t(xc) ? units[xc] : "-");
    auto& cy = t.add(y_name, units.size() > std::size_t(yc) ? units[yc] : "-");
    (void)cx;
    (void)cy;
    for (const auto& [x, y] : points) {
      t.columns[0].values.push_back(x);
      t.columns[1].values.push_back(y);
    }
    maris::Results r;
    r.tables.push_back(std::move(t));
    runs.push_back(std::move(r));
    labels.push_back(QString::fromStdString(label));
  }
  std::vector<maris::ui::PlotSource> sources;
  for (std::size_t k = 0; k < runs.size(); ++k) sources.push_back({labels[k], &runs[k]});
  maris::PlotSpec spec = maris::makePlot("work_precision", title, "points", x_name, {y_name}, true);
  spec.log_x = true;
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QCustomPlot plot;
  plot.resize(1200, 800);
  if (!maris::ui::fillPlot(plot, sources, spec) || !maris::ui::savePlotWidget(plot, QString::fromStdString(output), 1200, 800)) {
    std::fprintf(stderr, "work_precision_plot: could not write %s\n", output.c_str());
    return 3;
  }
  std::printf("written %s (%zu series)\n", output.c_str(), series.size());
  return 0;
}
