// A study's cases: expanded from its design and checked, all of them, before anything runs.
#include <algorithm>

#include "catalog.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"
#include "study/study.hpp"
#include "study/study_design.hpp"

namespace maris::study {

std::string caseId(std::size_t index, std::size_t count) {
  std::size_t width = 4;
  for (std::size_t c = count; c >= 10000; c /= 10) ++width;
  std::string id = std::to_string(index + 1);
  return std::string(id.size() < width ? width - id.size() : 0, '0') + id;
}

std::string caseRanges(const std::vector<std::size_t>& indices, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    text += (text.empty() ? "" : ", ") + caseId(indices[i], count);
    if (j > i) text += (j == i + 1 ? ", " : "-") + caseId(indices[j], count);
    i = j + 1;
  }
  return text;
}

std::size_t caseCount(const Study& study) {
  std::size_t count = 0;
  switch (study.kind) {
    case DesignKind::Grid:
      count = study.grid.empty() ? 0 : 1;
      for (const auto& values : study.grid) {
        if (!values.empty() && count > StudyLimits::kCases / values.size())
          throw InputError("grid", "", "has more than " + std::to_string(StudyLimits::kCases) +
                                           " cases (the product of the value counts); the limit is " +
                                           std::to_string(StudyLimits::kCases));
        count *= values.size();
      }
      break;
    case DesignKind::Table: count = study.rows.size(); break;
    case DesignKind::LatinHypercube: count = study.sample_count; break;
  }
  return count;
}

namespace {

const SceneDefinition& studyScene(const Study& study) {
  if (study.scene) return *study.scene;
  return requireScene(study.base.scene);  // a Study put together by hand: the catalog's scene
}

}  // namespace

std::vector<StudyCase> expandStudy(const Study& study) {
  const std::size_t count = caseCount(study);
  std::vector<std::vector<Json>> rows;
  if (study.kind == DesignKind::Table) rows = study.rows;
  if (study.kind == DesignKind::LatinHypercube) rows = detail::latinHypercubeRows(study);
  if (study.kind == DesignKind::Grid) {
    rows.reserve(count);
    std::vector<std::size_t> at(study.grid.size(), 0);  // odometer: the last parameter turns fastest
    for (std::size_t c = 0; c < count; ++c) {
      std::vector<Json> row;
      for (std::size_t p = 0; p < at.size(); ++p) row.push_back(study.grid[p][at[p]]);
      rows.push_back(std::move(row));
      for (std::size_t p = at.size(); p-- > 0;) {
        if (++at[p] < study.grid[p].size()) break;
        at[p] = 0;
      }
    }
  }
  const SceneDefinition& scene = studyScene(study);
  std::vector<StudyCase> cases;
  cases.reserve(count);
  for (std::size_t c = 0; c < count; ++c) {
    StudyCase k;
    k.id = caseId(c, count);
    k.values = std::move(rows[c]);
    k.scenario = study.base;
    k.scenario.name = (study.name.empty() ? study.base.name : study.name) + ", case " + k.id;
    std::string description = "Case " + k.id + " of " + std::to_string(count) + ":";
    for (std::size_t p = 0; p < study.parameters.size(); ++p) {
      detail::setParameter(k.scenario.parameters, study.parameters[p].path, k.values[p]);
      description += (p ? ", " : " ") + study.parameters[p].path + " = " + jsonSnippet(k.values[p]);
    }
    k.scenario.description = description + ". " + study.base.description;
    resolveDataPaths(scene.schema, k.scenario.parameters, study.folder);  // data paths among the values
    cases.push_back(std::move(k));
  }
  return cases;
}

std::vector<FieldError> caseErrors(const Study& study, const std::vector<StudyCase>& cases, bool allow_large) {
  const SceneDefinition& scene = studyScene(study);
  std::vector<FieldError> errors;
  std::vector<std::size_t> bad;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    auto problems = validateParameters(scene, cases[c].scenario.parameters);
    if (problems.empty() && !allow_large && scene.estimate) {
      // estimateWork() would validate again; the parameters just passed, so ask the scene directly.
      Json upgraded = cases[c].scenario.parameters;
      upgradeParameters(scene, upgraded);
      problems = workLimitErrors(scene.estimate(upgraded));
    }
    if (problems.empty()) continue;
    bad.push_back(c);
    for (auto& e : problems) {
      e.path = "case " + cases[c].id + ": " + e.path;
      errors.push_back(std::move(e));
    }
  }
  if (bad.empty()) return errors;
  FieldError summary{"cases", "", std::to_string(bad.size()) + " of " + std::to_string(cases.size()) +
                                      " cases are invalid: " + caseRanges(bad, cases.size()) +
                                      "; nothing was run"};
  errors.insert(errors.begin(), std::move(summary));
  return errors;
}

}  // namespace maris::study
