// The three designs: a full-factorial grid, a table of cases and a Latin-hypercube sample.
#include "study/study_design.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "core/input_limits.hpp"
#include "core/portable_random.hpp"
#include "core/text_format.hpp"

namespace maris::study::detail {

namespace {

bool isNumeric(ParamKind kind) { return kind == ParamKind::Real || kind == ParamKind::Integer; }

std::string countText(std::size_t n) { return std::to_string(n); }

// Reads a finite number at `key` of `object`; adds an error and returns NaN otherwise.
double finiteNumber(const Json& object, const char* key, const std::string& where, std::vector<FieldError>& errors) {
  const auto it = object.find(key);
  if (it == object.end()) {
    errors.push_back({where + "." + key, "", "is missing (a number)"});
    return std::nan("");
  }
  if (!it->is_number() || !std::isfinite(it->get<double>())) {
    errors.push_back({where + "." + key, jsonSnippet(*it), "must be a finite number"});
    return std::nan("");
  }
  return it->get<double>();
}

// Refuses every key of `object` not in `known`, with a did-you-mean.
void refuseUnknownKeys(const Json& object, const std::vector<std::string>& known, const std::string& where,
                       std::vector<FieldError>& errors) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    const auto guess = didYouMean(it.key(), known);
    errors.push_back({where + "." + it.key(), jsonSnippet(it.value()),
                      "unknown field" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
  }
}

Spacing readSpacing(const Json& object, const std::string& where, std::vector<FieldError>& errors) {
  const auto it = object.find("spacing");
  if (it == object.end()) return Spacing::Linear;
  if (it->is_string() && it->get<std::string>() == "linear") return Spacing::Linear;
  if (it->is_string() && it->get<std::string>() == "log") return Spacing::Log;
  errors.push_back({where + ".spacing", jsonSnippet(*it), "must be \"linear\" or \"log\""});
  return Spacing::Linear;
}

// A whole number in [low, high] at `key`, or `fallback` after an error.
std::size_t wholeNumber(const Json& object, const char* key, std::size_t low, std::size_t high,
                        const std::string& where, std::vector<FieldError>& errors) {
  const auto it = object.find(key);
  if (it == object.end()) {
    errors.push_back({where + "." + key, "", "is missing (a whole number in [" + countText(low) + ", " +
                                                  countText(high) + "])"});
    return 0;
  }
  if (!it->is_number_integer() || it->get<long long>() < static_cast<long long>(low) ||
      it->get<long long>() > static_cast<long long>(high)) {
    errors.push_back({where + "." + key, jsonSnippet(*it),
                      "must be a whole number in [" + countText(low) + ", " + countText(high) + "]"});
    return 0;
  }
  return static_cast<std::size_t>(it->get<long long>());
}

// The values of {"from", "to", "count", "spacing"}: the ends exactly, the points between evenly spaced in
// the value or, for "log", in its logarithm.
std::vector<Json> rangeValues(const Json& range, const ParamSpec& spec, const std::string& where,
                              std::vector<FieldError>& errors) {
  refuseUnknownKeys(range, {"from", "to", "count", "spacing"}, where, errors);
  const std::size_t before = errors.size();
  const double from = finiteNumber(range, "from", where, errors), to = finiteNumber(range, "to", where, errors);
  const std::size_t count = wholeNumber(range, "count", 1, StudyLimits::kCases, where, errors);
  const Spacing spacing = readSpacing(range, where, errors);
  if (errors.size() > before) return {};
  if (count == 1 && from != to) {
    errors.push_back({where + ".count", "1", "gives one value, so from and to must be equal (or count >= 2)"});
    return {};
  }
  if (spacing == Spacing::Log && !(from > 0.0 && to > 0.0)) {
    errors.push_back({where + ".spacing", "\"log\"", "needs from > 0 and to > 0 (they are " +
                                                         formatText("%.17g and %.17g)", from, to)});
    return {};
  }
  std::vector<Json> values;
  const double n = static_cast<double>(count - 1);
  for (std::size_t i = 0; i < count; ++i) {
    const double a = static_cast<double>(count - 1 - i), b = static_cast<double>(i);
    double v = from;
    if (i + 1 == count) v = to;
    else if (i > 0 && spacing == Spacing::Linear) v = (a * from + b * to) / n;
    else if (i > 0) v = std::exp((a * std::log(from) + b * std::log(to)) / n);
    values.push_back(numberValue(v, spec.kind));
  }
  if (spec.kind == ParamKind::Integer) {
    std::set<long long> distinct;
    for (const auto& v : values) distinct.insert(v.get<long long>());
    if (distinct.size() < values.size())
      errors.push_back({where + ".count", std::to_string(count),
                        "gives repeated whole numbers for the integer parameter (" + countText(distinct.size()) +
                            " distinct); use a smaller count or a list"});
  }
  return values;
}

// One parameter of a design: refuses a second entry for the same path ("x" and "parameters.x").
bool addParameter(const ParamSpec& spec, const std::string& where, Study& study, std::vector<FieldError>& errors) {
  for (const auto& p : study.parameters)
    if (p.path == spec.path) {
      errors.push_back({where, "", "varies " + spec.path + " a second time"});
      return false;
    }
  study.parameters.push_back(studyParameter(spec));
  return true;
}

// Puts the parameters (and their columns of per-parameter data) in alphabetical order of path.
template <class T>
void sortByPath(Study& study, std::vector<T>& per_parameter) {
  std::vector<std::size_t> order(study.parameters.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return study.parameters[a].path < study.parameters[b].path; });
  std::vector<StudyParameter> parameters;
  std::vector<T> data;
  for (const auto i : order) {
    parameters.push_back(study.parameters[i]);
    data.push_back(per_parameter[i]);
  }
  study.parameters = std::move(parameters);
  per_parameter = std::move(data);
}

// Uniform in [0, 1) by core's portable draw (the one the seas' phases use): the same numbers on every platform
// (std::mt19937_64's sequence is fixed by the standard; std::uniform_real_distribution's mapping is not).
double uniform01(std::mt19937_64& engine) { return maris::uniform01(engine()); }

// Uniform in [0, n) without modulo bias (rejection of the incomplete last block).
std::uint64_t uniformBelow(std::mt19937_64& engine, std::uint64_t n) {
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t limit = max - max % n;
  for (;;) {
    const std::uint64_t r = engine();
    if (r < limit) return r % n;
  }
}

}  // namespace

