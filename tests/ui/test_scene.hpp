// A small scene defined by the UI tests themselves, so the GUI is tested independently of the
// real scenes (which the engine helpers write concurrently). It has a field of every schema kind,
// a cross-field check, a solver that can be slowed down (to test progress, partial results and
// cancellation) or made to fail (to test error display), and results with tables, two plots (one
// with reference points), scalars and an animated 3D view (tube coloured by a scalar, sphere,
// water level, sea bed).
#pragma once

#include <memory>

#include "scene_library.hpp"

namespace maris::test {

// The test scene "rod"; its results: profile table (point_count rows), history table
// (frame_count × 10 rows), plots "deflection" and "tip_motion", 3D view with frame_count frames.
SceneDefinition makeRodScene();

// A library with the rod scene and two examples: "rod_default" and "rod_slow" (3 s run).
std::shared_ptr<const ui::SceneLibrary> rodLibrary();

// Results without a scene: a vertical tube from z = -length to 0 at x = y = 0, coloured along its
// length, nothing else (no water plane), for pixel checks of the 3D view.
Results verticalTubeResults(double length, double radius);

}  // namespace maris::test
