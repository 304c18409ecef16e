// Collecting a study: every case's status and scalar results (from its summary.json) into study.csv,
// study.json and the data of its plots. Works on whatever is complete, so it runs after a local study,
// after a Slurm job array, or on a study still running.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/study_folder.hpp"

namespace maris::study {

struct CollectedCase {
  std::string id;
  CaseStatus status = CaseStatus::Missing;
  std::vector<Json> values;                    // one per varied parameter
  std::vector<std::optional<double>> results;  // one per CollectedStudy::result_names (none when missing)
  CaseOutcome outcome;                         // exit code, message and wall time of the last attempt
};

struct CollectedStudy {
  std::vector<StudyParameter> parameters;
  std::vector<std::string> result_names;  // the requested scalars, or every scalar of the complete cases (sorted)
  std::vector<std::string> result_units;
  std::vector<CollectedCase> cases;
  std::vector<std::string> warnings;      // requested results that no complete case has
  std::size_t count(CaseStatus status) const;
};

CollectedStudy collectStudy(const StudyFolder& folder, const StudyManifest& manifest);

// study.csv: a row of names (case, status, each varied parameter, each result), a row of units (SI; "-"
// where none), one row per case; numbers with 17 significant digits (a double round-trips), empty cells
// for results a case does not have. Nothing in it depends on timing or on the order cases finished.
std::string studyCsv(const CollectedStudy& collected);

// Writes study.csv and records the cases' status in study.json ("collected").
void writeCollected(const StudyFolder& folder, StudyManifest& manifest, const CollectedStudy& collected);

// The data of one PNG: a result against a varied parameter (points; a line when only one parameter varies),
// or, for a grid of two number parameters, the result as a heat map over both.
struct StudyPlot {
  std::string file_stem;  // "c_total_vs_hull.length", "c_total_map"
  std::string title;
  std::string x_name, x_unit, y_name, y_unit;
  std::vector<double> x, y;  // points (complete cases), or a heat map's axis values
  bool line = false;
  bool heat_map = false;
  std::string z_name, z_unit;
  std::vector<double> z;  // heat map: z[iy * x.size() + ix], NaN where the case has no result
};
std::vector<StudyPlot> studyPlots(const CollectedStudy& collected, const StudyManifest& manifest);

// A number cell as every Maris CSV writes it: 17 significant digits, independent of the locale.
std::string numberCell(double value);

}  // namespace maris::study
