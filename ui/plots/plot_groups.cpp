#include "plots/plot_groups.hpp"

#include <algorithm>

namespace maris::ui {

namespace {

QString fullTitle(const PlotSpec& spec) { return QString::fromStdString(spec.title.empty() ? spec.name : spec.title); }

QString readableName(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  QString text = QString::fromStdString(name);
  if (!text.isEmpty()) text[0] = text[0].toUpper();
  return text;
}

// The text up to and including ": " that every title of `group` starts with (and that leaves a title behind).
QString commonPrefix(const Results& results, const PlotGroup& group) {
  const QString first = fullTitle(results.plots[group.plots.front()]);
  const int colon = first.indexOf(QStringLiteral(": "));
  if (colon <= 0 || group.plots.size() < 2) return {};
  const QString prefix = first.left(colon + 2);
  for (int i : group.plots) {
    const QString title = fullTitle(results.plots[i]);
    if (!title.startsWith(prefix) || title.size() == prefix.size()) return {};
  }
  return prefix;
}

}  // namespace

std::vector<PlotGroup> groupPlots(const Results& results, const std::vector<PlotGroupSpec>& declared,
                                  int ungrouped_limit) {
  std::vector<PlotGroup> groups;
  const int n = static_cast<int>(results.plots.size());
  if (n <= ungrouped_limit) return groups;
  std::vector<bool> placed(static_cast<std::size_t>(n), false);
  for (const PlotGroupSpec& spec : declared) {
    PlotGroup group;
    group.title = QString::fromStdString(spec.title);
    for (const std::string& name : spec.plots)
      for (int i = 0; i < n; ++i)
        if (!placed[i] && plotGroupHolds(PlotGroupSpec{{}, {name}}, results.plots[i].name)) {
          placed[i] = true;
          group.plots.push_back(i);
        }
    if (!group.plots.empty()) groups.push_back(std::move(group));
  }
  const std::size_t declared_groups = groups.size();
  for (int i = 0; i < n; ++i) {
    if (placed[i]) continue;
    const std::string& table = results.plots[i].table;
    auto it = std::find_if(groups.begin() + static_cast<std::ptrdiff_t>(declared_groups), groups.end(),
                           [&](const PlotGroup& g) { return g.table == table; });
    if (it == groups.end()) {
      PlotGroup group;
      group.table = table;
      const Table* t = results.findTable(table);
      group.title = t && !t->title.empty() ? QString::fromStdString(t->title) : readableName(table);
      groups.push_back(std::move(group));
      it = groups.end() - 1;
    }
    it->plots.push_back(i);
  }
  if (groups.size() < 2) return {};
  for (PlotGroup& g : groups) g.common_prefix = commonPrefix(results, g);
  return groups;
}

QString plotTabText(const PlotSpec& spec, const PlotGroup* group) {
  const QString title = fullTitle(spec);
  if (group && !group->common_prefix.isEmpty() && title.startsWith(group->common_prefix))
    return title.mid(group->common_prefix.size());
  return title;
}

}  // namespace maris::ui
