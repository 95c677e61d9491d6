// The scene tests' one check of a refused input: loadScene throws a LoadError whose message names
// the file (so the user knows which one) and states the rule it broke.
#pragma once

#include <filesystem>
#include <string>

namespace bounce::test {

// Loads `path`, expecting a LoadError whose message names the file and contains `reason`; a
// load that succeeds is a test failure (the test goes on).
void expectLoadError(const std::filesystem::path& path, const std::string& reason);

}  // namespace bounce::test
