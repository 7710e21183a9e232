// What every node's command line shares (CLI11): errors in one line prefixed by the program's
// name, --version, and the project's exit statuses for them: 0 after --help or --version, 2 for
// a bad command line.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "lcmtypes/version.h"

namespace billiard::nodes {

// A parse error is printed as "NAME: what (see --help)".
inline void OneLineErrors(CLI::App& app, const std::string& name) {
  app.failure_message([name](const CLI::App*, const CLI::Error& e) {
    return name + ": " + std::string(e.what()) + " (see --help)\n";
  });
}

// --version prints "NAME VERSION" on stdout and exits 0, like --help: the version a node
// announces in NODE_STATUS, so that what runs can be compared with what is installed.
inline void VersionFlag(CLI::App& app, const std::string& name) {
  app.set_version_flag("--version", name + " " + kVersion, "the version and nothing else");
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
