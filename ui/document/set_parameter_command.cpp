#include "document/set_parameter_command.hpp"

#include <chrono>

#include "document/scenario_document.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

// Edits of one field closer together than this are one undo step (typing, dragging).
constexpr double kMergeWindowSeconds = 1.5;

double nowSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

SetParameterCommand::SetParameterCommand(ScenarioDocument* document, std::string path, Json old_value,
                                         Json new_value)
    : document_(document), path_(std::move(path)), old_value_(std::move(old_value)),
      new_value_(std::move(new_value)) {
  updateText();
  created_s_ = nowSeconds();
}

void SetParameterCommand::undo() { document_->applyValue(path_, old_value_); }

void SetParameterCommand::redo() { document_->applyValue(path_, new_value_); }

bool SetParameterCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const SetParameterCommand*>(other);
  if (!next || next->path_ != path_ || next->created_s_ - created_s_ > kMergeWindowSeconds) return false;
  new_value_ = next->new_value_;
  created_s_ = next->created_s_;
  updateText();
  // An edit merged back to where it started is no step at all.
  setObsolete(new_value_ == old_value_);
  return true;
}

void SetParameterCommand::updateText() {
  const ParamSpec* spec = document_->scene() ? document_->scene()->schema.find(path_) : nullptr;
  const QString label = spec ? fieldLabel(*spec) : QString::fromStdString(path_);
  if (spec && (spec->kind == ParamKind::Table || spec->kind == ParamKind::RealList)) {
    setText(QObject::tr("Edit %1").arg(label));
    return;
  }
  QString value = displayValue(new_value_);
  if (spec && !unitText(spec->unit).isEmpty()) value += " " + unitText(spec->unit);
  setText(QObject::tr("Set %1 to %2").arg(label, value));
}

}  // namespace maris::ui
