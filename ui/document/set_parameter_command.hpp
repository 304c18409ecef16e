// The one undo command for every parameter of every scene (style.md §14): it stores the path and
// the old and new JSON values, so no scene needs a command class of its own. Consecutive edits of
// the same field (typing, spin-box drags) merge into one undo step.
#pragma once

#include <string>

#include <QUndoCommand>

#include "core/schema.hpp"

namespace maris::ui {

class ScenarioDocument;

class SetParameterCommand : public QUndoCommand {
 public:
  SetParameterCommand(ScenarioDocument* document, std::string path, Json old_value, Json new_value);

  void undo() override;
  void redo() override;
  int id() const override { return 0x4d50; }  // same id for all: mergeWith checks the path
  bool mergeWith(const QUndoCommand* other) override;

  const std::string& path() const { return path_; }

 private:
  void updateText();

  ScenarioDocument* document_;
  std::string path_;
  Json old_value_;
  Json new_value_;
  double created_s_ = 0.0;  // steady-clock seconds of the latest merged edit
};

}  // namespace maris::ui
