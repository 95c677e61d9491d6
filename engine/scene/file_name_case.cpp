#include "scene/file_name_case.h"

#include <algorithm>
#include <string>
#include <system_error>

namespace bounce {

namespace {

bool equalIgnoringCase(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
           return lower(x) == lower(y);
         });
}

}  // namespace

std::filesystem::path findIgnoringCase(const std::filesystem::path& folder,
                                       const std::string& name) {
  std::error_code ec;
  const std::filesystem::path asWritten = folder / name;
  if (std::filesystem::exists(asWritten, ec)) return asWritten;
  std::string slashed = name;
  std::replace(slashed.begin(), slashed.end(), '\\', '/');
  std::filesystem::path found = folder;
  for (const std::filesystem::path& part : std::filesystem::path(slashed).relative_path()) {
    const std::string wanted = part.string();
    if (wanted.empty() || wanted == ".") continue;
    if (wanted == "..") {
      found /= part;
      continue;
    }
    if (std::filesystem::exists(found / part, ec)) {
      found /= part;
      continue;
    }
    std::filesystem::path match;
    int matches = 0;
    for (std::filesystem::directory_iterator it(found, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (!equalIgnoringCase(it->path().filename().string(), wanted)) continue;
      match = it->path();
      ++matches;
    }
    if (ec || matches != 1) return {};
    found = match;
  }
  return std::filesystem::exists(found, ec) ? found : std::filesystem::path();
}

}  // namespace bounce
