// Helpers shared by the billiard subcommands: strict number parsing and one-line errors.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace billiard::cli {

// A user error: printed as one line, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses exactly `count` comma-separated finite numbers; `what` names them in the error.
std::vector<double> ParseNumberList(const std::string& text, std::size_t count,
                                    const std::string& what);

// Throws UsageError unless value is finite.
void RequireFinite(double value, const std::string& what);

}  // namespace billiard::cli
