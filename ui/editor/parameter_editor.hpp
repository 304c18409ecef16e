// The parameter editor dock, built from the scene's schema and nothing else: one group box per
// schema group, one row per field with its editor, unit, reset-to-default button and, when the
// value is invalid, the validation message in words under it. Edits go to the document as
// undoable commands; the editor only mirrors the document (scenarioReset / valueChanged /
// errorsChanged), so undo and redo update it like any other change; Ctrl+Z / Ctrl+Shift+Z in a
// field act on the document's undo stack too, and Tab moves from field to field. The context menu
// of a number field (and of its label) offers "Sweep this parameter…".
#pragma once

#include <map>
#include <string>

#include <QWidget>

#include "core/schema.hpp"

class QLabel;
class QMenu;
class QToolButton;
class QVBoxLayout;

namespace maris::ui {

class ScenarioDocument;
class TableEditor;

class ParameterEditor : public QWidget {
  Q_OBJECT
 public:
  explicit ParameterEditor(ScenarioDocument* document, QWidget* parent = nullptr);

  // The editing widget of a field (QLineEdit, QCheckBox, QComboBox or TableEditor), or nullptr.
  QWidget* fieldWidget(const std::string& path) const;
  QLabel* errorLabel(const std::string& path) const;
  QToolButton* resetButton(const std::string& path) const;
  QLabel* problemsLabel() const { return problems_; }
  // The context menu of a field (its editor's own actions, then "Sweep this parameter…" for a real
  // or integer field); the caller owns it. nullptr for an unknown path.
  QMenu* fieldMenu(const std::string& path, QWidget* parent = nullptr);
  // Never narrower than the fields' own minimum (labels, editors, units, reset buttons) beside a vertical scroll
  // bar, nor than kMinimumWidth: the column holding the editor keeps its fields whole, with no sideways scrolling.
  QSize minimumSizeHint() const override;
  static constexpr int kMinimumWidth = 300;  // [px]

 signals:
  // "Sweep this parameter…" was chosen for the field at `path` (below "parameters"), or "Sweep this cell…" in a
  // table's cell ("sections[1].outer_diameter").
  void sweepRequested(const QString& path);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  struct Row {
    const ParamSpec* spec = nullptr;
    QWidget* editor = nullptr;
    QLabel* error = nullptr;
    QToolButton* reset = nullptr;
  };

  void rebuild();
  QWidget* makeEditor(const ParamSpec& spec);
  void refreshValue(const std::string& path);
  void refreshErrors();
  void commitText(const ParamSpec& spec, const QString& text);

  ScenarioDocument* document_;
  QLabel* title_;
  QLabel* description_;
  QLabel* problems_;
  QWidget* fields_host_ = nullptr;
  QVBoxLayout* fields_layout_;
  std::map<std::string, Row> rows_;
};

}  // namespace maris::ui
