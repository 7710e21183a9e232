// Figures quoted in the project's documents (README.md and the manuals in docs/), for the tests
// that hold them to a run: a quoted figure that a deterministic run no longer gives fails its
// test instead of going stale.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace billiard::testing {

// `document` (a path from the repository root) with every run of whitespace made one space: a
// sentence is found whatever its line breaks.
inline std::string DocumentText(const std::string& document) {
  std::ifstream in(std::string(BILLIARD_SOURCE_DIR) + "/" + document);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return std::regex_replace(text, std::regex("\\s+"), " ");
}

// The groups `pattern` captures in `document` (ECMAScript regex on the one-spaced text); an
// empty vector, and a test failure, when the document does not say it.
inline std::vector<std::string> QuotedFigures(const std::string& document,
                                              const std::string& pattern) {
  std::smatch match;
  const std::string text = DocumentText(document);
  if (!std::regex_search(text, match, std::regex(pattern))) {
    ADD_FAILURE() << document << " does not say /" << pattern << "/";
    return {};
  }
  return std::vector<std::string>(match.begin() + 1, match.end());
}

// `value` as the documents quote it, with `decimals` digits after the point.
inline std::string Quoted(double value, int decimals) {
  char out[64];
  std::snprintf(out, sizeof out, "%.*f", decimals, value);
  return out;
}

}  // namespace billiard::testing
