// GLSL files as the driver sees them. A shader file may `#include "other.glsl"` (relative to
// its own folder, each file at most once); the expansion marks every file change with
// `#line L S`, S being the file's index in `files`, so compile logs can be mapped back to the
// file and line that caused them. GL-free.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace bounce::gl {

// A shader could not be read, compiled or linked; the message names the file (and line).
class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A constant the C++ hands every stage of a program as `#define NAME VALUE`, written after the
// `#version` line (so GLSL files hold no copy of a value the C++ owns).
struct ShaderDefine {
  std::string name;
  std::string value;
};
using ShaderDefines = std::vector<ShaderDefine>;

struct ShaderSource {
  std::string text;                          // the expanded GLSL
  std::vector<std::filesystem::path> files;  // source-string number -> file
};

// Throws ShaderError naming the missing or unreadable file (and the including file and line).
// The defines go after the file's `#version` line (a file without one gets none), and the line
// after them is numbered as the file's next line.
ShaderSource readShaderSource(const std::filesystem::path& file, const ShaderDefines& defines = {});

// Rewrites a driver log's "S:L(C): msg" (Mesa) and "S(L) : msg" (NVIDIA/AMD) prefixes to
// "file:L: msg"; lines it cannot attribute are kept as they are.
std::string attributeLog(const std::string& log, const std::vector<std::filesystem::path>& files);

}  // namespace bounce::gl
