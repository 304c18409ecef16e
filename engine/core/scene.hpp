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
#include "core/work_estimate.hpp"

namespace maris {

// A group of plots a scene declares for front ends that group many plots (the GUI's plot list and group chooser):
// its title and its plots by name, in the order wanted. A name with one '*' matches every plot name that starts
// with the text before it and ends with the text after it ("envelope_*", "probe*_displacement").
struct PlotGroupSpec {
  std::string title;
  std::vector<std::string> plots;
  bool operator==(const PlotGroupSpec&) const = default;
};

// True when `plot_name` is one of `group`'s names or matches one of its patterns.
bool plotGroupHolds(const PlotGroupSpec& group, const std::string& plot_name);

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
  // Optional: the run's steps, unknowns, stored values, memory and output size, estimated from validated
  // parameters in well under a second (no solve). Front ends refuse a run beyond defaultWorkLimits() unless
  // the user allows a large run (workLimitErrors(estimateWork(...))); a scene without it is never refused.
  std::function<WorkEstimate(const Json& parameters)> estimate;
  // Optional: parameters that are valid but doubtful for what the model covers (a riser top in the air, a
  // current beyond the drag data, waves steeper than a wave can be), each as path (relative to "parameters"),
  // value and why. Never refuses a run: front ends show them before a run, and runScenario adds them to the
  // run's warnings. A built-in example that warns says why in its description.
  std::function<std::vector<FieldError>(const Json& parameters)> plausibility;
  // Optional: how its plots are grouped where a run has many (by what they show rather than by table). A plot in
  // no declared group is grouped with the other plots of its table; front ends know no plot by name.
  std::vector<PlotGroupSpec> plot_groups;
};

// Sets scene.estimate from a typed estimator over the scene's parameter struct.
template <class P>
void setWorkEstimate(SceneDefinition& scene, SchemaBinder<P> binder, std::function<WorkEstimate(const P&)> estimate) {
  scene.estimate = [binder, estimate](const Json& j) { return estimate(binder.read(j)); };
}

// Sets scene.plausibility from typed checks over the scene's parameter struct.
template <class P>
void setPlausibility(SceneDefinition& scene, SchemaBinder<P> binder, std::function<std::vector<FieldError>(const P&)> checks) {
  scene.plausibility = [binder, checks](const Json& j) { return checks(binder.read(j)); };
}

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

// The scene's estimate for these parameters (upgraded; all zero without an estimator or for invalid parameters).
WorkEstimate estimateWork(const SceneDefinition& scene, const Json& parameters);

// The scene's plausibility warnings for these parameters, paths prefixed with "parameters." (upgraded; none
// without checks or for invalid parameters, which have errors instead).
std::vector<FieldError> plausibilityWarnings(const SceneDefinition& scene, const Json& parameters);

// Upgrades a copy of the parameters (notes become warnings; so do plausibility warnings), validates (throws InputError with every
// problem), then runs. Fills stats.wall_time_s and warnings.
Results runScenario(const SceneDefinition& scene, const Scenario& scenario, RunContext& context);

// A scenario of `scene` with every parameter at its default.
Scenario defaultScenario(const SceneDefinition& scene);

}  // namespace maris
