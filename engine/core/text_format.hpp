// printf-style text for messages, labels and number cells: the one place that sizes the buffer, so a long
// message is never cut at a fixed buffer length.
#pragma once

#include <string>

namespace maris {

// `spec` is a printf format; the attribute lets the compiler check the arguments against it (-Wformat).
[[gnu::format(printf, 1, 2)]] std::string formatText(const char* spec, ...);

// A value as a message quotes it: printf's %g (six significant digits, no trailing zeros).
std::string numberText(double v);

}  // namespace maris
