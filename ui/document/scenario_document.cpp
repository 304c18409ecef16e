#include "document/scenario_document.hpp"

#include <charconv>
#include <cmath>

#include <QRegularExpression>

#include "document/set_parameter_command.hpp"

namespace maris::ui {

ScenarioDocument::ScenarioDocument(QObject* parent) : QObject(parent) {
  connect(&undo_, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
}

void ScenarioDocument::reset(const SceneDefinition* scene, Scenario scenario, QString file_path) {
  scene_ = scene;
  scenario_ = std::move(scenario);
  undo_.clear();
  undo_.setClean();
  setFilePath(std::move(file_path));
  revalidate();
  emit scenarioReset();
  emit modifiedChanged(false);
}

void ScenarioDocument::setFilePath(QString path) {
  if (path == file_path_) return;
  file_path_ = std::move(path);
  emit filePathChanged(file_path_);
}

Json ScenarioDocument::value(const std::string& path) const {
  const Json* found = findAtPath(scenario_.parameters, path);
  return found ? *found : Json();
}

void ScenarioDocument::edit(const std::string& path, Json new_value) {
  Json old_value = value(path);
  if (old_value == new_value) return;
  undo_.push(new SetParameterCommand(this, path, std::move(old_value), std::move(new_value)));
}

void ScenarioDocument::applyValue(const std::string& path, const Json& value) {
  setAtPath(scenario_.parameters, path, value);
  // Value first, errors second: editors rebuild their cells on the value, then mark the bad ones.
  emit valueChanged(QString::fromStdString(path));
  revalidate();
}

namespace {

// The messages of `problems` at `path` or inside it ("sections" also matches "sections[1].outer_diameter").
QString problemsAt(const std::vector<FieldError>& problems, const std::string& path) {
  const std::string full = "parameters." + path;
  QStringList lines;
  for (const auto& e : problems) {
    const bool same = e.path == full;
    const bool inside = e.path.size() > full.size() && e.path.compare(0, full.size(), full) == 0 &&
                        (e.path[full.size()] == '.' || e.path[full.size()] == '[');
    if (!same && !inside) continue;
    QString line = QString::fromStdString(e.message);
    if (inside) line = QString::fromStdString(e.path.substr(full.size())) + ": " + line;
    lines << line;
  }
  return lines.join('\n');
}

}  // namespace

QString ScenarioDocument::errorText(const std::string& path) const {
  const QString text = problemsAt(errors_, path);
  return scene_ ? withFieldNames(text.toStdString(), scene_->schema) : text;
}

QString ScenarioDocument::warningText(const std::string& path) const {
  const QString text = problemsAt(warnings_, path);
  return scene_ ? withFieldNames(text.toStdString(), scene_->schema) : text;
}

void ScenarioDocument::revalidate() {
  errors_ = scene_ ? validateParameters(*scene_, scenario_.parameters) : std::vector<FieldError>{};
  warnings_ = scene_ && errors_.empty() ? plausibilityWarnings(*scene_, scenario_.parameters) : std::vector<FieldError>{};
  emit errorsChanged();
}

QString groupTitle(const std::string& group) {
  QString title = QString::fromStdString(group);
  title.replace('_', ' ');
  if (!title.isEmpty()) title[0] = title[0].toUpper();
  return title;
}

namespace {

// The editor's name of the field at `path` (below "parameters"), or empty when it is none of `schema`'s.
QString fieldNameAt(const std::string& path, const Schema& schema) {
  static const QRegularExpression indexed(QStringLiteral("^([a-z0-9_.]+)\\[(\\d+)\\](?:\\.([a-z0-9_]+))?$"));
  const QRegularExpressionMatch m = indexed.match(QString::fromStdString(path));
  const std::string base = m.hasMatch() ? m.captured(1).toStdString() : path;
  const ParamSpec* spec = schema.find(base);
  if (!spec) return {};
  const bool grouped = spec->path.find('.') != std::string::npos;
  const QString owner = grouped ? groupTitle(spec->group()) + QStringLiteral(" ▸ ") : QString();
  if (!m.hasMatch()) return owner + fieldLabel(*spec);
  const int row = m.captured(2).toInt() + 1;
  if (spec->kind == ParamKind::Table) {
    const std::string column = m.captured(3).toStdString();
    if (column.empty()) return owner + fieldLabel(*spec) + QStringLiteral(" row %1").arg(row);
    for (const ParamSpec& c : spec->columns)
      if (c.path == column) return owner + QString::fromStdString(tableCellLabel(*spec, c, static_cast<std::size_t>(row - 1)));
    return {};
  }
  if (!m.captured(3).isEmpty()) return {};
  return owner + fieldLabel(*spec) + QStringLiteral(", value %1").arg(row);
}

}  // namespace

QString withFieldNames(const std::string& text, const Schema& schema) {
  // A path: lower-case words joined by '.', each optionally indexed ("a.b[2].c"), with a '.' or '[' somewhere.
  static const QRegularExpression path_like(
      QStringLiteral("\\b(?:parameters\\.)?[a-z][a-z0-9_]*(?:\\[\\d+\\])?(?:\\.[a-z][a-z0-9_]*(?:\\[\\d+\\])?)*"));
  const QString in = QString::fromStdString(text);
  QString out;
  qsizetype done = 0;
  for (auto it = path_like.globalMatch(in); it.hasNext();) {
    const QRegularExpressionMatch m = it.next();
    QString token = m.captured(0);
    if (!token.contains(QLatin1Char('.')) && !token.contains(QLatin1Char('['))) continue;
    if (token.startsWith(QStringLiteral("parameters."))) token.remove(0, 11);
    const QString name = fieldNameAt(token.toStdString(), schema);
    if (name.isEmpty()) continue;
    out += in.mid(done, m.capturedStart(0) - done) + name;
    done = m.capturedEnd(0);
  }
  return out + in.mid(done);
}

QString fieldLabel(const ParamSpec& spec) { return QString::fromStdString(parameterLabel(spec)); }

QString displayValue(const Json& value) {
  if (value.is_string()) return QString::fromStdString(value.get<std::string>());
  // Very large and very small reals in scientific notation ("2.1e+11 Pa", not "210000000000.0"),
  // shortest text that reads back to the same double.
  if (value.is_number_float()) {
    const double x = value.get<double>();
    const double magnitude = std::abs(x);
    if (std::isfinite(x) && x != 0.0 && (magnitude >= 1e6 || magnitude < 1e-3)) {
      char text[32];
      const auto end = std::to_chars(text, text + sizeof text, x, std::chars_format::scientific).ptr;
      return QString::fromLatin1(text, static_cast<int>(end - text));
    }
  }
  return QString::fromStdString(value.dump());
}

}  // namespace maris::ui
