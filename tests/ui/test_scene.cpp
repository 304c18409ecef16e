#include "test_scene.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include "core/errors.hpp"

namespace maris::test {

namespace {

struct SectionRow {
  double length = 50.0;         // [m]
  double outer_diameter = 0.5;  // [m]
};

struct RodParameters {
  double length = 100.0;                      // [m] rod length
  double radius = 0.5;                        // [m] drawn radius
  int point_count = 50;                       // [-] points along the rod
  int frame_count = 10;                       // [-] animation frames
  double delay = 0.0;                         // [s] wall time the solver spends (to test cancelling)
  bool fail = false;                          // make the solver fail half way
  std::string method = "joint";               // coordinates
  std::vector<double> amplitudes{1.0, 0.5};   // [m] mode amplitudes
  std::vector<SectionRow> sections{SectionRow{}, SectionRow{50.0, 0.4}};
};

SchemaBinder<RodParameters> rodBinder() {
  SchemaBinder<SectionRow> row;
  row.real("length", &SectionRow::length, "m", Range::positive(1e4), "Section length");
  row.real("outer_diameter", &SectionRow::outer_diameter, "m", Range::positive(10.0), "Outer diameter");
  SchemaBinder<RodParameters> b;
  b.real("geometry.length", &RodParameters::length, "m", Range::positive(1000.0), "Rod length");
  b.real("geometry.radius", &RodParameters::radius, "m", Range::positive(10.0), "Drawn radius of the rod");
  b.integer("discretisation.point_count", &RodParameters::point_count, "-", Range::closed(2, 10000), "Points along the rod");
  b.integer("discretisation.frame_count", &RodParameters::frame_count, "-", Range::closed(1, 500), "Animation frames");
  b.real("run.delay", &RodParameters::delay, "s", Range::closed(0.0, 60.0), "Wall time the solver spends");
  b.boolean("run.fail", &RodParameters::fail, "Make the solver fail half way");
  b.choice("run.method", &RodParameters::method, {"joint", "absolute"}, "Coordinates");
  b.realList("loads.amplitudes", &RodParameters::amplitudes, "m", Range::any(), 1, 10, "Mode amplitudes");
  row.label("outer_diameter", "Outer diameter D");
  b.table("sections", &RodParameters::sections, row, 1, 20, "Sections from the top");
  // Labels for people (study plots, legends and tables); the other fields fall back to their keys.
  b.labels({{"geometry.length", "Length L"}, {"geometry.radius", "Radius r"}, {"sections", "section"}});
  return b;
}

std::vector<FieldError> checkRod(const RodParameters& p) {
  if (2.0 * p.radius >= p.length)
    return {{"geometry.radius", std::to_string(p.radius), "must be less than half the length"}};
  return {};
}

double deflection(const RodParameters& p, double s, double t) {
  double d = 0.0;
  for (std::size_t k = 0; k < p.amplitudes.size(); ++k)
    d += p.amplitudes[k] * std::sin((k + 1) * M_PI * s / p.length) * std::cos(2.0 * M_PI * (k + 1) * t);
  return d;
}

Frame3D rodFrame(const RodParameters& p, double t) {
  Frame3D frame;
  frame.time = t;
  Shape3D tube;
  tube.kind = Shape3D::Kind::Tube;
  tube.name = "rod";
  tube.radius = p.radius;
  for (int i = 0; i < p.point_count; ++i) {
    const double s = p.length * i / (p.point_count - 1);
    tube.points.emplace_back(deflection(p, s, t), 0.0, -s);
    tube.scalars.push_back(std::abs(deflection(p, s, t)) * 1e6);
  }
  Shape3D ball;
  ball.kind = Shape3D::Kind::Sphere;
  ball.name = "end mass";
  ball.radius = 3.0 * p.radius;
  ball.points.push_back(tube.points.back());
  ball.color = {0.9, 0.6, 0.1};
  frame.shapes = {tube, ball};
  return frame;
}

Results solveRod(const RodParameters& p, RunContext& ctx) {
  Results r;
  std::vector<double> arc, defl;
  for (int i = 0; i < p.point_count; ++i) {
    arc.push_back(p.length * i / (p.point_count - 1));
    defl.push_back(deflection(p, arc.back(), 0.0));
  }
  double max_d = 0.0;
  for (double v : defl) max_d = std::max(max_d, std::abs(v));
  Table profile;
  profile.name = "profile";
  profile.title = "Deflection along the rod";
  profile.add("arc_length", "m", arc);
  profile.add("deflection", "m", defl);
  r.tables.push_back(std::move(profile));
  r.plots.push_back({"deflection", "Deflection", "profile", "arc_length", {"deflection"}, false, false, "reference",
                     {"deflection"}});
  Table ref;
  ref.name = "reference";
  ref.title = "Reference";
  ref.add("arc_length", "m", {0.0, p.length / 2, p.length});
  ref.add("deflection", "m", {0.0, deflection(p, p.length / 2, 0.0), 0.0});
  r.tables.push_back(std::move(ref));
  r.plots.push_back({"tip_motion", "Tip motion", "history", "time", {"tip_x", "mid_x"}, false, false, "", {}});

  // The "time integration": history rows and frames, slowed to `delay` seconds of wall time.
  const int rows = p.frame_count * 10;
  Table history;
  history.name = "history";
  history.title = "Tip history";
  history.add("time", "s");
  history.add("tip_x", "m");
  history.add("mid_x", "m");
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < rows; ++i) {
    const double t = static_cast<double>(i) / rows;
    history.columns[0].values.push_back(t);
    history.columns[1].values.push_back(deflection(p, p.length, t) + p.amplitudes[0] * t);
    history.columns[2].values.push_back(deflection(p, p.length / 2, t));
    if (i % 10 == 0) r.view.frames.push_back(rodFrame(p, t));
    if (p.fail && i == rows / 2) throw SolverError("node 3 displacement", t, i, "became non-finite (nan)");
    // Spend this row's share of the delay in 1 ms slices, polling for cancellation.
    const auto until = start + std::chrono::duration<double>(p.delay * (i + 1) / rows);
    while (std::chrono::steady_clock::now() < until) {
      ctx.throwIfCancelled();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ctx.throwIfCancelled();
    ctx.progress(static_cast<double>(i + 1) / rows, "time integration");
    if (ctx.wantsPartialResults()) {
      auto partial = std::make_shared<Results>(r);
      partial->tables.push_back(history);
      ctx.publishPartial(partial);
    }
  }
  r.tables.push_back(std::move(history));
  r.view.scalar_name = "bending_stress";
  r.view.scalar_unit = "Pa";
  r.view.water_level_z = 0.0;
  r.view.seabed_z = -p.length - 10.0;
  r.addScalar("max_deflection", max_d, "m", "Largest deflection along the rod at t = 0");
  // Closed form in both geometry fields, so a study's plot can be checked value by value.
  r.addScalar("rod_volume", M_PI * p.radius * p.radius * p.length, "m^3", "Volume of the drawn rod, pi r^2 L");
  r.stats.method = "closed form";
  r.stats.steps = rows;
  if (p.method == "absolute") ctx.warn("absolute coordinates are only a label in the test scene");
  return r;
}

}  // namespace

SceneDefinition makeRodScene() {
  SceneDefinition scene = makeScene<RodParameters>("rod", "Test rod", "A rod with a closed-form deflection, for UI tests.",
                                                   rodBinder(), checkRod, solveRod);
  // An older spelling, so the UI tests exercise SceneDefinition::upgrade: geometry.span became geometry.length.
  scene.upgrade = [](Json& parameters) {
    std::vector<std::string> notes;
    Json& geometry = parameters["geometry"];
    if (geometry.is_object() && geometry.contains("span")) {
      geometry["length"] = geometry["span"];
      geometry.erase("span");
      notes.push_back("geometry.span is now geometry.length");
    }
    return notes;
  };
  return scene;
}

std::shared_ptr<const ui::SceneLibrary> rodLibrary() {
  auto library = std::make_shared<ui::SceneLibrary>();
  library->scenes.push_back(makeRodScene());
  BuiltinScenario basic{"rod_default", defaultScenario(library->scenes.front())};
  basic.scenario.name = "Rod, default";
  BuiltinScenario slow{"rod_slow", defaultScenario(library->scenes.front())};
  slow.scenario.name = "Rod, slow run";
  slow.scenario.parameters["run"]["delay"] = 3.0;
  library->examples = {basic, slow};
  return library;
}

Results verticalTubeResults(double length, double radius) {
  Results r;
  Frame3D frame;
  Shape3D tube;
  tube.kind = Shape3D::Kind::Tube;
  tube.radius = radius;
  for (int i = 0; i <= 20; ++i) {
    tube.points.emplace_back(0.0, 0.0, -length * i / 20.0);
    tube.scalars.push_back(i);
  }
  frame.shapes.push_back(tube);
  r.view.frames.push_back(frame);
  r.view.scalar_name = "index";
  r.view.scalar_unit = "-";
  return r;
}

}  // namespace maris::test
