// The three kinds of failure a run can end in (style.md §12):
//   InputError   – the user's scenario is invalid; carries every bad field (CLI exit code 2);
//   SolverError  – the numerics failed; says at which time/step and in which quantity (exit code 3);
//   RunCancelled – the user asked to stop (exit code 130).
// Our own bugs are asserts, not exceptions.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace maris {

// One invalid field of a scenario: "parameters.geometry.length = -3: must be in (0, 100000]".
struct FieldError {
  std::string path;     // JSON path inside the scenario, e.g. "parameters.sections[1].outer_diameter"
  std::string value;    // the offending value as JSON text ("" when the field is missing)
  std::string message;  // what was expected, in words, with the allowed range
  std::string str() const;
};

class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<FieldError> errors);
  explicit InputError(const std::string& path, const std::string& value, const std::string& message);
  const std::vector<FieldError>& errors() const { return errors_; }

 private:
  std::vector<FieldError> errors_;
};

// A numerical failure: non-finite state, step-size collapse, no convergence.
class SolverError : public std::runtime_error {
 public:
  SolverError(std::string quantity, double time_s, long step, std::string detail);
  const std::string& quantity() const { return quantity_; }  // e.g. "segment 17 angle psi"
  double time() const { return time_s_; }                      // [s] simulated time of failure
  long step() const { return step_; }                          // step index (-1 if not applicable)
  const std::string& detail() const { return detail_; }

 private:
  std::string quantity_;
  double time_s_;
  long step_;
  std::string detail_;
};

class RunCancelled : public std::runtime_error {
 public:
  RunCancelled() : std::runtime_error("run cancelled") {}
};

// Joins the messages of all errors, one per line.
std::string describeErrors(const std::vector<FieldError>& errors);

}  // namespace maris
