#include "core/checked_count.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "core/text_format.hpp"

namespace maris {

long checkedCount(double count, long limit, const std::string& field, const std::string& quantity) {
  const double whole = std::ceil(count - 1e-9);
  if (!std::isfinite(count) || whole > static_cast<double>(limit) || whole >= 0x1p62)
    throw InputError(field, "", formatText("gives %.3g %s; the limit is %.3g (a larger step, a coarser grid or a "
                                           "shorter duration)", count, quantity.c_str(), static_cast<double>(limit)));
  if (whole < 0.0) throw InputError(field, "", formatText("gives a negative count of %s (%.3g)", quantity.c_str(), count));
  return static_cast<long>(whole);
}

}  // namespace maris
