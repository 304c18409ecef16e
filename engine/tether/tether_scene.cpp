#include "core/scene.hpp"
namespace maris {
struct TetherStubParameters { double x = 1.0; };
SceneDefinition makeTetherScene() {
  SchemaBinder<TetherStubParameters> b;
  b.real("x.x", &TetherStubParameters::x, "m", Range::positive(), "stub");
  return makeScene<TetherStubParameters>("tether", "Tether", "stub", b, nullptr, [](const TetherStubParameters&, RunContext&) { return Results{}; });
}
}
