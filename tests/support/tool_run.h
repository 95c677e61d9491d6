// Running bounce's built tools from the tests, as users run them: a shell command with its
// standard output and error captured in a log file, its exit code, and the log as text.
#pragma once

#include <filesystem>
#include <string>

namespace bounce::test {

// `path` single-quoted for the shell (the tests' paths hold no quote).
std::string shellQuote(const std::filesystem::path& path);

// The exit code of a std::system status; -1 when the command did not exit normally (a signal).
int exitCode(int systemStatus);

struct ToolRun {
  int exitCode = -1;   // as exitCode() gives it
  std::string output;  // standard output and error, interleaved
};

// Runs `command` through the shell with standard output and error sent to `log` (left in place).
ToolRun runCommand(const std::string& command, const std::filesystem::path& log);

// The file's bytes as a string; empty when it cannot be read.
std::string readText(const std::filesystem::path& path);

}  // namespace bounce::test
