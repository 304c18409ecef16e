// Exports of plot data and whole runs: the CSV behind one plot (names row, units row, data) and
// the one-click report folder (every table as CSV, scenario.json, summary.json from
// core/run_output.hpp, plus every plot as PNG and PDF, the 3D view, and a readable summary.md).
#pragma once

#include <chrono>
#include <filesystem>
#include <vector>

#include <QImage>
#include <QString>

#include "core/results.hpp"
#include "core/scenario.hpp"

namespace maris::ui {

// The columns a plot shows (x, then each y) as a table; empty if the spec does not match.
Table plotDataTable(const Results& results, const PlotSpec& spec);

// Writes plotDataTable as CSV, atomically. Throws std::runtime_error on failure.
void writePlotCsv(const std::filesystem::path& file, const Results& results, const PlotSpec& spec);

// Several runs' data of one plot stacked in one table: a "run" column (the run's number) first,
// then x and each y, the rows of each run in turn. Runs lacking the plot's columns are left out.
struct RunData {
  unsigned long long id = 0;
  const Results* results = nullptr;
  std::string scenario;  // the scenario's name, written beside the run number
};
Table plotDataOfRuns(const std::vector<RunData>& runs, const PlotSpec& spec);
// Writes plotDataOfRuns as CSV, atomically, with a "scenario" column after "run" naming each run's scenario.
// Throws std::runtime_error if no run has the data.
void writeRunsCsv(const std::filesystem::path& file, const std::vector<RunData>& runs, const PlotSpec& spec);

// `text` made safe for one cell of a Markdown table: `|` and `\` escaped with a backslash, line
// breaks as <br>.
std::string markdownTableCell(const std::string& text);

// A summary for people: scalars with units and descriptions, solver statistics, warnings, files.
std::string summaryMarkdown(const Scenario& scenario, const Results& results,
                            const std::vector<std::filesystem::path>& files);

// Writes the report folder (summary.json through writeRunFolder, with the run's start time);
// `view3d` (if not null) is saved as view_3d.png. Returns every file written. Throws
// std::runtime_error when a file cannot be written.
std::vector<std::filesystem::path> writeReportFolder(const std::filesystem::path& dir, const Scenario& scenario,
                                                     const Results& results,
                                                     std::chrono::system_clock::time_point started_at,
                                                     const QImage& view3d = {});

}  // namespace maris::ui