std::optional<ParamSpec> lookupParameter(const SceneDefinition& scene, const Json& base, const std::string& raw,
                                         const std::string& where, std::vector<FieldError>& errors,
                                         bool whole_tables) {
  const std::string path = raw.rfind("parameters.", 0) == 0 ? raw.substr(11) : raw;
  bool is_cell = false;
  auto cell = lookupTableCell(scene, base, path, where, errors, is_cell);
  if (is_cell) return cell;
  const ParamSpec* spec = scene.schema.find(path);
  if (!spec) {
    std::vector<std::string> paths;
    for (const auto& f : scene.schema.fields) paths.push_back(f.path);
    const auto guess = didYouMean(path, paths);
    errors.push_back({where, "", "is not a parameter of scene '" + scene.name + "'" +
                                     (guess.empty() ? std::string() : "; did you mean '" + guess + "'?") +
                                     " (see `maris-cli schema " + scene.name + "`)"});
    return std::nullopt;
  }
  if (spec->kind == ParamKind::Table && !whole_tables) {
    errors.push_back({where, "", "is a table; a design varies single values, such as one cell (" + spec->path +
                                     "[0]." + (spec->columns.empty() ? std::string("COLUMN") : spec->columns[0].key()) +
                                     "), or \"set\" replaces the whole table"});
    return std::nullopt;
  }
  return *spec;
}

StudyParameter studyParameter(const ParamSpec& spec) {
  StudyParameter p;
  p.path = spec.path;
  p.unit = spec.unit;
  p.kind = spec.kind;
  p.label = parameterLabel(spec);
  return p;
}

Json numberValue(double value, ParamKind kind) {
  if (kind == ParamKind::Integer && std::abs(value) < 9e15) return Json(static_cast<long long>(std::llround(value)));
  return Json(value);
}

void readGrid(const Json& grid, const SceneDefinition& scene, Study& study, std::vector<FieldError>& errors) {
  study.kind = DesignKind::Grid;
  if (!grid.is_object() || grid.empty()) {
    errors.push_back({"grid", jsonSnippet(grid),
                      "must be an object of parameter paths, each with a list of values or {from, to, count, "
                      "spacing}"});
    return;
  }
  for (auto it = grid.begin(); it != grid.end(); ++it) {
    const std::string where = "grid." + it.key();
    const auto spec = lookupParameter(scene, study.base.parameters, it.key(), where, errors);
    if (!spec) continue;
    std::vector<Json> values;
    if (it->is_array()) {
      if (it->empty()) errors.push_back({where, "[]", "needs at least one value"});
      values.assign(it->begin(), it->end());
    } else if (it->is_object() && isNumeric(spec->kind)) {
      values = rangeValues(*it, *spec, where, errors);
    } else {
      errors.push_back({where, jsonSnippet(*it),
                        isNumeric(spec->kind) ? "must be a list of values or {from, to, count, spacing}"
                                              : "must be a list of values (the parameter is not a number)"});
      continue;
    }
    if (addParameter(*spec, where, study, errors)) study.grid.push_back(std::move(values));
  }
  sortByPath(study, study.grid);
}

