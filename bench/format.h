// Number formatting and file opening shared by the benchmark reports.
#pragma once

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace billiard::bench {

inline std::string Fixed(double x, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, x);
  return text;
}

inline std::string Sci(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", x);
  return text;
}

// Throws std::runtime_error when the file cannot be opened for writing.
inline std::ofstream OpenForWriting(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  return out;
}

}  // namespace billiard::bench
