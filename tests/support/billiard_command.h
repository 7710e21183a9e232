// The billiard tool as the CLI tests run it (BILLIARD_BIN is the built binary, set by CMake).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace billiard::testing {

inline CommandResult Billiard(const std::string& args, bool merge_stderr = false) {
  return RunCommand(std::string(BILLIARD_BIN) + " " + args, merge_stderr);
}

// What a --json command printed: exactly one JSON object, on one line.
inline nlohmann::json OneObject(const CommandResult& r, const std::string& args) {
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  const auto j = nlohmann::json::parse(r.out, nullptr, false);
  EXPECT_TRUE(j.is_object()) << args << ": " << r.out;
  return j;
}

}  // namespace billiard::testing
