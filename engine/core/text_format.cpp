#include "core/text_format.hpp"

#include <cstdarg>
#include <cstdio>

namespace maris {

std::string formatText(const char* spec, ...) {
  va_list args;
  va_start(args, spec);
  va_list again;
  va_copy(again, args);
  const int size = std::vsnprintf(nullptr, 0, spec, args);
  va_end(args);
  std::string out(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
  if (size > 0) std::vsnprintf(out.data(), out.size() + 1, spec, again);
  va_end(again);
  return out;
}

std::string numberText(double v) { return formatText("%g", v); }

}  // namespace maris
