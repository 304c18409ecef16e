// Plots in groups, for scenes with many of them (a riser run has about 14): the plot panel then shows a group
// chooser beside the tab bar and only the chosen group's tabs, so the tab bar fits a 1366-pixel screen and every
// plot stays two clicks away. A scene may declare its groups in its registry entry (SceneDefinition::plot_groups:
// a title and plot names); a plot in none of them, or of a scene that declares none, is in the group of the table
// it draws from, named by the table's title (the scene writes it where it makes the table), so "Probe points, end
// reactions and energies over time" holds the probe, top-force, energy and stress histories.
#pragma once

#include <string>
#include <vector>

#include <QString>

#include "core/results.hpp"
#include "core/scene.hpp"

namespace maris::ui {

// Plots are grouped only when there are more than this many of them (and they come from two or more tables).
inline constexpr int kUngroupedPlotLimit = 6;

struct PlotGroup {
  std::string table;         // the plots' table (empty for a group the scene declared)
  QString title;             // the table's title, or its name made readable
  std::vector<int> plots;    // indices into Results::plots, in their order
  QString common_prefix;     // "Envelope: " when every plot title of the group starts with it (dropped on the tabs)
};

// The groups of `results.plots`: the `declared` groups that hold a plot (their plots in the order of the group's
// names), then by table in order of their first plot; empty when no grouping is needed (at most `ungrouped_limit`
// plots, or all in one group).
std::vector<PlotGroup> groupPlots(const Results& results, const std::vector<PlotGroupSpec>& declared = {},
                                  int ungrouped_limit = kUngroupedPlotLimit);

// The text of a plot's tab: its title (its name when untitled), less the group's common prefix.
QString plotTabText(const PlotSpec& spec, const PlotGroup* group = nullptr);

}  // namespace maris::ui
