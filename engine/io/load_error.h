// The one error type of scene and file loading: "<file>: <reason>".
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace bounce {

class LoadError : public std::runtime_error {
 public:
  LoadError(const std::filesystem::path& file, const std::string& reason)
      : std::runtime_error(file.string() + ": " + reason), file_(file), reason_(reason) {}
  const std::filesystem::path& file() const { return file_; }
  const std::string& reason() const { return reason_; }

 private:
  std::filesystem::path file_;
  std::string reason_;
};

}  // namespace bounce
