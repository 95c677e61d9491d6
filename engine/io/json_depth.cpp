#include "io/json_depth.h"

#include <string>

#include "io/load_error.h"

namespace bounce {

void checkJsonDepth(const std::filesystem::path& file, std::string_view json) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        throw LoadError(file, "JSON nests arrays/objects deeper than " +
                                  std::to_string(kMaxJsonDepth) + " levels (at byte " +
                                  std::to_string(i) + "); bounce's limit is " +
                                  std::to_string(kMaxJsonDepth));
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace bounce
