#include "support/tool_run.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace bounce::test {

// Built with += : GCC 12 gives a false -Wrestrict on "'" + std::string.
std::string shellQuote(const std::filesystem::path& path) {
  std::string quoted(1, '\'');
  quoted += path.string();
  quoted += '\'';
  return quoted;
}

int exitCode(int systemStatus) {
  return WIFEXITED(systemStatus) ? WEXITSTATUS(systemStatus) : -1;
}

ToolRun runCommand(const std::string& command, const std::filesystem::path& log) {
  ToolRun run;
  run.exitCode = exitCode(std::system((command + " > " + shellQuote(log) + " 2>&1").c_str()));
  run.output = readText(log);
  return run;
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace bounce::test
