// A scene is a study type (riser dynamics, ship resistance, ...). Its registry entry is the
// seam between the engine, the CLI and the GUI: name, schema, validation and the solver entry
// point. The CLI and GUI never know a scene by name; they iterate the catalog.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/results.hpp"
#include "core/run_context.hpp"
#include "core/scenario.hpp"
#include "core/schema_binder.hpp"

namespace maris {

struct SceneDefinition {
  std::string name;         // registry key used in scenario files: "riser"
  std::string title;        // "Riser / cable dynamics"
  std::string description;  // one paragraph: what it models, its source paper
  Schema schema;
  // Cross-field checks (e.g. inner diameter < outer diameter) on parameters that passed the schema.
  // Paths are relative to "parameters".
  std::function<std::vector<FieldError>(const Json& parameters)> check;
  // Runs the solver on validated parameters. Throws SolverError or RunCancelled.
  std::function<Results(const Json& parameters, RunContext& context)> run;
  // Optional: rewrites parameters written for an earlier version of this scene's schema (a renamed or
  // replaced field) in place and returns one note per change. Scenario files keep loading after a
  // schema change without a new "maris-scenario/N" format; empty when the schema never changed.
  std::function<std::vector<std::string>(Json& parameters)> upgrade;
};

// Builds a type-erased scene from a typed parameter struct P, its binder, a checker and a solver.
template <class P>
SceneDefinition makeScene(std::string name, std::string title, std::string description, SchemaBinder<P> binder,
                          std::function<std::vector<FieldError>(const P&)> check,
                          std::function<Results(const P&, RunContext&)> solve) {
  SceneDefinition s;
  s.name = std::move(name);
  s.title = std::move(title);
  s.description = std::move(description);
  s.schema = binder.schema();
  s.check = [binder, check](const Json& j) { return check ? check(binder.read(j)) : std::vector<FieldError>{}; };
  s.run = [binder, solve](const Json& j, RunContext& ctx) { return solve(binder.read(j), ctx); };
  return s;
}

// Applies scene.upgrade to `parameters` (no-op without one). Returns the notes (what was rewritten).
// Call it where a scenario is read (file, built-in, GUI document) so edits and saves see the new fields.
std::vector<std::string> upgradeParameters(const SceneDefinition& scene, Json& parameters);

// Every error of the scenario's parameters (schema first, then the scene's cross-field checks),
// judged after upgradeParameters on a copy, so an old file is as valid as it runs.
std::vector<FieldError> validateParameters(const SceneDefinition& scene, const Json& parameters);

// Upgrades a copy of the parameters (notes become warnings), validates (throws InputError with every
// problem), then runs. Fills stats.wall_time_s and warnings.
Results runScenario(const SceneDefinition& scene, const Scenario& scenario, RunContext& context);

// A scenario of `scene` with every parameter at its default.
Scenario defaultScenario(const SceneDefinition& scene);

}  // namespace maris
