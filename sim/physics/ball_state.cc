#include "sim/physics/ball_state.h"

#include <cstdio>

namespace billiard::physics {

std::string FormatState(const BallState& s) {
  std::string out;
  char buffer[32];
  for (int i = 0; i < 7; ++i) {
    std::snprintf(buffer, sizeof buffer, "%s%.17g", i ? "," : "", s[i]);
    out += buffer;
  }
  return out;
}

}  // namespace billiard::physics