void readLatinHypercube(const Json& design, const SceneDefinition& scene, Study& study,
                        std::vector<FieldError>& errors) {
  study.kind = DesignKind::LatinHypercube;
  const std::string where = "latin_hypercube";
  if (!design.is_object()) {
    errors.push_back({where, jsonSnippet(design), "must be an object with count, seed and bounds"});
    return;
  }
  refuseUnknownKeys(design, {"count", "seed", "bounds"}, where, errors);
  study.sample_count = wholeNumber(design, "count", 1, StudyLimits::kCases, where, errors);
  const auto seed = design.find("seed");
  if (seed == design.end())
    errors.push_back({where + ".seed", "", "is missing: a whole number >= 0 (the same seed gives the same cases)"});
  else if (seed->is_number_unsigned() || (seed->is_number_integer() && seed->get<long long>() >= 0))
    study.seed = seed->get<std::uint64_t>();
  else
    errors.push_back({where + ".seed", jsonSnippet(*seed), "must be a whole number >= 0"});
  const auto bounds = design.find("bounds");
  if (bounds == design.end() || !bounds->is_object() || bounds->empty()) {
    errors.push_back({where + ".bounds", bounds == design.end() ? "" : jsonSnippet(*bounds),
                      "must be an object of parameter paths, each with [low, high] or {from, to, spacing}"});
    return;
  }
  for (auto it = bounds->begin(); it != bounds->end(); ++it) {
    const std::string at = where + ".bounds." + it.key();
    const auto spec = lookupParameter(scene, study.base.parameters, it.key(), at, errors);
    if (!spec) continue;
    if (!isNumeric(spec->kind)) {
      errors.push_back({at, "", "is not a number parameter; a Latin hypercube samples numbers"});
      continue;
    }
    SampleBounds b;
    const std::size_t before = errors.size();
    if (it->is_array() && it->size() == 2 && (*it)[0].is_number() && (*it)[1].is_number()) {
      b.low = (*it)[0].get<double>();
      b.high = (*it)[1].get<double>();
    } else if (it->is_object()) {
      refuseUnknownKeys(*it, {"from", "to", "spacing"}, at, errors);
      b.low = finiteNumber(*it, "from", at, errors);
      b.high = finiteNumber(*it, "to", at, errors);
      b.spacing = readSpacing(*it, at, errors);
    } else {
      errors.push_back({at, jsonSnippet(*it), "must be [low, high] or {from, to, spacing}"});
    }
    if (errors.size() > before) continue;
    if (!(std::isfinite(b.low) && std::isfinite(b.high) && b.low < b.high))
      errors.push_back({at, jsonSnippet(*it), "needs finite bounds with low < high"});
    else if (b.spacing == Spacing::Log && !(b.low > 0.0))
      errors.push_back({at, jsonSnippet(*it), "needs bounds > 0 for \"log\" spacing"});
    else if (addParameter(*spec, at, study, errors))
      study.bounds.push_back(b);
  }
  sortByPath(study, study.bounds);
}

std::vector<std::vector<Json>> latinHypercubeRows(const Study& study) {
  // Per parameter (in path order): a random permutation of the n strata (Fisher-Yates, from the last
  // position down), then one uniform point inside each case's stratum, so every parameter has exactly one
  // case in each of its n equal intervals.
  const std::size_t n = study.sample_count;
  std::vector<std::vector<Json>> rows(n, std::vector<Json>(study.parameters.size()));
  std::mt19937_64 engine(study.seed);
  for (std::size_t j = 0; j < study.parameters.size(); ++j) {
    std::vector<std::size_t> strata(n);
    for (std::size_t i = 0; i < n; ++i) strata[i] = i;
    for (std::size_t i = n; i-- > 1;) std::swap(strata[i], strata[uniformBelow(engine, i + 1)]);
    const SampleBounds& b = study.bounds[j];
    for (std::size_t i = 0; i < n; ++i) {
      const double u = (static_cast<double>(strata[i]) + uniform01(engine)) / static_cast<double>(n);
      const double v = b.spacing == Spacing::Log ? std::exp(std::log(b.low) + u * (std::log(b.high) - std::log(b.low)))
                                                 : b.low + u * (b.high - b.low);
      rows[i][j] = numberValue(std::clamp(v, b.low, b.high), study.parameters[j].kind);
    }
  }
  return rows;
}

}  // namespace maris::study::detail

namespace maris::study {

std::string displayLabel(const StudyParameter& parameter) {
  return parameter.label.empty() ? parameter.path : parameter.label;
}

}  // namespace maris::study
