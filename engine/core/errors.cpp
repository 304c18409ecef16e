#include "core/errors.hpp"

#include <cmath>

#include "core/input_limits.hpp"
#include "core/text_format.hpp"

namespace maris {

std::string echoText(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  std::size_t at = limit - 3;
  while (at > 0 && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;  // not inside a UTF-8 character
  return text.substr(0, at) + "... (" + std::to_string(text.size()) + " characters)";
}

std::string FieldError::str() const {
  const std::string where = echoText(path, 2 * kEchoLimit);
  if (value.empty()) return where + ": " + echoText(message, 12 * kEchoLimit);
  return where + " = " + echoText(value, kEchoLimit) + ": " + echoText(message, 12 * kEchoLimit);
}

std::string describeErrors(const std::vector<FieldError>& errors) {
  std::string text;
  for (std::size_t i = 0; i < errors.size() && i < kReportedErrorLimit; ++i) {
    if (!text.empty()) text += '\n';
    text += errors[i].str();
  }
  if (errors.size() > kReportedErrorLimit)
    text += formatText("\n... and %zu more errors (%zu in all)", errors.size() - kReportedErrorLimit, errors.size());
  return text;
}

InputError::InputError(std::vector<FieldError> errors)
    : std::runtime_error(describeErrors(errors)), errors_(std::move(errors)) {}

InputError::InputError(const std::string& path, const std::string& value, const std::string& message)
    : InputError(std::vector<FieldError>{FieldError{path, value, message}}) {}

static std::string solverMessage(const std::string& quantity, double t, long step, const std::string& detail) {
  std::string message = !std::isfinite(t) ? std::string("solver failed: ")  // not tied to a time (a result)
                        : step >= 0      ? formatText("solver failed at t = %.6g s (step %ld): ", t, step)
                                         : formatText("solver failed at t = %.6g s: ", t);
  message.append(quantity);
  if (!detail.empty()) message.append(" ").append(detail);
  return message;
}

SolverError::SolverError(std::string quantity, double time_s, long step, std::string detail)
    : std::runtime_error(solverMessage(quantity, time_s, step, detail)),
      quantity_(std::move(quantity)), time_s_(time_s), step_(step), detail_(std::move(detail)) {}

}  // namespace maris
