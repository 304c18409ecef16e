#include "riser/riser_labels.hpp"
#include "riser/riser_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace maris::riser {

void addEnvelope(const RiserModel& model, Results& results) {
  const Table* nodes = results.findTable("node_positions");
  if (nodes == nullptr) return;
  const auto& time = nodes->find("time")->values;
  const auto& x = nodes->find("x")->values;
  const auto& y = nodes->find("y")->values;
  const auto& z = nodes->find("z")->values;
  const std::size_t per_frame = static_cast<std::size_t>(model.n + 2);
  const std::size_t frames = time.size() / per_frame;
  if (frames < 3) return;
  auto point = [&](std::size_t frame, std::size_t node) {
    const std::size_t r = frame * per_frame + node;
    return Vec3(x[r], y[r], z[r]);
  };
  const double t_end = time.back();
  std::vector<double> arc(per_frame), displacement(per_frame, 0.0), curvature(per_frame, 0.0);
  for (std::size_t k = 0; k < per_frame; ++k) arc[k] = nodes->find("arc_length")->values[k];
  for (std::size_t f = 1; f < frames; ++f) {
    if (time[f * per_frame] < 0.5 * t_end) continue;
    for (std::size_t k = 0; k < per_frame; ++k) {
      displacement[k] = std::max(displacement[k], (point(f, k) - point(0, k)).norm());
      if (k == 0 || k + 1 == per_frame) continue;
      // Bend angle at joint k between the chords of segments k-1 and k, change from the static shape.
      auto bend = [&](std::size_t g) {
        const Vec3 a = (point(g, k) - point(g, k - 1)).normalized(), b = (point(g, k + 1) - point(g, k)).normalized();
        return std::atan2(a.cross(b).norm(), a.dot(b));
      };
      curvature[k] = std::max(curvature[k], std::abs(bend(f) - bend(0)) / model.element_length);
    }
  }
  Table t;
  t.name = "envelope";
  t.title = "Amplitude envelopes along the riser (second half of the run)";
  t.add("arc_length", "m", arc, riserColumnLabel("arc_length"));
  t.add("displacement_amplitude", "m", displacement, riserColumnLabel("displacement_amplitude"));
  t.add("curvature_amplitude", "1/m", curvature, riserColumnLabel("curvature_amplitude"));
  results.tables.push_back(std::move(t));
  for (const char* c : {"displacement_amplitude", "curvature_amplitude"}) {
    PlotSpec p;
    p.name = std::string("envelope_") + c;
    p.title = "Envelope: " + riserColumnLabel(c);
    p.table = "envelope";
    p.x = "arc_length";
    p.y = {c};
    results.plots.push_back(std::move(p));
  }
}

}  // namespace maris::riser
