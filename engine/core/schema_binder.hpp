// Binds a scene's plain parameter struct to its schema, so the struct's default member
// initialisers are the one source of defaults and JSON <-> struct conversion is generated:
//
//   struct PendulumParameters {
//     double length = 1.0;  // [m] rod length
//     int segment_count = 10;  // [-]
//   };
//   SchemaBinder<PendulumParameters> b;
//   b.real("geometry.length", &PendulumParameters::length, "m", Range::positive(1e4), "Rod length");
//   b.label("geometry.length", "Rod length L");  // what plots and study tables call it (optional)
//   PendulumParameters p = b.read(json);   // after validateAgainstSchema(b.schema(), json) passed
#pragma once

#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/schema.hpp"

namespace maris {

template <class P>
class SchemaBinder {
 public:
  void real(std::string path, double P::*member, std::string unit, Range range, std::string description) {
    add(makeSpec(std::move(path), ParamKind::Real, std::move(unit), range, std::move(description)), member);
  }
  void integer(std::string path, int P::*member, std::string unit, Range range, std::string description) {
    add(makeSpec(std::move(path), ParamKind::Integer, std::move(unit), range, std::move(description)), member);
  }
  void boolean(std::string path, bool P::*member, std::string description) {
    add(makeSpec(std::move(path), ParamKind::Boolean, "-", Range::any(), std::move(description)), member);
  }
  void choice(std::string path, std::string P::*member, std::vector<std::string> choices, std::string description) {
    auto spec = makeSpec(std::move(path), ParamKind::Choice, "-", Range::any(), std::move(description));
    spec.choices = std::move(choices);
    add(std::move(spec), member);
  }
  void text(std::string path, std::string P::*member, std::string description) {
    add(makeSpec(std::move(path), ParamKind::Text, "", Range::any(), std::move(description)), member);
  }
  // A data file or folder ("builtin:NAME" or a path): text that resolveDataPaths makes absolute.
  void dataPath(std::string path, std::string P::*member, std::string description) {
    auto spec = makeSpec(std::move(path), ParamKind::Text, "", Range::any(), std::move(description));
    spec.data_path = true;
    add(std::move(spec), member);
  }
  void realList(std::string path, std::vector<double> P::*member, std::string unit, Range element_range,
                std::size_t min_items, std::size_t max_items, std::string description) {
    auto spec = makeSpec(std::move(path), ParamKind::RealList, std::move(unit), element_range, std::move(description));
    spec.min_items = min_items;
    spec.max_items = max_items;
    add(std::move(spec), member);
  }
  // A table of rows of type R, each row described by its own binder (paths are the column keys).
  template <class R>
  void table(std::string path, std::vector<R> P::*member, const SchemaBinder<R>& row, std::size_t min_rows,
             std::size_t max_rows, std::string description) {
    auto spec = makeSpec(std::move(path), ParamKind::Table, "-", Range::any(), std::move(description));
    spec.columns = row.schema().fields;
    spec.min_items = min_rows;
    spec.max_items = max_rows;
    const P defaults{};
    spec.default_value = Json::array();
    for (const auto& r : defaults.*member) spec.default_value.push_back(row.write(r));
    const std::string p = spec.path;
    schema_.fields.push_back(std::move(spec));
    readers_.push_back([p, member, row](const Json& root, P& out) {
      const Json* rows = findAtPath(root, p);
      if (!rows) return;  // not validated (a field newer than the document): the default rows
      (out.*member).clear();
      for (const auto& j : *rows) (out.*member).push_back(row.read(j));
    });
    writers_.push_back([p, member, row](const P& in, Json& root) {
      Json arr = Json::array();
      for (const auto& r : in.*member) arr.push_back(row.write(r));
      setAtPath(root, p, std::move(arr));
    });
  }

  // The label for people of the field or column `path` declared above ("Length L"); a study's plots, legends
  // and tables name the parameter by it. A path not declared is a programming error (std::logic_error).
  void label(const std::string& path, std::string text) {
    for (auto& spec : schema_.fields)
      if (spec.path == path) {
        spec.label = std::move(text);
        return;
      }
    throw std::logic_error("SchemaBinder::label: no field " + path);
  }

  void labels(std::initializer_list<std::pair<const char*, const char*>> list) {
    for (const auto& [path, text] : list) label(path, text);
  }

  const Schema& schema() const { return schema_; }

  // Converts validated JSON to the struct (call validateAgainstSchema first; a field the JSON lacks keeps its
  // default, so an older document read without validation cannot crash).
  P read(const Json& parameters) const {
    P out{};
    for (const auto& r : readers_) r(parameters, out);
    return out;
  }
  Json write(const P& in) const {
    Json root = Json::object();
    for (const auto& w : writers_) w(in, root);
    return root;
  }

 private:
  static ParamSpec makeSpec(std::string path, ParamKind kind, std::string unit, Range range, std::string description) {
    ParamSpec s;
    s.path = std::move(path);
    s.kind = kind;
    s.unit = std::move(unit);
    s.range = range;
    s.description = std::move(description);
    return s;
  }

  template <class T>
  void add(ParamSpec spec, T P::*member) {
    const P defaults{};
    spec.default_value = Json(defaults.*member);
    const std::string p = spec.path;
    schema_.fields.push_back(std::move(spec));
    readers_.push_back([p, member](const Json& root, P& out) {
      if (const Json* value = findAtPath(root, p)) out.*member = value->get<T>();  // absent: the default
    });
    writers_.push_back([p, member](const P& in, Json& root) { setAtPath(root, p, Json(in.*member)); });
  }

  Schema schema_;
  std::vector<std::function<void(const Json&, P&)>> readers_;
  std::vector<std::function<void(const P&, Json&)>> writers_;
};

}  // namespace maris
