// The glTF JSON checks tinygltf does not make: before tinygltf parses a document, its nesting
// depth is bounded (the parser recurses per level) and every property bounce reads is checked
// for its JSON type and range (glTF 2.0 schema): an index that is not a non-negative integer,
// a translation of two numbers or of strings, a negative byteOffset, `primitives: null`,
// `extensionsRequired` as a string, `asset.version` other than 2.x — each is a LoadError naming
// the file and the JSON path, where tinygltf would take a default and drop the value silently.
#pragma once

#include <filesystem>
#include <string_view>

namespace bounce {

// Throws LoadError on malformed JSON, on nesting deeper than kMaxJsonDepth (io/json_depth.h),
// or on a property of the wrong type or range.
void checkGltfSchema(const std::filesystem::path& file, std::string_view json);

}  // namespace bounce
