// Helpers shared by the riser tests: the scene's factory, one run of the solver, result columns and
// input-error lookups.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/run_context.hpp"
#include "core/scene.hpp"
#include "riser/riser_parameters.hpp"
#include "riser/riser_scene.hpp"

namespace maris {
// The riser scene as the catalog registers it (engine/riser/riser_scene.cpp).
SceneDefinition makeRiserScene();
}  // namespace maris

namespace maris::riser::test {

// One run of the solver with a fresh run context (never cancelled).
inline Results run(const RiserParameters& p) {
  RunContext context;
  return solveRiser(p, context);
}

// The values of column `name` of table `table`: the test fails, naming both, if there is none.
inline const std::vector<double>& column(const Results& r, const std::string& table, const std::string& name) {
  static const std::vector<double> kNone;
  const Table* t = r.findTable(table);
  const Column* c = t ? t->find(name) : nullptr;
  if (!c) ADD_FAILURE() << "no column " << table << "." << name;
  return c ? c->values : kNone;
}

// A column of the time history ("history" table).
inline const std::vector<double>& column(const Results& r, const std::string& name) {
  return column(r, "history", name);
}

inline bool hasErrorAt(const std::vector<FieldError>& errors, const std::string& path) {
  for (const auto& e : errors)
    if (e.path == path) return true;
  return false;
}

// The input errors the scene reports for `p`.
inline std::vector<FieldError> errorsOf(const RiserParameters& p) {
  return validateParameters(makeRiserScene(), riserBinder().write(p));
}

}  // namespace maris::riser::test
