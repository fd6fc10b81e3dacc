#pragma once
// Runs a shell command for the CLI tests and keeps its exit code and its merged stdout/stderr.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace snell::test {

struct Outcome {
  int code = -1;
  std::string output;
};

inline Outcome run_command(const std::string& command) {
  Outcome r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace snell::test
