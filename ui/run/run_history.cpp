#include "run/run_history.hpp"

#include <QStringList>

#include "document/scenario_document.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

// A changed value as a run label shows it: a real to 4 significant digits ("1.571", not
// "1.5707963267948966"), then the unit.
QString labelValue(const Json& value, const ParamSpec* spec) {
  if (value.is_array()) return QObject::tr("edited");
  QString text = value.is_number_float() ? QString::number(value.get<double>(), 'g', 4) : displayValue(value);
  if (spec && value.is_number() && !unitText(spec->unit).isEmpty()) text += QLatin1Char(' ') + unitText(spec->unit);
  return text;
}

void collectDifferences(const Json& before, const Json& after, const std::string& path, const Schema* schema,
                        QStringList& out) {
  if (before.is_object() && after.is_object()) {
    for (auto it = after.begin(); it != after.end(); ++it) {
      const std::string child = path.empty() ? it.key() : path + "." + it.key();
      collectDifferences(before.contains(it.key()) ? before[it.key()] : Json(), it.value(), child, schema, out);
    }
    return;
  }
  if (before == after) return;
  const ParamSpec* spec = schema ? schema->find(path) : nullptr;
  QString key;
  if (spec) {
    key = fieldLabel(*spec);
  } else {
    key = QString::fromStdString(path.substr(path.rfind('.') == std::string::npos ? 0 : path.rfind('.') + 1));
    key.replace('_', ' ');
  }
  out << QStringLiteral("%1 = %2").arg(key, labelValue(after, spec));
}

}  // namespace

const RunRecord& RunHistory::add(RunRecord record, bool keep_label, const Schema* schema) {
  const RunRecord* previous = nullptr;
  for (auto it = runs_.rbegin(); it != runs_.rend(); ++it)
    if (sameScenario(it->scenario, record.scenario)) {
      previous = &*it;
      break;
    }
  QString label = QObject::tr("run %1").arg(record.id);
  if (previous) {
    const QString diff = parameterDifference(previous->scenario.parameters, record.scenario.parameters, 3, schema);
    if (!diff.isEmpty()) label += QStringLiteral(" (%1)").arg(diff);
  }
  if (!keep_label) record.label = label;
  runs_.push_back(std::move(record));
  while (runs_.size() > capacity_) runs_.pop_front();
  return runs_.back();
}

bool sameScenario(const Scenario& a, const Scenario& b) { return a.scene == b.scene && a.name == b.name; }

const RunRecord* RunHistory::find(quint64 id) const {
  for (const auto& r : runs_)
    if (r.id == id) return &r;
  return nullptr;
}

QString parameterDifference(const Json& before, const Json& after, int max_items, const Schema* schema) {
  QStringList items;
  collectDifferences(before, after, "", schema, items);
  if (items.size() > max_items) {
    items = items.mid(0, max_items);
    items << QStringLiteral("…");
  }
  return items.join(QStringLiteral(", "));
}

}  // namespace maris::ui
