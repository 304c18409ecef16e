// What a study plot draws, as plain numbers (no Qt): per case, every varied parameter's value and the
// result. The GUI's study panel builds it from a session, maris-cli from a collected study folder, and the
// plot renderer (plots/study_plot.hpp, loaded by maris-cli only when it writes plots) draws it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace maris::ui {

// One varied parameter and its value in each case.
struct StudyParameterData {
  std::string name;   // the parameter path, "geometry.length"
  std::string label;  // for people, from the scene's schema ("Length L"); empty: the path is shown
  std::string unit;
  bool log = false;  // varied on a log scale: the x axis is logarithmic
  std::vector<double> values;
};

// A study's numbers for one result scalar: every varied parameter and the result, per case. A
// case without the result (failed, cancelled, not run) holds NaN and is left out of the plot.
struct StudyPlotData {
  std::string title;  // above the plot (empty: none)
  std::vector<StudyParameterData> parameters;
  std::string result_name;
  std::string result_label;  // for people ("σ_b max"); empty: the name made readable
  std::string result_unit;
  std::vector<double> result;
  std::size_t caseCount() const { return result.size(); }
};

enum class StudyPlotKind { Lines, HeatMap };

}  // namespace maris::ui
