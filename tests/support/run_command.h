// Runs a command line as a user would (through the shell) and collects what it prints.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
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

struct SeparateOutput {
  int status;  // as CommandResult's
  std::string out, err;
};

// stdout and stderr apart, from one run: what a command prints where is part of its contract.
inline SeparateOutput RunCommandApart(const std::string& command) {
  std::string err_path = "/tmp/run_command_stderr_XXXXXX";
  const int fd = mkstemp(err_path.data());
  if (fd < 0) return {-1, "", ""};
  close(fd);
  // The inner redirection wins over RunCommand's own 2>/dev/null, which the outer one takes.
  const CommandResult r = RunCommand("( (" + command + ") 2>" + err_path + " )");
  std::ifstream in(err_path);
  std::string err{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::remove(err_path.c_str());
  return {r.status, r.out, err};
}

}  // namespace billiard::testing
