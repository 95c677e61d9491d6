// The JSON depth guard: a document's nesting of arrays and objects, bounded before any recursive
// parser sees it (nlohmann::json and tinygltf recurse once per level; a deeper file would
// overflow the stack). The glTF, JSON-wrapper and bake.json readers call it first.
#pragma once

#include <filesystem>
#include <string_view>

namespace bounce {

// The deepest nesting bounce reads: glTF itself needs ~8 levels (docs/input_limits.md).
inline constexpr int kMaxJsonDepth = 64;

// Throws LoadError (io/load_error.h) when `json` nests arrays/objects deeper than
// kMaxJsonDepth. Scans bytes only (strings skipped), so it is safe on any input.
void checkJsonDepth(const std::filesystem::path& file, std::string_view json);

}  // namespace bounce
