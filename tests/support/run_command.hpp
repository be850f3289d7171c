#pragma once
// Runs a shell command line and captures what it prints: the CLI tests' one way to run a tool.
// Redirections are the caller's (append " 2>&1" to capture stderr too).
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace ringlet::test {

struct CommandRun {
  int rc = -1;      // exit code; -1 when the command could not start or did not exit normally
  std::string out;  // what the command line wrote to the pipe
};

inline CommandRun run_command(const std::string& command_line) {
  CommandRun r;
  FILE* pipe = ::popen(command_line.c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace ringlet::test
