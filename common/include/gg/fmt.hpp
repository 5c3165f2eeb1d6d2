#pragma once
// A number as it reads in a message: six significant digits, printf's %g ("0.5", "1e+05").
#include <cstdio>
#include <string>

namespace gg {

inline std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace gg
