// What every node's command line shares (CLI11): errors in one line prefixed by the program's
// name, and the project's exit statuses for them: 0 after --help, 2 for a bad command line.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace billiard::nodes {

// A parse error is printed as "NAME: what (see --help)".
inline void OneLineErrors(CLI::App& app, const std::string& name) {
  app.failure_message([name](const CLI::App*, const CLI::Error& e) {
    return name + ": " + std::string(e.what()) + " (see --help)\n";
  });
}

// Parses the command line; the status to exit with when it says to (--help, or an error).
inline std::optional<int> ParseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return std::nullopt;
}

}  // namespace billiard::nodes
