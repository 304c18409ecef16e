// Failure diagnostics shared by the integrators.
#include "core/ode_internal.hpp"

#include "core/errors.hpp"
#include "core/text_format.hpp"

namespace maris::ode_detail {

void throwNonFiniteStep(std::initializer_list<const Eigen::VectorXd*> stage_derivatives,
                        const Eigen::VectorXd& y_new, double t, long step, const OdeOptions& options) {
  int stage = 1;
  for (const Eigen::VectorXd* k : stage_derivatives) {
    for (Eigen::Index i = 0; i < k->size(); ++i)
      if (!std::isfinite((*k)[i]))
        throw SolverError(componentName(options, i), t, step,
                          "has a non-finite time derivative (" + numberText((*k)[i]) + ", stage " +
                              std::to_string(stage) + ")");
    ++stage;
  }
  throwIfNotFinite(y_new, t, step, options.state_name);
}

}  // namespace maris::ode_detail
