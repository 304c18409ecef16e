// The command line of `maris`: which scenario to open and, for `--screenshot`, what the picture
// shows (3D frame, colour map, plot tab, window size, theme). Parsed with CLI11 under the conventions
// both executables share (app/cli_conventions.hpp: --help, --version, usage errors, exit codes).
// Parsing needs no display, so `maris --help`, `--version` and mistakes in the options are answered
// before Qt opens one; the values that depend on a run's results (a frame number, a time, a plot's
// name) are checked against them once the run has finished.
#pragma once

#include <optional>

#include <QString>
#include <QStringList>

#include "view3d/color_maps.hpp"

namespace maris::ui {

class MainWindow;

struct CommandLine {
  QString scenario;                     // a scenario file or a built-in scenario's id ("" = default)
  QString screenshot;                   // PNG file to write ("" = the interactive application)
  QString theme;                        // "light", "dark", "system" or "" (the remembered one)
  int width = 1600, height = 1000;      // [px] window size for --screenshot
  std::optional<int> frame;             // 3D frame, counted from 1 as the time label does
  std::optional<double> time;           // [s] the 3D frame nearest to this time
  QString tab;                          // plot tab: a plot's name or its tab title
  std::optional<ColorMap> color_map;    // colour map of the 3D view's coloured quantity
};

struct ParsedCommandLine {
  CommandLine options;
  std::optional<int> exit_code;  // set: do not start; print `output` or `error` and exit with this code
  QString output;                // the text of --help or --version (stdout; exit code 0)
  QString error;                 // a usage error (exit code 1), naming the option; "" if none
};

// `arguments` without the program name. An unknown option, a missing value, a value out of its
// allowed set or range is an error that names the option, the value and what is allowed
// ("--colormap pink: must be one of cool-warm, viridis, rainbow, greyscale").
ParsedCommandLine parseCommandLine(const QStringList& arguments);

// The text of `maris --help` (generated from the options).
QString commandLineHelp();

// Shows what `options` ask for in `window` after a run: the 3D frame (--frame or --time), the
// colour map, the plot tab. Returns "" or an error naming the option and the values this run
// allows ("--tab stress: no such plot; the plots are probe_displacement, top_force, ...").
QString applyViewOptions(MainWindow& window, const CommandLine& options);

}  // namespace maris::ui
