// Runs a command line as a user would (through the shell) and collects what it prints.
#pragma once

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <string>

namespace billiard::testing {

struct CommandResult {
  int status;       // exit status; -1 if the command did not exit (a signal killed it)
  std::string out;  // stdout, and stderr when asked
};

// stderr goes to /dev/null unless merge_stderr.
inline CommandResult RunCommand(const std::string& command, bool merge_stderr = false) {
  const std::string line = command + (merge_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(line.c_str(), "r");
  if (pipe == nullptr) return {-1, ""};
  std::string out;
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace billiard::testing
