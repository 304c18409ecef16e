// The scenario being edited: its scene, its parameters (JSON, SI units), the file it came from,
// the undo stack of edits and the validation errors of the current parameters. Every parameter
// edit goes through SetParameterCommand (style.md §14), so undo, the modified marker and the
// editor's error marks all follow from this one object.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "core/scene.hpp"

namespace maris::ui {

class ScenarioDocument : public QObject {
  Q_OBJECT
 public:
  explicit ScenarioDocument(QObject* parent = nullptr);

  // Replaces the scenario (clears undo history; the document is unmodified afterwards).
  void reset(const SceneDefinition* scene, Scenario scenario, QString file_path = {});
  bool isEmpty() const { return scene_ == nullptr; }

  const SceneDefinition* scene() const { return scene_; }
  const Scenario& scenario() const { return scenario_; }
  const QString& filePath() const { return file_path_; }
  void setFilePath(QString path);
  QUndoStack* undoStack() { return &undo_; }
  bool isModified() const { return !undo_.isClean(); }
  void markSaved() { undo_.setClean(); }

  // Parameter value at a dotted path below "parameters" (null JSON if absent).
  Json value(const std::string& path) const;
  // Pushes an undoable edit (no-op if the value is unchanged).
  void edit(const std::string& path, Json new_value);
  // Sets a value without an undo entry; used by SetParameterCommand itself.
  void applyValue(const std::string& path, const Json& value);

  // Every current problem, paths prefixed with "parameters." as the engine reports them.
  const std::vector<FieldError>& errors() const { return errors_; }
  bool isValid() const { return scene_ && errors_.empty(); }
  // Errors at `path` or inside it ("sections" also matches "sections[1].outer_diameter"), joined.
  QString errorText(const std::string& path) const;
  // The scene's plausibility warnings for valid parameters (a riser top in the air, a current beyond the
  // model's range): the run goes ahead, the editor shows them at their fields. Paths as errors().
  const std::vector<FieldError>& warnings() const { return warnings_; }
  QString warningText(const std::string& path) const;

 signals:
  void scenarioReset();                   // a different scenario was loaded
  void valueChanged(const QString& path); // one parameter changed (by an edit, undo or redo)
  void errorsChanged();
  void modifiedChanged(bool modified);
  void filePathChanged(const QString& path);

 private:
  void revalidate();

  const SceneDefinition* scene_ = nullptr;
  Scenario scenario_;
  QString file_path_;
  QUndoStack undo_;
  std::vector<FieldError> errors_;
  std::vector<FieldError> warnings_;
};

// A field's label for people, as everything in the GUI names it: the scene's declared label ("Length L"), else its
// key made readable ("Segment count"); parameterLabel as Qt text.
QString fieldLabel(const ParamSpec& spec);
// A parameter group's title as the editor shows it: "Free surface" from "free_surface".
QString groupTitle(const std::string& group);
// `text` (a message, a warning) with every parameter path of `schema` in it named as the editor shows the field,
// group ▸ label: "parameters.speed.froude_min" → "Speed ▸ First Froude number", "sections[1].outer_diameter" →
// "Outer diameter D_out of section row 2" (tableCellLabel), a list's element "…, value 1". The engine's messages name fields by their
// paths, which is what a scenario file's author needs; people in the GUI find fields by their group and label.
// Words that are not parameter paths stay as they are.
QString withFieldNames(const std::string& text, const Schema& schema);
// A value shown in words: numbers in shortest round-trip form, strings unquoted.
QString displayValue(const Json& value);

}  // namespace maris::ui
