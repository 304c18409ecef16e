// Collecting a study: every case's status and scalar results (from its summary.json) into study.csv,
// study.json and the data of its plots. Works on whatever is complete, so it runs after a local study,
// after a Slurm job array, or on a study still running.
#pragma once

#include <map>
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

// A table study's weighted sum ("weighted_sum"): sum_i weight_i * result_i over its cases, e.g. a scatter
// diagram's yearly fatigue damage from each sea state's probability and its damage per year.
struct WeightedSum {
  std::string result;
  std::string unit;                  // the result's ("-" when no case has it)
  std::optional<double> value;       // none while a case of weight > 0 is not complete or lacks the result
  double weight_total = 0.0;         // sum of all cases' weights (1 for probabilities covering every case)
  std::vector<std::string> missing;  // cases of weight > 0 that are not complete or lack the result
};

struct CollectedStudy {
  std::vector<StudyParameter> parameters;
  std::vector<std::string> result_names;  // the requested scalars, or every scalar of the complete cases (sorted)
  std::vector<std::string> result_units;
  std::vector<std::string> result_labels;  // collectStudy: each result's label from the cases' summary.json ("": none)
  std::vector<CollectedCase> cases;
  std::vector<std::string> warnings;      // requested results that no complete case has
  std::vector<WeightedSum> weighted_sums; // a table study's "weighted_sum", one per listed result
  std::size_t count(CaseStatus status) const;
};

CollectedStudy collectStudy(const StudyFolder& folder, const StudyManifest& manifest);

// One case's scalar results: name -> (value, unit).
using CaseScalars = std::map<std::string, std::pair<double, std::string>>;
// The collected study from each case's status and, for the Ok ones, its scalars (one per case): what
// collectStudy does after reading the folder, and what the desktop application does with results in memory.
// The result columns are `requested`, or else every scalar of the Ok cases (sorted by name).
CollectedStudy collectScalars(std::vector<StudyParameter> parameters, const std::vector<std::string>& requested,
                              std::vector<CollectedCase> cases, const std::vector<CaseScalars>& scalars);

// Each of `results` summed over the cases with the cases' `weights` (one per case), in case order. A case
// counts when it is Ok and has the result; a case of weight 0 is not needed.
std::vector<WeightedSum> weightedSums(const std::vector<std::string>& results, const std::vector<double>& weights,
                                      const std::vector<CollectedCase>& cases, const std::vector<CaseScalars>& scalars);

// study.csv: a row of names (case, status, each varied parameter, each result), a row of units (SI; "-"
// where none), one row per case; numbers with 17 significant digits (a double round-trips), empty cells
// for results a case does not have. Nothing in it depends on timing or on the order cases finished.
std::string studyCsv(const CollectedStudy& collected);

// Writes study.csv and records the cases' status in study.json ("collected", with its "weighted_sums").
void writeCollected(const StudyFolder& folder, StudyManifest& manifest, const CollectedStudy& collected);

// One PNG of a collected study: result `result` against the number parameter `x` (a line per combination
// of the other varied number parameters; markers only when no two cases share one, as in a table or a
// Latin-hypercube sample), or, for a full grid of two number parameters, a heat map of the result over
// both (`x` across). Indices are into CollectedStudy::parameters and ::result_names; the desktop
// application's study plot draws it (the same picture as its Study panel).
struct StudyPlot {
  std::string file_stem;  // "c_total_vs_hull.length", "c_total_map", "drag_vs_current.profile_1.speed" for the
                          // cell current.profile[1].speed: only [A-Za-z0-9._-], unique in the study (ignoring case)
  std::string title;
  std::size_t result = 0;
  std::size_t x = 0;
  bool heat_map = false;
};
std::vector<StudyPlot> studyPlots(const CollectedStudy& collected, const StudyManifest& manifest);

// True when the study document varies parameter `path` on a log scale (a grid's or a sample's "spacing":
// "log"): the study file as read (Study::document) or as study.json records it (its "study").
bool logSpaced(const Json& study_document, const std::string& path);


}  // namespace maris::study
