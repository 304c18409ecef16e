// PEER strong-motion records (.AT2: the PEER NGA database and its predecessor): header lines (title, event and
// station, "ACCELERATION TIME HISTORY IN UNITS OF G"), a line with the number of points and the step, either
//   NPTS=  1800, DT= .02000 SEC        or        4094    0.0100    NPTS, DT
// then the accelerations in g, several per line. They are converted to m/s² with standard gravity
// g = 9.80665 m/s² (the value the records are defined with, CGPM 1901).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace maris::formats {

inline constexpr double kStandardGravity = 9.80665;  // [m/s²]

struct PeerRecord {
  std::string title;                  // the header line naming event, station and component
  double dt = 0.0;                    // [s]
  std::vector<double> acceleration;   // [m/s²], NPTS values
};

// Throws InputError(field, "file", "line N: ...") when the header or a value is missing or malformed, or when
// the number of values differs from NPTS.
PeerRecord parsePeerAt2(std::string_view text, const std::string& field, const std::string& file);

}  // namespace maris::formats
