// What a run returns: value types the CLI writes to disk and the GUI plots and draws.
// Every number carries its unit. Tables are the data behind plots; PlotSpec says how to plot
// them; View3D holds the geometry to draw per animation frame. Nothing here knows a scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/schema.hpp"

namespace maris {

// A key scalar result ("tip deflection", "max bending stress").
struct Scalar {
  std::string name;         // machine name, snake_case: "tip_deflection"
  double value = 0.0;
  std::string unit;         // "m", "Pa", "-"
  std::string description;  // one line for people
  std::string label;        // short name for people, with symbols: "Tip deflection", "σ_b", "C_W"; written where
                            // the result is made (empty: displayLabel falls back to the name)
};

struct Column {
  std::string name;  // "time", "tip_x"
  std::string unit;  // "s", "m", "-"
  std::vector<double> values;
  std::string label;  // for people: "Time", "Tip x", "Fn", "A*/D" (empty: displayLabel falls back to the name)
};

// What people read for a result: its label, or, where the scene declared none, the name made readable
// ("tip_x" as "Tip x"). CSV headers and summary.json keys stay the machine names.
std::string displayLabel(const Column& column);
std::string displayLabel(const Scalar& scalar);
// The fallback alone: underscores as spaces, the first letter capitalised.
std::string readableName(const std::string& name);

// A table of equally long columns: a time series, a field along arc length at chosen times,
// a spectrum, a resistance curve. Written as CSV: a row of names, a row of units, then data.
struct Table {
  std::string name;   // file stem, snake_case: "tip_history"
  std::string title;  // "Tip displacement history"
  std::vector<Column> columns;

  Column& add(std::string column_name, std::string unit, std::vector<double> values = {}, std::string label = {});
  const Column* find(const std::string& column_name) const;
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().values.size(); }
  std::string toCsv() const;
};

// How to plot a table: y columns against an x column.
struct PlotSpec {
  std::string name;                    // file stem for exports: "tip_displacement"
  std::string title;                   // "Tip displacement"
  std::string table;                   // Table::name
  std::string x;                       // column name on the x axis
  std::vector<std::string> y;          // column names on the y axis (same unit preferred)
  bool log_x = false;
  bool log_y = false;
  std::string reference_table;         // optional: a table of reference points drawn as markers
  std::vector<std::string> reference_y;  // its y columns (x column has the same name as `x`)
  bool operator==(const PlotSpec&) const = default;
};

// A plot of y columns against x from one table; the other fields (log_x, references) set afterwards.
PlotSpec makePlot(std::string name, std::string title, std::string table, std::string x, std::vector<std::string> y,
                  bool log_y = false);

// One drawable object. Coordinates in metres, z up, in the scene's global frame.
struct Shape3D {
  enum class Kind { Tube, Polyline, Sphere, Hemisphere, Box, Surface, Points };
  Kind kind = Kind::Tube;
  std::string name;                        // "riser", "float 1", "free surface"
  std::vector<Eigen::Vector3d> points;     // Tube/Polyline/Points: vertices; Sphere/Hemisphere/Box: [0] = centre;
                                           // Surface: grid_u × grid_v vertices, u fastest
  std::vector<double> scalars;             // optional, one per point, coloured with View3D's colour map
  double radius = 0.0;                     // Tube, Sphere, Hemisphere [m]
  Eigen::Vector3d direction{0, 0, -1};     // Hemisphere: from centre towards the pole; Box: unused
  Eigen::Vector3d size{1, 1, 1};           // Box edge lengths [m]
  int grid_u = 0, grid_v = 0;              // Surface grid size
  Eigen::Vector3d color{0.8, 0.8, 0.8};    // RGB in [0, 1], used when scalars are empty
  double opacity = 1.0;
};

struct Frame3D {
  double time = 0.0;  // [s] (mode shapes: mode index + phase / 2π, an ordering only)
  std::vector<Shape3D> shapes;
  std::string label;  // shown instead of "t = … s" when set ("mode 2: 9.21 rad/s, phase 90°")
};

struct View3D {
  std::vector<Frame3D> frames;   // one per animation step; a static result has one frame
  std::string scalar_name;       // what Shape3D::scalars mean: "bending stress"
  std::string scalar_unit;       // "Pa"
  std::optional<double> water_level_z;  // [m] still-water free surface, drawn as a translucent plane
  std::optional<double> seabed_z;       // [m] sea bed plane
  // Optional: the shapes the motion is measured from (a riser's static shape), drawn as a faint ghost. A
  // frame's shape with the same name, kind and point count can be drawn with its displacement from its
  // reference magnified (the view states the factor).
  std::vector<Shape3D> reference;
  bool empty() const { return frames.empty(); }
};

// Solver bookkeeping reported with every run.
struct SolverStats {
  long steps = 0;
  long rejected_steps = 0;
  long rhs_evaluations = 0;
  double wall_time_s = 0.0;
  double error_estimate = 0.0;  // the solver's own global error estimate, in `error_unit` (0 if none)
  std::string error_unit;
  std::string method;           // "RK4 h=1e-4 s", "Dormand-Prince 5(4) rtol=1e-6"
};

struct Results {
  std::vector<Scalar> scalars;
  std::vector<Table> tables;
  std::vector<PlotSpec> plots;
  View3D view;
  SolverStats stats;
  std::vector<std::string> warnings;

  const Table* findTable(const std::string& name) const;
  const Scalar* findScalar(const std::string& name) const;
  void addScalar(std::string name, double value, std::string unit, std::string description, std::string label = {});
};

// summary.json content: scalars with units (and labels, where declared), solver statistics and warnings.
Json summaryJson(const Results& results);

}  // namespace maris
