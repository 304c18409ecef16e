#include "core/schema.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/results.hpp"
#include "core/text_format.hpp"

namespace maris {

const char* toString(ParamKind kind) {
  switch (kind) {
    case ParamKind::Real: return "number";
    case ParamKind::Integer: return "integer";
    case ParamKind::Boolean: return "boolean";
    case ParamKind::Choice: return "choice";
    case ParamKind::Text: return "text";
    case ParamKind::RealList: return "list of numbers";
    case ParamKind::Table: return "table";
  }
  return "?";
}

static std::string formatNumber(double v) { return formatText("%.6g", v); }

bool Range::contains(double v) const {
  if (std::isnan(v)) return false;
  if (min_open ? !(v > min) : !(v >= min)) return false;
  if (max_open ? !(v < max) : !(v <= max)) return false;
  return true;
}

std::string Range::str() const {
  const bool lo = std::isfinite(min), hi = std::isfinite(max);
  if (!lo && !hi) return "any finite number";
  if (lo && !hi) return (min_open ? "> " : ">= ") + formatNumber(min);
  if (!lo && hi) return (max_open ? "< " : "<= ") + formatNumber(max);
  return std::string(min_open ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) + (max_open ? ")" : "]");
}

std::string ParamSpec::group() const {
  const auto dot = path.find('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string ParamSpec::key() const {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string parameterLabel(const ParamSpec& spec) { return spec.label.empty() ? readableName(spec.key()) : spec.label; }

std::string tableCellLabel(const ParamSpec& table, const ParamSpec& column, std::size_t row) {
  std::string table_name = table.label;
  if (table_name.empty()) {
    table_name = table.key();
    std::replace(table_name.begin(), table_name.end(), '_', ' ');
  }
  return parameterLabel(column) + " of " + table_name + " row " + std::to_string(row + 1);
}

const ParamSpec* Schema::find(const std::string& path) const {
  for (const auto& f : fields)
    if (f.path == path) return &f;
  return nullptr;
}

Json Schema::defaults() const {
  Json root = Json::object();
  for (const auto& f : fields) setAtPath(root, f.path, f.default_value);
  return root;
}

static std::vector<std::string> splitPath(const std::string& dotted) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(dotted);
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

const Json* findAtPath(const Json& root, const std::string& dotted_path) {
  const Json* node = &root;
  for (const auto& part : splitPath(dotted_path)) {
    if (!node->is_object()) return nullptr;
    auto it = node->find(part);
    if (it == node->end()) return nullptr;
    node = &*it;
  }
  return node;
}

void setAtPath(Json& root, const std::string& dotted_path, Json value) {
  Json* node = &root;
  for (const auto& part : splitPath(dotted_path)) {
    if (!node->is_object()) *node = Json::object();
    node = &(*node)[part];
  }
  *node = std::move(value);
}

static std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(3, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    // Compare the last path components too, so "geometry.lenght" suggests "geometry.length".
    const auto d = editDistance(word, c);
    if (d < best_d) { best_d = d; best = c; }
  }
  return best;
}

// Appends the JSON text of `value` to `out`, stopping once `out` is past `budget` characters, so a huge
// or deeply nested value costs no more than the snippet (no full dump, bounded recursion).
static void appendSnippet(const Json& value, std::string& out, std::size_t budget, int depth) {
  if (out.size() > budget) return;
  if (depth > 8) {
    out += value.is_array() ? "[...]" : value.is_object() ? "{...}" : "...";
    return;
  }
  if (value.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = value.begin(); it != value.end() && out.size() <= budget; ++it) {
      out += first ? "" : ",";
      first = false;
      appendSnippet(Json(it.key().substr(0, budget)), out, budget, depth + 1);
      out += ':';
      appendSnippet(it.value(), out, budget, depth + 1);
    }
    out += '}';
  } else if (value.is_array()) {
    out += '[';
    for (std::size_t i = 0; i < value.size() && out.size() <= budget; ++i) {
      out += i ? "," : "";
      appendSnippet(value[i], out, budget, depth + 1);
    }
    out += ']';
  } else if (value.is_string()) {
    out += Json(value.get_ref<const std::string&>().substr(0, budget)).dump(-1, ' ', false, Json::error_handler_t::replace);
  } else {
    out += value.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

std::string jsonSnippet(const Json& value) {
  std::string text;
  appendSnippet(value, text, 60, 0);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

namespace {

// Checks one value against one spec; appends errors with the given full path.
void checkValue(const ParamSpec& spec, const Json& v, const std::string& path, std::vector<FieldError>& errors);

void checkNumber(const ParamSpec& spec, const Json& v, const std::string& path, std::vector<FieldError>& errors,
                 bool integer) {
  const std::string unit = spec.unit.empty() || spec.unit == "-" ? "" : " " + spec.unit;
  if (!v.is_number()) {
    // nlohmann parses NaN/Infinity as invalid JSON, but a string "nan" may sneak in.
    errors.push_back({path, jsonSnippet(v), std::string("must be ") + (integer ? "an integer" : "a number") +
                                                " in " + spec.range.str() + unit});
    return;
  }
  const double x = v.get<double>();
  if (!std::isfinite(x)) {
    errors.push_back({path, jsonSnippet(v), "must be a finite number in " + spec.range.str() + unit});
    return;
  }
  if (integer && (!v.is_number_integer() && std::floor(x) != x)) {
    errors.push_back({path, jsonSnippet(v), "must be a whole number in " + spec.range.str() + unit});
    return;
  }
  if (!spec.range.contains(x))
    errors.push_back({path, jsonSnippet(v), "must be in " + spec.range.str() + unit});
}

void checkTable(const ParamSpec& spec, const Json& v, const std::string& path, std::vector<FieldError>& errors) {
  if (!v.is_array()) {
    errors.push_back({path, jsonSnippet(v), "must be a table (a JSON array of rows)"});
    return;
  }
  if (v.size() < spec.min_items || v.size() > spec.max_items) {
    errors.push_back({path, std::to_string(v.size()) + " rows",
                      "must have between " + std::to_string(spec.min_items) + " and " +
                          std::to_string(spec.max_items) + " rows"});
  }
  std::vector<std::string> names;
  for (const auto& c : spec.columns) names.push_back(c.path);
  for (std::size_t r = 0; r < v.size(); ++r) {
    const std::string row_path = path + "[" + std::to_string(r) + "]";
    const Json& row = v[r];
    if (!row.is_object()) {
      errors.push_back({row_path, jsonSnippet(row), "must be an object with fields " + [&] {
                          std::string s;
                          for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
                          return s;
                        }()});
      continue;
    }
    for (const auto& c : spec.columns) {
      auto it = row.find(c.path);
      if (it == row.end())
        errors.push_back({row_path + "." + c.path, "", std::string("is missing (") + toString(c.kind) +
                                                           (c.unit.empty() || c.unit == "-" ? "" : " in " + c.unit) +
                                                           ")"});
      else
        checkValue(c, *it, row_path + "." + c.path, errors);
    }
    for (auto it = row.begin(); it != row.end(); ++it) {
      if (std::find(names.begin(), names.end(), it.key()) != names.end()) continue;
      const auto guess = didYouMean(it.key(), names);
      errors.push_back({row_path + "." + it.key(), jsonSnippet(it.value()),
                        "unknown field" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
    }
  }
}

void checkValue(const ParamSpec& spec, const Json& v, const std::string& path, std::vector<FieldError>& errors) {
  switch (spec.kind) {
    case ParamKind::Real: checkNumber(spec, v, path, errors, false); break;
    case ParamKind::Integer: checkNumber(spec, v, path, errors, true); break;
    case ParamKind::Boolean:
      if (!v.is_boolean()) errors.push_back({path, jsonSnippet(v), "must be true or false"});
      break;
    case ParamKind::Choice: {
      std::string allowed;
      for (const auto& c : spec.choices) allowed += (allowed.empty() ? "" : ", ") + ("\"" + c + "\"");
      if (!v.is_string() || std::find(spec.choices.begin(), spec.choices.end(), v.get<std::string>()) ==
                                spec.choices.end())
        errors.push_back({path, jsonSnippet(v), "must be one of " + allowed});
      break;
    }
    case ParamKind::Text:
      if (!v.is_string()) errors.push_back({path, jsonSnippet(v), "must be a text string"});
      break;
    case ParamKind::RealList: {
      if (!v.is_array()) {
        errors.push_back({path, jsonSnippet(v), "must be a list of numbers"});
        break;
      }
      if (v.size() < spec.min_items || v.size() > spec.max_items)
        errors.push_back({path, jsonSnippet(v), "must have between " + std::to_string(spec.min_items) + " and " +
                                                    std::to_string(spec.max_items) + " entries"});
      for (std::size_t i = 0; i < v.size(); ++i)
        checkNumber(spec, v[i], path + "[" + std::to_string(i) + "]", errors, false);
      break;
    }
    case ParamKind::Table: checkTable(spec, v, path, errors); break;
  }
}

// Walks the JSON objects and reports every key that is neither a field nor a group of fields.
void findUnknown(const Json& node, const std::string& rel, const std::set<std::string>& leaves,
                 const std::set<std::string>& groups, const std::vector<std::string>& all_paths,
                 const std::string& prefix, std::vector<FieldError>& errors) {
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string p = rel.empty() ? it.key() : rel + "." + it.key();
    if (leaves.count(p)) continue;
    if (groups.count(p)) {
      if (it.value().is_object())
        findUnknown(it.value(), p, leaves, groups, all_paths, prefix, errors);
      else
        errors.push_back({prefix + "." + p, jsonSnippet(it.value()), "must be an object (a group of fields)"});
      continue;
    }
    const auto guess = didYouMean(p, all_paths);
    errors.push_back({prefix + "." + p, jsonSnippet(it.value()),
                      "unknown field" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
  }
}

}  // namespace

std::vector<FieldError> validateAgainstSchema(const Schema& schema, const Json& parameters, const std::string& prefix) {
  std::vector<FieldError> errors;
  if (!parameters.is_object()) {
    errors.push_back({prefix, jsonSnippet(parameters), "must be a JSON object of parameters"});
    return errors;
  }
  std::set<std::string> leaves, groups;
  std::vector<std::string> all_paths;
  for (const auto& f : schema.fields) {
    leaves.insert(f.path);
    all_paths.push_back(f.path);
    for (auto dot = f.path.find('.'); dot != std::string::npos; dot = f.path.find('.', dot + 1))
      groups.insert(f.path.substr(0, dot));
  }
  for (const auto& f : schema.fields) {
    const Json* v = findAtPath(parameters, f.path);
    const std::string full = prefix + "." + f.path;
    if (!v) {
      errors.push_back({full, "", std::string("is missing (") + toString(f.kind) +
                                      (f.unit.empty() || f.unit == "-" ? "" : " in " + f.unit) +
                                      ", default " + jsonSnippet(f.default_value) + ")"});
      continue;
    }
    checkValue(f, *v, full, errors);
  }
  findUnknown(parameters, "", leaves, groups, all_paths, prefix, errors);
  return errors;
}

static std::string describeSpec(const ParamSpec& f, const std::string& indent) {
  std::ostringstream out;
  out << indent << f.path << "  [" << (f.unit.empty() ? "text" : f.unit) << "]  " << toString(f.kind);
  if (f.kind == ParamKind::Real || f.kind == ParamKind::Integer || f.kind == ParamKind::RealList)
    out << " in " << f.range.str();
  if (f.kind == ParamKind::Choice) {
    out << " one of {";
    for (std::size_t i = 0; i < f.choices.size(); ++i) out << (i ? ", " : "") << f.choices[i];
    out << "}";
  }
  if (f.kind != ParamKind::Table) out << ", default " << jsonSnippet(f.default_value);
  out << "\n" << indent << "    " << f.description << "\n";
  for (const auto& c : f.columns) out << describeSpec(c, indent + "    | ");
  return out.str();
}

std::string describeSchema(const Schema& schema) {
  std::string text, group = "\x01";
  for (const auto& f : schema.fields) {
    if (f.group() != group) {
      group = f.group();
      text += "\n[" + (group.empty() ? std::string("general") : group) + "]\n";
    }
    text += describeSpec(f, "  ");
  }
  return text;
}

static Json specToJson(const ParamSpec& f) {
  Json j;
  j["path"] = f.path;
  j["kind"] = toString(f.kind);
  j["unit"] = f.unit;
  j["description"] = f.description;
  if (!f.label.empty()) j["label"] = f.label;
  j["default"] = f.default_value;
  if (f.kind == ParamKind::Real || f.kind == ParamKind::Integer || f.kind == ParamKind::RealList) {
    j["range"] = f.range.str();
    if (std::isfinite(f.range.min)) j["min"] = f.range.min;
    if (std::isfinite(f.range.max)) j["max"] = f.range.max;
    j["min_exclusive"] = f.range.min_open;
    j["max_exclusive"] = f.range.max_open;
  }
  if (!f.choices.empty()) j["choices"] = f.choices;
  if (f.data_path) j["data_path"] = true;
  if (!f.columns.empty()) {
    j["columns"] = Json::array();
    for (const auto& c : f.columns) j["columns"].push_back(specToJson(c));
  }
  return j;
}

Json schemaToJson(const Schema& schema) {
  Json arr = Json::array();
  for (const auto& f : schema.fields) arr.push_back(specToJson(f));
  return arr;
}

}  // namespace maris
