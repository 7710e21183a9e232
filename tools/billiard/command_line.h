// Helpers shared by the billiard subcommands: strict number parsing and one-line errors.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "parameters.h"

namespace billiard::cli {

// A user error: printed as one line, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Not a failure of the tool: the command ran and its answer is no (a refused plan), already
// printed. what() is the one-line reason for stderr; exit status 3.
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses exactly `count` comma-separated finite numbers; `what` names them in the error.
std::vector<double> ParseNumberList(const std::string& text, std::size_t count,
                                    const std::string& what);

// Throws UsageError unless value is finite.
void RequireFinite(double value, const std::string& what);

// The parameter set of a --params option (a built-in name or a JSON file); UsageError if it
// does not load.
ModelParameters LoadParametersOption(const std::string& name_or_path);

}  // namespace billiard::cli
