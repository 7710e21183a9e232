// Figures quoted in README.md, for the tests that hold them to a run: a quoted figure that a
// deterministic run no longer gives fails its test instead of going stale.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace billiard::testing {

// README.md with every run of whitespace made one space: a sentence is found whatever its line
// breaks.
inline std::string ReadmeText() {
  std::ifstream in(std::string(BILLIARD_SOURCE_DIR) + "/README.md");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return std::regex_replace(text, std::regex("\\s+"), " ");
}

// The groups `pattern` captures in README.md (ECMAScript regex on the one-spaced text); an
// empty vector, and a test failure, when the README does not say it.
inline std::vector<std::string> ReadmeFigures(const std::string& pattern) {
  std::smatch match;
  const std::string text = ReadmeText();
  if (!std::regex_search(text, match, std::regex(pattern))) {
    ADD_FAILURE() << "README.md does not say /" << pattern << "/";
    return {};
  }
  return std::vector<std::string>(match.begin() + 1, match.end());
}

// `value` as the README quotes it, with `decimals` digits after the point.
inline std::string Quoted(double value, int decimals) {
  char out[64];
  std::snprintf(out, sizeof out, "%.*f", decimals, value);
  return out;
}

}  // namespace billiard::testing
