#include "core/errors.hpp"

#include "core/text_format.hpp"

namespace maris {

std::string FieldError::str() const {
  if (value.empty()) return path + ": " + message;
  return path + " = " + value + ": " + message;
}

std::string describeErrors(const std::vector<FieldError>& errors) {
  std::string text;
  for (const auto& e : errors) {
    if (!text.empty()) text += '\n';
    text += e.str();
  }
  return text;
}

InputError::InputError(std::vector<FieldError> errors)
    : std::runtime_error(describeErrors(errors)), errors_(std::move(errors)) {}

InputError::InputError(const std::string& path, const std::string& value, const std::string& message)
    : InputError(std::vector<FieldError>{FieldError{path, value, message}}) {}

static std::string solverMessage(const std::string& quantity, double t, long step, const std::string& detail) {
  std::string message = step >= 0 ? formatText("solver failed at t = %.6g s (step %ld): ", t, step)
                                  : formatText("solver failed at t = %.6g s: ", t);
  message.append(quantity);
  if (!detail.empty()) message.append(" ").append(detail);
  return message;
}

SolverError::SolverError(std::string quantity, double time_s, long step, std::string detail)
    : std::runtime_error(solverMessage(quantity, time_s, step, detail)),
      quantity_(std::move(quantity)), time_s_(time_s), step_(step), detail_(std::move(detail)) {}

}  // namespace maris
