#include "expect_load_error.h"

#include <gtest/gtest.h>

#include "scene/load.h"

namespace bounce::test {

void expectLoadError(const std::filesystem::path& path, const std::string& reason) {
  try {
    loadScene(path);
    ADD_FAILURE() << path << " loaded; expected an error about '" << reason << "'";
  } catch (const LoadError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(reason), std::string::npos)
        << "expected '" << reason << "' in: " << message;
  }
}

}  // namespace bounce::test
